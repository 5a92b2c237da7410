// The main window: opens with the demo, picking in either view selects in both, a bad file is
// reported (through the injected presenter and through the real message box) and leaves the open
// pattern, files dropped on the window open, recent files and window geometry persist, the
// session's actions exist and stay disabled until a session connects them, a click on a failure in
// the Quality panel selects its pieces in both views, and opening a pattern or a body clears the
// verdict.

#include <QAction>
#include <QListWidget>
#include <QMenu>
#include <QMessageBox>
#include <QMimeData>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTimer>
#include <QTreeWidget>
#include <QtTest>

#include "engine/body/default_body.h"
#include "support/test_paths.h"
#include "tests/ui/ui_test_support.h"
#include "ui/arrangement_order_list.h"
#include "ui/avatar_view.h"
#include "ui/main_window.h"
#include "ui/pattern_view.h"
#include "ui/quality_panel.h"
#include "ui/recent_files.h"

using namespace garment;

namespace {

struct CapturedErrors {
  QStringList titles, messages;
};

QString test_pattern(const char* name) {
  return QString::fromStdString(test::test_data(std::filesystem::path("patterns") / name).string());
}

QString default_body() {
  return QString::fromStdString(default_body_path().string());
}

QStringList piece_names(const Garment& garment) {
  QStringList names;
  for (const Piece& piece : garment.pieces)
    names << QString::fromStdString(piece.name);
  return names;
}

// A verdict on the demo garment with one failure on two of its pieces.
QualityVerdict crossing_between(int a, int b) {
  QualityFailure failure;
  failure.kind = FailureKind::SelfCrossing;
  failure.pieces = {a, b};
  failure.message = "5 cloth edges crossing cloth";
  QualityVerdict verdict;
  verdict.failures.push_back(failure);
  return verdict;
}

void drop_files(QWidget& target, const QStringList& paths) {
  QMimeData data;
  QList<QUrl> urls;
  for (const QString& path : paths)
    urls << QUrl::fromLocalFile(path);
  data.setUrls(urls);
  const QPoint centre = target.rect().center();
  QDragEnterEvent enter(centre, Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
  QApplication::sendEvent(&target, &enter);
  QVERIFY(enter.isAccepted());
  QDropEvent drop(QPointF(centre), Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
  QApplication::sendEvent(&target, &drop);
}

}  // namespace

class MainWindowTest : public QObject {
  Q_OBJECT

 private:
  std::unique_ptr<ui::MainWindow> window_;
  CapturedErrors errors_;

 private slots:
  // Every test starts from a fresh window showing the demo pattern (without the body, which
  // takes a second to load: the tests that need one open it).
  void init() {
    window_ = std::make_unique<ui::MainWindow>();
    errors_ = {};
    window_->setErrorPresenter([this](const QString& title, const QString& message) {
      errors_.titles << title;
      errors_.messages << message;
    });
    QVERIFY(window_->openDemoPattern());
    ui::RecentFiles::clear();
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
  }

  void cleanup() { window_.reset(); }

  void opensWithTheDemo() {
    ui::MainWindow window;
    QVERIFY(window.openDemoPattern());
    QVERIFY(window.openDefaultBody());
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.garment());
    QCOMPARE(window.garment()->pieces.size(), std::size_t(8));
    QVERIFY(window.body());
    QVERIFY(window.windowTitle().contains("demo_pattern.json"));
    QVERIFY(window.windowTitle().contains("mean_all.obj"));
    QCOMPARE(window.patternView()->pieceAt(window.patternView()->pieceLabelPosition(0)), 0);
    // Bundled files are not recent files.
    QVERIFY(ui::RecentFiles::load().isEmpty());

    // Before any arrangement the 3D view shows the pieces flat where the file puts them: the
    // front pieces (in front of the body, facing the camera) show their outside colour.
    ui::AvatarView* avatar = window.avatarView();
    QVERIFY(avatar->garmentShown());
    avatar->setOrbit(0, 0);
    avatar->frameAll();
    QCoreApplication::processEvents();
    const QImage front = avatar->grabFramebuffer();
    GARMENT_VERIFY_IMAGE(test::count_pixels(front, test::looks_outside) > 1000, front,
                         "main_window_demo_flat");
    const QColor background = avatar->colours().background;
    GARMENT_VERIFY_IMAGE(test::count_pixels(front,
                                            [&](QColor c) {
                                              return !test::looks_outside(c) &&
                                                     !test::colours_close(c, background, 10);
                                            }) > 5000,
                         front, "main_window_demo_body");

    // The body's 15 locations are listed; choosing one highlights its marker.
    QCOMPARE(window.locationList()->count(), 15);
    QCOMPARE(window.locationList()->item(0)->text(), QString("neck"));
    QSignalSpy location(&window, &ui::MainWindow::bodyLocationSelected);
    window.locationList()->setCurrentRow(3);  // waist
    QCOMPARE(location.count(), 1);
    QCOMPARE(location.takeFirst().at(0).toInt(), 3);
    QCOMPARE(avatar->highlightedLocation(), 3);
    QCoreApplication::processEvents();
    const QImage highlighted = avatar->grabFramebuffer();
    const QPoint waist = avatar->projectToView(window.body()->locations[3].center).toPoint();
    GARMENT_VERIFY_IMAGE(test::colours_close(highlighted.pixelColor(waist),
                                             avatar->colours().highlighted_marker, 12),
                         highlighted, "main_window_location_highlight");
  }

  void pickingSelectsInBothViews() {
    auto garment = window_->garment();
    auto positions = test::sheet_positions(*garment, 0.5, 1.0, 0.8);
    window_->avatarView()->setBody(test::sphere_body(Eigen::Vector3d(0, 1, 0), 0.3));
    window_->setGarmentPositions(positions);
    window_->avatarView()->setOrbit(0, 0);
    window_->avatarView()->frameAll();
    QCoreApplication::processEvents();
    QSignalSpy selection(window_.get(), &ui::MainWindow::pieceSelectionChanged);

    ui::PatternView* pattern = window_->patternView();
    QTest::mouseClick(pattern->viewport(), Qt::LeftButton, Qt::NoModifier,
                      pattern->pieceLabelPosition(4));
    QCOMPARE(window_->avatarView()->selectedPieces(), QList<int>({4}));
    QCOMPARE(selection.count(), 1);

    ui::AvatarView* avatar = window_->avatarView();
    const QPoint at =
        avatar->projectToView(test::point_inside_piece(*garment, *positions, 6)).toPoint();
    QTest::mouseClick(avatar, Qt::LeftButton, Qt::NoModifier, at);
    QCOMPARE(pattern->selectedPieces(), QList<int>({6}));
    QCOMPARE(window_->selectedPieces(), QList<int>({6}));
    QCOMPARE(selection.count(), 2);
    QCOMPARE(selection.at(1).at(0).value<QList<int>>(), QList<int>({6}));
    QVERIFY(pattern->sewingHighlightCount() > 0);
  }

  void qualityFailureSelectsItsPiecesInBothViews() {
    const Garment& garment = *window_->garment();
    QVERIFY(garment.pieces.size() > 5);
    window_->setQualityVerdict(crossing_between(2, 5), piece_names(garment));
    QTreeWidget* list = window_->qualityPanel()->failureList();
    QVERIFY(list->isVisible());
    QCOMPARE(list->topLevelItemCount(), 1);
    QTreeWidgetItem* item = list->topLevelItem(0);
    QCOMPARE(item->text(ui::QualityPanel::PiecesColumn),
             QString::fromStdString(garment.pieces[2].name + ", " + garment.pieces[5].name));
    QSignalSpy selection(window_.get(), &ui::MainWindow::pieceSelectionChanged);
    const QRect row = list->visualItemRect(item);
    QVERIFY(list->viewport()->rect().contains(row.center()));
    QTest::mouseClick(list->viewport(), Qt::LeftButton, Qt::NoModifier, row.center());
    QCOMPARE(window_->patternView()->selectedPieces(), QList<int>({2, 5}));
    QCOMPARE(window_->avatarView()->selectedPieces(), QList<int>({2, 5}));
    // A selection by the user, as a click in a view is: the manual seed follows it.
    QCOMPARE(selection.count(), 1);
    QCOMPARE(selection.at(0).at(0).value<QList<int>>(), QList<int>({2, 5}));
  }

  void openingClearsTheVerdict() {
    auto show_failed_verdict = [this] {
      window_->setQualityVerdict(crossing_between(0, 1), piece_names(*window_->garment()));
      ui::ArrangementStatus status;
      status.phase = "done";
      status.quality_failures = QStringList{"self_crossing: 5 cloth edges crossing cloth"};
      window_->setArrangementStatus(status);
      QVERIFY(window_->qualityPanel()->judged());
      QVERIFY(!window_->arrangementStatusBar()->qualityText().isEmpty());
    };
    show_failed_verdict();
    QVERIFY2(window_->openBody(default_body()), qPrintable(errors_.messages.join("\n")));
    QVERIFY(!window_->qualityPanel()->judged());
    QCOMPARE(window_->qualityPanel()->failureList()->topLevelItemCount(), 0);
    QCOMPARE(window_->arrangementStatusBar()->qualityText(), QString());

    show_failed_verdict();
    QVERIFY(window_->openPattern(test_pattern("basic_tee__tee.json")));
    QVERIFY(!window_->qualityPanel()->judged());
    QCOMPARE(window_->arrangementStatusBar()->qualityText(), QString());
  }

  void badPatternKeepsTheOpenOne() {
    const auto before = window_->garment();
    const QString title = window_->windowTitle();
    QSignalSpy opened(window_.get(), &ui::MainWindow::garmentOpened);
    for (const char* bad : {"bad/dangling_edge.json", "bad/truncated.json", "bad/empty_file.json",
                            "does_not_exist.json"}) {
      QVERIFY(!window_->openPattern(test_pattern(bad)));
      QCOMPARE(window_->garment(), before);
    }
    QCOMPARE(errors_.messages.size(), 4);
    // The engine's message names the file.
    QVERIFY2(errors_.messages[0].contains("dangling_edge.json"), qPrintable(errors_.messages[0]));
    QCOMPARE(opened.count(), 0);
    QCOMPARE(window_->windowTitle(), title);
    QCOMPARE(window_->patternView()->pieceAt(window_->patternView()->pieceLabelPosition(0)), 0);
    QVERIFY(ui::RecentFiles::load().isEmpty());
  }

  void badFileShowsAMessageBox() {
    // The default presenter: a modal QMessageBox, closed here as soon as it shows.
    ui::MainWindow window;
    QVERIFY(window.openDemoPattern());
    QString shown_text;
    QTimer closer;
    connect(&closer, &QTimer::timeout, [&] {
      if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
        shown_text = box->text();
        box->done(QMessageBox::Ok);
      }
    });
    closer.start(20);
    QVERIFY(!window.openPattern(test_pattern("bad/self_intersecting.json")));
    closer.stop();
    QVERIFY2(shown_text.contains("self_intersecting.json"), qPrintable(shown_text));
    QCOMPARE(window.garment()->pieces.size(), std::size_t(8));
  }

  void bodyOpensAndBadBodyIsReported() {
    QSignalSpy body_opened(window_.get(), &ui::MainWindow::bodyOpened);
    QVERIFY2(window_->openBody(default_body()), qPrintable(errors_.messages.join("\n")));
    QCOMPARE(body_opened.count(), 1);
    QVERIFY(window_->body());
    QCOMPARE(window_->body()->locations.size(), std::size_t(15));
    QVERIFY(window_->windowTitle().contains("mean_all.obj"));
    QCOMPARE(ui::RecentFiles::load(), QStringList({QFileInfo(default_body()).absoluteFilePath()}));

    const auto before = window_->body();
    QTemporaryDir directory;
    QFile garbage(directory.filePath("broken.obj"));
    QVERIFY(garbage.open(QIODevice::WriteOnly));
    garbage.write("v 0 0 0\nf 1 2 3\n");
    garbage.close();
    QVERIFY(!window_->openBody(garbage.fileName()));
    QCOMPARE(window_->body(), before);
    QCOMPARE(errors_.messages.size(), 1);
    QVERIFY2(errors_.messages[0].contains("broken.obj"), qPrintable(errors_.messages[0]));
    QVERIFY(window_->windowTitle().contains("mean_all.obj"));
    QCOMPARE(window_->locationList()->count(), 15);
  }

  void droppedFilesOpen() {
    drop_files(*window_, {test_pattern("basic_tee__tee.json"), default_body()});
    QVERIFY(errors_.messages.isEmpty());
    QVERIFY(QString::fromStdString(window_->garment()->pattern.source).contains("basic_tee"));
    QVERIFY(window_->body());
    // Only patterns and bodies are taken.
    QMimeData other;
    other.setUrls({QUrl::fromLocalFile("/tmp/notes.txt")});
    QDragEnterEvent enter(QPoint(10, 10), Qt::CopyAction, &other, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(window_.get(), &enter);
    QVERIFY(!enter.isAccepted());
  }

  void recentFilesRemembered() {
    const QString tee = test_pattern("basic_tee__tee.json");
    const QString skirt = test_pattern("skirts__skirt_4_panels.json");
    QVERIFY(window_->openPattern(tee));
    QVERIFY(window_->openPattern(skirt));
    QVERIFY(window_->openPattern(tee));
    const QStringList recent = ui::RecentFiles::load();
    QCOMPARE(recent.size(), 2);
    QCOMPARE(recent[0], QFileInfo(tee).absoluteFilePath());
    QCOMPARE(recent[1], QFileInfo(skirt).absoluteFilePath());
    emit window_->recentFilesMenu()->aboutToShow();
    QStringList entries;
    for (QAction* action : window_->recentFilesMenu()->actions())
      entries << action->text();
    QVERIFY(entries[0].startsWith("basic_tee__tee.json"));
    QVERIFY(entries[1].startsWith("skirts__skirt_4_panels.json"));
    // Choosing an entry opens it.
    window_->recentFilesMenu()->actions()[1]->trigger();
    QVERIFY(QString::fromStdString(window_->garment()->pattern.source).contains("skirt_4_panels"));
  }

  void geometryPersists() {
    window_->resize(1100, 700);
    QCoreApplication::processEvents();
    window_->close();
    ui::MainWindow restored;
    QCOMPARE(restored.size(), QSize(1100, 700));
  }

  void sessionActionsWaitForASession() {
    const ui::SessionActions& actions = window_->sessionActions();
    for (QAction* action :
         {actions.run_pause, actions.step, actions.stop, actions.reset, actions.export_obj,
          actions.export_glb, actions.export_report, actions.export_sewn_obj,
          actions.export_sewn_glb, actions.export_sewing_obj}) {
      QVERIFY(action);
      QVERIFY2(!action->isEnabled(), qPrintable(action->text()));
    }
    QCOMPARE(actions.run_pause->shortcut(), QKeySequence(Qt::Key_Space));
    QCOMPARE(actions.step->shortcut(), QKeySequence(Qt::Key_F10));
  }

  void sessionDataReachesThePanels() {
    window_->setArrangementOrder({2, 0, 1});
    QCOMPARE(window_->orderList()->order(), QList<int>({2, 0, 1}));
    QVERIFY(window_->orderList()->item(0)->text().contains(
        QString::fromStdString(window_->garment()->pieces[2].name)));
    QSignalSpy reordered(window_.get(), &ui::MainWindow::arrangementOrderChanged);
    window_->orderList()->movePiece(0, 3);
    QCOMPARE(reordered.count(), 1);
    QCOMPARE(reordered.takeFirst().at(0).value<QList<int>>(), QList<int>({0, 1, 2}));

    window_->setBodyLocations({{"neck", Eigen::Vector3d(0, 1.5, 0), Eigen::Vector3d::UnitY()},
                               {"waist", Eigen::Vector3d(0, 1.0, 0), Eigen::Vector3d::UnitY()}});
    QCOMPARE(window_->locationList()->count(), 2);
    QSignalSpy location(window_.get(), &ui::MainWindow::bodyLocationSelected);
    window_->locationList()->setCurrentRow(1);
    QCOMPARE(location.count(), 1);
    QCOMPARE(window_->avatarView()->highlightedLocation(), 1);

    ui::PieceClassification row;
    row.piece = "left_ftorso";
    row.predicted = 2;
    row.probabilities = {0.0, 0.05, 0.9, 0.05, 0.0, 0.0, 0.0};
    row.seed = true;
    window_->setClassifications(
        {"neck", "waist", "front_chest", "back_chest", "front_pelvis", "back_pelvis", "other"},
        {row});
    QCOMPARE(window_->classifierModel()->rowCount(), 1);

    ui::ArrangementStatus status;
    status.phase = "align";
    status.batch = 2;
    status.batch_count = 5;
    status.iteration = 120;
    status.elapsed_seconds = 3.2;
    status.progress = 0.4;
    status.running = true;
    window_->setArrangementStatus(status);
    QCOMPARE(window_->arrangementStatusBar()->progressPercent(), 40);

    // A new pattern clears what belonged to the old one.
    QVERIFY(window_->openPattern(test_pattern("basic_tee__tee.json")));
    QCOMPARE(window_->orderList()->count(), 0);
    QCOMPARE(window_->classifierModel()->rowCount(), 0);
    QCOMPARE(window_->arrangementStatusBar()->status().phase, QString());
  }
};

GARMENT_UI_TEST_MAIN(MainWindowTest)
#include "test_main_window.moc"
