// Flat regions (issue 43): pieces sewn flat found and merged back into the panels they were cut
// from. The expectations come from the pattern before quilting: its panels, their areas and its
// centre seams, never from the code under test.

#include <QtTest>

#include <set>

#include "engine/pattern/edge_curve.h"
#include "engine/pattern/flat_regions.h"
#include "engine/pattern/garment_mesh.h"
#include "engine/pattern/outline.h"
#include "support/quilted_shirt.h"

using namespace garment;

namespace {

double area(const Panel& panel) {
  return std::abs(build_outline(panel).signed_area);
}

// A frame of four rectangles round a square hole (centimetres), each sewn flat to its neighbours.
const char* kFrame = R"({"pattern": {"panels": {
  "top": {"translation": [0, 0, 0], "rotation": [0, 0, 0],
          "vertices": [[0, 20], [10, 20], [20, 20], [30, 20], [30, 30], [0, 30]],
          "edges": [{"endpoints": [0, 1]}, {"endpoints": [1, 2]}, {"endpoints": [2, 3]},
                    {"endpoints": [3, 4]}, {"endpoints": [4, 5]}, {"endpoints": [5, 0]}]},
  "bottom": {"translation": [0, 0, 0], "rotation": [0, 0, 0],
          "vertices": [[0, 0], [30, 0], [30, 10], [20, 10], [10, 10], [0, 10]],
          "edges": [{"endpoints": [0, 1]}, {"endpoints": [1, 2]}, {"endpoints": [2, 3]},
                    {"endpoints": [3, 4]}, {"endpoints": [4, 5]}, {"endpoints": [5, 0]}]},
  "left": {"translation": [0, 0, 0], "rotation": [0, 0, 0],
          "vertices": [[0, 10], [10, 10], [10, 20], [0, 20]],
          "edges": [{"endpoints": [0, 1]}, {"endpoints": [1, 2]}, {"endpoints": [2, 3]},
                    {"endpoints": [3, 0]}]},
  "right": {"translation": [0, 0, 0], "rotation": [0, 0, 0],
          "vertices": [[20, 10], [30, 10], [30, 20], [20, 20]],
          "edges": [{"endpoints": [0, 1]}, {"endpoints": [1, 2]}, {"endpoints": [2, 3]},
                    {"endpoints": [3, 0]}]}},
  "stitches": [[{"panel": "left", "edge": 0}, {"panel": "bottom", "edge": 4}],
               [{"panel": "left", "edge": 2}, {"panel": "top", "edge": 0}],
               [{"panel": "right", "edge": 0}, {"panel": "bottom", "edge": 2}],
               [{"panel": "right", "edge": 2}, {"panel": "top", "edge": 2}]]},
  "properties": {"units_in_meter": 100}})";

}  // namespace

class FlatRegionsTest : public QObject {
  Q_OBJECT
 private slots:
  // gc_0022 (shirt front and back halves): the halves are sewn flat at the centre, and two
  // pieces sewn flat are the pattern's own layout, not a quilt: nothing to merge.
  void theHalvesOfATorsoAreSewnFlatButNotMerged() {
    const Pattern pattern = load_pattern(test::test_data("patterns/gc_0022_specification.json"));
    const std::vector<bool> flat = stitches_sewn_flat(pattern);
    std::vector<std::pair<std::string, std::string>> joined;
    for (std::size_t s = 0; s < flat.size(); ++s)
      if (flat[s])
        joined.push_back({pattern.panels[pattern.stitches[s].a.panel].name,
                          pattern.panels[pattern.stitches[s].b.panel].name});
    std::sort(joined.begin(), joined.end());
    const std::vector<std::pair<std::string, std::string>> expected = {
        {"right_btorso", "left_btorso"}, {"right_ftorso", "left_ftorso"}};
    QCOMPARE(joined, expected);
    QVERIFY(!merge_flat_regions(pattern));
  }

  // The same shirt quilted: every cell of the two front halves makes one front, the back cells one
  // back, each with the area of its two halves, and the merged pattern meshes.
  void aQuiltMergesBackIntoItsFrontAndBack() {
    const Pattern original = load_pattern(test::test_data(test::kQuiltedShirtOriginal));
    const Pattern quilt = test::quilted_shirt();
    QVERIFY(quilt.panels.size() > 20);
    const std::optional<RegionPattern> regions = merge_flat_regions(quilt);
    QVERIFY(regions);
    QCOMPARE(regions->pattern.panels.size(), std::size_t(2));
    QCOMPARE(regions->region_of_panel.size(), quilt.panels.size());
    for (std::size_t p = 0; p < quilt.panels.size(); ++p) {
      const bool front = quilt.panels[p].name.find("ftorso") != std::string::npos;
      const Panel& region = regions->pattern.panels[regions->region_of_panel[p]];
      QCOMPARE(region.name, std::string(front ? "ftorso" : "btorso"));
    }
    for (const char* side : {"ftorso", "btorso"}) {
      const double halves =
          area(original.panels[original.panel_index(std::string("left_") + side)]) +
          area(original.panels[original.panel_index(std::string("right_") + side)]);
      const Panel& merged = regions->pattern.panels[regions->pattern.panel_index(side)];
      QVERIFY2(std::abs(area(merged) - halves) < 1e-4 * halves,
               qPrintable(QString("%1: %2 against %3 m²")
                              .arg(side)
                              .arg(area(merged), 0, 'g', 12)
                              .arg(halves, 0, 'g', 12)));
    }
    int pieces = 0;
    for (int count : regions->pieces_of_region)
      pieces += count;
    QCOMPARE(pieces, static_cast<int>(quilt.panels.size()));
    // The shirt's side and shoulder seams, split by the quilting, remain between front and back.
    for (const Stitch& stitch : regions->pattern.stitches)
      QVERIFY(stitch.a.panel != stitch.b.panel);
    const Garment garment = build_garment(regions->pattern);
    QCOMPARE(garment.pieces.size(), std::size_t(2));
  }

  // Where the cuts met the outline, the edges they cut are whole again: every edge of the shirt's
  // halves (the centre seams aside) lies along one edge of its region, start, middle and end.
  void theEdgesTheCutsSplitAreWholeAgain() {
    const Pattern original = load_pattern(test::test_data(test::kQuiltedShirtOriginal));
    const RegionPattern regions = *merge_flat_regions(test::quilted_shirt());
    const std::vector<bool> flat = stitches_sewn_flat(original);
    std::set<std::pair<int, int>> centre;
    for (std::size_t s = 0; s < flat.size(); ++s)
      if (flat[s]) {
        centre.insert({original.stitches[s].a.panel, original.stitches[s].a.edge});
        centre.insert({original.stitches[s].b.panel, original.stitches[s].b.edge});
      }
    int edges = 0;
    for (std::size_t p = 0; p < original.panels.size(); ++p) {
      const Panel& panel = original.panels[p];
      const bool front = panel.name.find("ftorso") != std::string::npos;
      const Panel& region =
          regions.pattern.panels[regions.pattern.panel_index(front ? "ftorso" : "btorso")];
      for (std::size_t e = 0; e < panel.edges.size(); ++e) {
        if (centre.count({static_cast<int>(p), static_cast<int>(e)})) continue;
        ++edges;
        const EdgeCurve curve(panel, panel.edges[e]);
        const bool covered =
            std::any_of(region.edges.begin(), region.edges.end(), [&](const PanelEdge& edge) {
              const EdgeCurve along_region(region, edge);
              const double along[] = {0.0, 0.5, 1.0};
              return std::all_of(std::begin(along), std::end(along), [&](double u) {
                return along_region.distance_to(curve.point(u)) < 1e-4;
              });
            });
        QVERIFY2(covered,
                 qPrintable(QString("%1 edge %2").arg(QString::fromStdString(panel.name)).arg(e)));
      }
    }
    int region_edges = 0;
    for (const Panel& region : regions.pattern.panels)
      region_edges += static_cast<int>(region.edges.size());
    QVERIFY2(region_edges <= edges,
             qPrintable(QString("%1 against %2").arg(region_edges).arg(edges)));
  }

  // The regions are meshed as asked, but no finer than 20 mm (the arrangement's default).
  void theRegionsAreMeshedNoFinerThanTheDefault() {
    const Pattern quilt = test::quilted_shirt();
    for (const auto& [asked, meshed] : {std::pair{0.01, 0.02}, std::pair{0.03, 0.03}}) {
      MeshingOptions options;
      options.target_edge_length = asked;
      const std::optional<MeshedRegions> regions = mesh_flat_regions(quilt, options);
      QVERIFY(regions);
      QCOMPARE(regions->garment.target_edge_length, meshed);
      QCOMPARE(regions->garment.pieces.size(), std::size_t(2));
    }
  }

  // Four pieces round a hole do not close into one outline: they stay as they are, sewn flat.
  void aRegionRoundAHoleKeepsItsPieces() {
    const Pattern frame = parse_pattern(kFrame, "frame.json");
    const std::vector<bool> flat = stitches_sewn_flat(frame);
    QCOMPARE(std::count(flat.begin(), flat.end(), true), 4);
    QVERIFY(!merge_flat_regions(frame));
  }
};

QTEST_APPLESS_MAIN(FlatRegionsTest)
#include "test_flat_regions.moc"
