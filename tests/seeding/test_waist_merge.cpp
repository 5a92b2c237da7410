// The waist merge (paper §5.1): strips wider than 3× their height sewn end to end become one seed
// piece; on real waistbands (straight and curved), on a pattern without one, and over the held-out
// part of the shared dataset.

#include <QtTest>

#include <algorithm>

#include "engine/pattern/garment_mesh.h"
#include "engine/pattern/pattern_files.h"
#include "engine/seeding/classifier_training.h"
#include "engine/seeding/waist_merge.h"
#include "support/test_paths.h"

using namespace garment;

namespace {

std::vector<std::vector<std::string>> merged_names(const Garment& garment) {
  std::vector<std::vector<std::string>> result;
  for (const std::vector<int>& group : merge_waist_pieces(garment)) {
    if (group.size() < 2) continue;
    std::vector<std::string> names;
    for (int piece : group)
      names.push_back(garment.pieces[piece].name);
    std::sort(names.begin(), names.end());
    result.push_back(names);
  }
  return result;
}

void verify_partition(const Garment& garment, const std::vector<std::vector<int>>& groups) {
  std::vector<int> seen(garment.pieces.size(), 0);
  for (const auto& group : groups) {
    QVERIFY(std::is_sorted(group.begin(), group.end()));
    for (int piece : group)
      ++seen[piece];
    if (group.size() > 1)
      for (int piece : group)
        QVERIFY2(is_strip(garment, piece), garment.pieces[piece].name.c_str());
  }
  QVERIFY(std::all_of(seen.begin(), seen.end(), [](int count) { return count == 1; }));
}

}  // namespace

class WaistMergeTest : public QObject {
  Q_OBJECT
 private slots:
  void straightWaistbandIsMerged() {
    const Garment garment =
        build_garment(load_pattern(test::test_data("patterns/gc_0012_specification.json")));
    verify_partition(garment, merge_waist_pieces(garment));
    QCOMPARE(merged_names(garment),
             (std::vector<std::vector<std::string>>{{"wb_back", "wb_front"}}));
  }

  void curvedWaistbandIsMerged() {
    // FittedWB: both halves are arcs of constant width (the back one fills only ~60 % of its box).
    const Garment garment = build_garment(
        load_pattern(test::test_data("seeding/garmentcode_random/gc_0035_specification.json")));
    verify_partition(garment, merge_waist_pieces(garment));
    QCOMPARE(merged_names(garment),
             (std::vector<std::vector<std::string>>{{"wb_back", "wb_front"}}));
  }

  void patternWithoutStripsIsUntouched() {
    const Garment garment =
        build_garment(load_pattern(test::test_data("patterns/gc_0000_specification.json")));
    const auto groups = merge_waist_pieces(garment);
    QCOMPARE(groups.size(), garment.pieces.size());
    for (std::size_t p = 0; p < groups.size(); ++p)
      QCOMPARE(groups[p], std::vector<int>{static_cast<int>(p)});
    for (std::size_t p = 0; p < garment.pieces.size(); ++p)
      QVERIFY(!is_strip(garment, static_cast<int>(p)));
  }

  void tallBandIsNotAStrip() {
    // gc_0420: a straight waistband 2.4× wider than tall, under the paper's threshold of 3.
    const Garment garment = build_garment(
        load_pattern(test::test_data("seeding/garmentcode_random/gc_0420_specification.json")));
    verify_partition(garment, merge_waist_pieces(garment));
    for (std::size_t p = 0; p < garment.pieces.size(); ++p)
      if (garment.pieces[p].name.rfind("wb_", 0) == 0) {
        const auto rows = garment.rest_positions.middleRows(garment.pieces[p].first_vertex,
                                                            garment.pieces[p].vertex_count);
        const Eigen::RowVector2d size = rows.colwise().maxCoeff() - rows.colwise().minCoeff();
        QCOMPARE(is_strip(garment, static_cast<int>(p)), size.x() > 3.0 * size.y());
      }
  }

  void heldOutDatasetWaistbands() {
    if (!test::shared_data_available()) QSKIP("shared dataset not present");
    const auto files = pattern_files(test::shared_data("patterns/garmentcode_random"));
    int waistbands = 0, merged = 0;
    for (std::size_t i = 0; i < files.size(); ++i) {
      if (!is_held_out(i)) continue;
      const Garment garment = build_garment(load_pattern(files[i]));
      verify_partition(garment, merge_waist_pieces(garment));
      const int front = garment.pattern.panel_index("wb_front");
      const int back = garment.pattern.panel_index("wb_back");
      if (front < 0) continue;
      ++waistbands;
      const auto groups = merged_names(garment);
      const bool together =
          std::find(groups.begin(), groups.end(),
                    std::vector<std::string>{"wb_back", "wb_front"}) != groups.end();
      // Both halves strips ⇔ merged (they are always sewn end to end).
      QVERIFY2(together == (is_strip(garment, front) && is_strip(garment, back)),
               files[i].filename().c_str());
      merged += together;
    }
    qInfo("held-out waistbands: %d, merged: %d", waistbands, merged);
    QVERIFY(waistbands > 40);
    QVERIFY(merged > waistbands / 2);
  }
};

QTEST_APPLESS_MAIN(WaistMergeTest)
#include "test_waist_merge.moc"
