// Outfits in the studio (issue "Complex garments"): File › Add garment… and the Outfit dock's
// layer list, on two real garments of the tuning half made for f_smpl_average_A40: gc_0022 (a
// sleeveless top) and gc_0340 (a maxi pencil skirt), tests/data/patterns.
// - Adding the skirt to the open top makes one garment of both, its pieces named GARMENT:PANEL,
//   the layers listed innermost first, the title naming both; the session opened on it is an
//   outfit scene on that very garment.
// - Run to the end, the studio's outfit is the command line's: the same positions, to the bit,
//   as the engine's Session on load_outfit_scene of the same files (one thread for both: the
//   thread count is part of the input); the dock says no garment crosses the other, which the
//   test checks on those positions with its own measure.
// - Moving a layer (the buttons, a drag in the list) reorders the outfit and opens a session
//   with the skirt innermost; removing a garment leaves the other alone under its own panel
//   names; a garment of the same name, or a bad file, is refused with the file named and
//   changes nothing.

#include <tbb/global_control.h>

#include <QAbstractItemModel>
#include <QAction>
#include <QDockWidget>
#include <QListWidget>
#include <QPushButton>
#include <QSignalSpy>
#include <QtTest>

#include "engine/quality/expected_region.h"
#include "engine/quality/garment_metrics.h"
#include "engine/quality/outfit_crossings.h"
#include "engine/session/session.h"
#include "support/test_paths.h"
#include "tests/ui/studio_harness.h"
#include "ui/outfit_layer_list.h"

using namespace garment;

namespace {

QString test_file(const std::filesystem::path& relative) {
  return QString::fromStdString(test::test_data(relative).string());
}

const std::filesystem::path kTop = "patterns/gc_0022_specification.json";
const std::filesystem::path kSkirt = "patterns/gc_0340_specification.json";
const std::filesystem::path kBody = "bodies/f_smpl_average_A40.obj";

}  // namespace

class StudioOutfitTest : public QObject, test::StudioHarness {
  Q_OBJECT

 private:
  const tbb::global_control one_thread_{tbb::global_control::max_allowed_parallelism, 1};

  // The top open on the body, then the skirt added over it; waits for the outfit's session.
  void openTopThenSkirt() {
    openStudio({{}, {1100, 700}, test_file(kTop), test_file(kBody), false});
    QVERIFY(window_->addGarmentAction()->isEnabled());
    QVERIFY2(window_->addGarment(test_file(kSkirt)), qPrintable(errors_.join("\n")));
    QVERIFY(waitOutfitSession({"gc_0022", "gc_0340"}));
  }

  // Waits for a session whose scene is the window's garment with these garments, innermost first.
  bool waitOutfitSession(const std::vector<std::string>& names) {
    return waitFor(
        [&](const ui::SessionState& s) {
          if (!s.has_session || !s.scene || s.scene->garment != window_->garment()) return false;
          if (s.scene->outfit.size() != (names.size() > 1 ? names.size() : 0)) return false;
          for (std::size_t g = 0; g < s.scene->outfit.size(); ++g)
            if (s.scene->outfit[g].name != names[g]) return false;
          return true;
        },
        120000);
  }

  ui::OutfitLayerList* layers() const { return window_->outfitList(); }

 private slots:
  void cleanup() {
    controller_.reset();
    window_.reset();
    errors_.clear();
  }

  void addingAGarmentMakesAnOutfit() {
    openTopThenSkirt();
    const Garment& garment = *window_->garment();
    int top_pieces = 0, skirt_pieces = 0;
    for (const Piece& piece : garment.pieces) {
      top_pieces += piece.name.starts_with("gc_0022:");
      skirt_pieces += piece.name.starts_with("gc_0340:");
    }
    QVERIFY(top_pieces > 0 && skirt_pieces > 0);
    QCOMPARE(top_pieces + skirt_pieces, static_cast<int>(garment.pieces.size()));
    QCOMPARE(layers()->layers(), QStringList({"gc_0022", "gc_0340"}));
    QCOMPARE(layers()->list()->count(), 2);
    QVERIFY(layers()->list()->item(0)->text().contains("innermost"));
    QVERIFY(layers()->list()->item(1)->text().contains("outermost"));
    QVERIFY(
        window_->windowTitle().contains("gc_0022_specification.json + "
                                        "gc_0340_specification.json"));
    QCOMPARE(state().scene->outfit[0].piece_count, top_pieces);
    QVERIFY(layers()->crossingsText().isEmpty());  // nothing judged yet
  }

  void theStudiosOutfitIsTheCommandLines() {
    openTopThenSkirt();
    window_->sessionActions().run_pause->trigger();
    QVERIFY(waitFor([](const ui::SessionState& s) { return s.done; }, 600000));
    QVERIFY2(errors_.isEmpty(), qPrintable(errors_.join("\n")));

    Session engine(load_outfit_scene({test::test_data(kTop), test::test_data(kSkirt)},
                                     test::test_data(kBody)));
    engine.run();
    const Eigen::MatrixX3d& shown = *controller_->lastUpdate().positions;
    QCOMPARE(shown.rows(), engine.positions().rows());
    QVERIFY2(shown == engine.positions(), "the studio arranged the outfit otherwise");

    const Garment& garment = *window_->garment();
    const BodyReference body(window_->body()->mesh);
    const GarmentMetrics metrics =
        measure_garment(garment, shown, &body, expected_regions_from_names(garment));
    QVERIFY(crossings_between_garments(outfit_piece_garments(*state().scene), metrics).empty());
    QVERIFY(state().between_garments.has_value());
    QVERIFY(state().between_garments->empty());
    QCOMPARE(layers()->crossingsText(), QString("no crossing between garments"));
    QVERIFY(state().verdict && state().verdict->ok());
  }

  void layersMoveAndGo() {
    openTopThenSkirt();
    // The buttons: the skirt (outermost) moved inward.
    layers()->list()->setCurrentRow(1);
    QVERIFY(layers()->inwardButton()->isEnabled());
    QVERIFY(!layers()->outwardButton()->isEnabled());
    layers()->inwardButton()->click();
    QCOMPARE(layers()->layers(), QStringList({"gc_0340", "gc_0022"}));
    QVERIFY(waitOutfitSession({"gc_0340", "gc_0022"}));
    QCOMPARE(window_->outfitNames(), std::vector<std::string>({"gc_0340", "gc_0022"}));

    // A drag in the list moves the row in its model; the outfit follows.
    QSignalSpy reordered(layers(), &ui::OutfitLayerList::orderChanged);
    QVERIFY(layers()->list()->model()->moveRow(QModelIndex(), 1, QModelIndex(), 0));
    QVERIFY(reordered.wait(5000));
    QCOMPARE(layers()->layers(), QStringList({"gc_0022", "gc_0340"}));
    QVERIFY(waitOutfitSession({"gc_0022", "gc_0340"}));

    // Removing the top leaves the skirt alone, its panels under their own names.
    layers()->list()->setCurrentRow(0);
    layers()->removeButton()->click();
    QCOMPARE(layers()->layers(), QStringList({"gc_0340"}));
    QVERIFY(!layers()->removeButton()->isEnabled());
    QVERIFY(waitOutfitSession({"gc_0340"}));
    for (const Piece& piece : window_->garment()->pieces)
      QVERIFY2(piece.name.find(':') == std::string::npos, piece.name.c_str());
    QVERIFY(errors_.isEmpty());
  }

  void aBadGarmentChangesNothing() {
    openTopThenSkirt();
    const auto before = window_->garment();
    QVERIFY(!window_->addGarment(test_file(kTop)));
    QCOMPARE(errors_.size(), 1);
    QVERIFY2(errors_.front().startsWith("Cannot add garment") &&
                 errors_.front().contains("gc_0022") &&
                 errors_.front().contains("already in the outfit"),
             qPrintable(errors_.front()));
    QVERIFY(!window_->addGarment(test_file("patterns/bad/does_not_exist.json")));
    QCOMPARE(errors_.size(), 2);
    QVERIFY2(errors_.back().contains("does_not_exist.json"), qPrintable(errors_.back()));
    QCOMPARE(window_->garment(), before);
    QCOMPARE(layers()->layers(), QStringList({"gc_0022", "gc_0340"}));
  }
};

QTEST_MAIN(StudioOutfitTest)
#include "test_studio_outfit.moc"
