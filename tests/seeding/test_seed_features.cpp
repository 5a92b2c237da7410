// Seeding features (paper §5.1.1): Eq. 1 on a scene whose answer is known by hand and on a real
// waistband; the radial profile; and that nothing depends on panel names (renamed panels give the
// same features and the same classification).

#include <QtTest>

#include <nlohmann/json.hpp>

#include <cmath>
#include <map>
#include <random>

#include "engine/core/input_file.h"
#include "engine/pattern/garment_mesh.h"
#include "engine/seeding/piece_classifier.h"
#include "engine/seeding/seed_graph.h"
#include "engine/seeding/sewing_relationship.h"
#include "support/test_paths.h"

using namespace garment;

namespace {

// A 100×20 cm band sewn along its bottom edge to the top edge of a 100×50 cm panel.
const char* kBandOnPanel = R"({
  "pattern": {
    "panels": {
      "band": {"vertices": [[0, 0], [100, 0], [100, 20], [0, 20]],
               "edges": [{"endpoints": [0, 1]}, {"endpoints": [1, 2]}, {"endpoints": [2, 3]},
                         {"endpoints": [3, 0]}],
               "rotation": [0, 0, 0], "translation": [0, 60, 0]},
      "panel": {"vertices": [[0, 0], [100, 0], [100, 50], [0, 50]],
                "edges": [{"endpoints": [0, 1]}, {"endpoints": [1, 2]}, {"endpoints": [2, 3]},
                          {"endpoints": [3, 0]}],
                "rotation": [0, 0, 0], "translation": [0, 0, 0]}
    },
    "panel_order": ["band", "panel"],
    "stitches": [[{"panel": "band", "edge": 0}, {"panel": "panel", "edge": 2}]]
  },
  "properties": {"units_in_meter": 100, "curvature_coords": "relative"}
})";

int piece_named(const Garment& garment, const std::string& name) {
  for (std::size_t p = 0; p < garment.pieces.size(); ++p)
    if (garment.pieces[p].name == name) return static_cast<int>(p);
  return -1;
}

// The same specification with every panel renamed to a random meaningless name (stitches and
// panel_order follow); returns the text and the map old name → new name.
std::pair<std::string, std::map<std::string, std::string>> renamed(const std::string& text,
                                                                   unsigned seed) {
  nlohmann::ordered_json root = nlohmann::ordered_json::parse(text);
  std::mt19937 generator(seed);
  std::map<std::string, std::string> names;
  nlohmann::ordered_json panels = nlohmann::ordered_json::object();
  for (auto& [name, panel] : root["pattern"]["panels"].items()) {
    std::string fresh = "p";
    for (int k = 0; k < 10; ++k)
      fresh += static_cast<char>('a' + generator() % 26);
    names[name] = fresh;
    panels[fresh] = panel;
  }
  root["pattern"]["panels"] = panels;
  for (auto& stitch : root["pattern"]["stitches"])
    for (auto& side : stitch)
      if (side.is_object()) side["panel"] = names.at(side["panel"].get<std::string>());
  if (root["pattern"].contains("panel_order"))
    for (auto& name : root["pattern"]["panel_order"])
      name = names.at(name.get<std::string>());
  return {root.dump(), names};
}

}  // namespace

class SeedFeaturesTest : public QObject {
  Q_OBJECT
 private slots:
  void equationOneOnBandOverPanel() {
    const Garment garment = build_garment(parse_pattern(kBandOnPanel, "band_on_panel.json"));
    const int band = piece_named(garment, "band"), panel = piece_named(garment, "panel");
    const SewingRelationship sewing(garment);
    // The whole panel lies beneath the seam: S_{band→panel} is its area, 1.0 × 0.5 m².
    QVERIFY(std::abs(sewing.score(band, panel) - 0.5) < 1e-9);
    // Nothing of the band lies beneath its bottom edge.
    QCOMPARE(sewing.score(panel, band), 0.0);
    QVERIFY(std::abs(sewing.sewn_length(sewing.mask({band}), panel) - 1.0) < 1e-9);
    QVERIFY(std::abs(sewing.sewing_boundary_length(panel) - 1.0) < 1e-9);
    QVERIFY(std::abs(sewing.outline_length(panel) - 3.0) < 1e-9);
    // Sets: from both pieces to the panel counts the band only (the panel is not sewn to itself).
    QVERIFY(std::abs(sewing.score(std::vector<int>{band, panel}, std::vector<int>{panel}) - 0.5) <
            1e-9);

    const SeedGraph graph = build_seed_graph(garment);
    QCOMPARE(graph.node_count(), 2);
    QCOMPARE(graph.edge_count(), 2);  // both directions of the one seam
    for (int e = 0; e < graph.edge_count(); ++e) {
      const bool into_panel = graph.groups[graph.edges(e, 0)] == std::vector<int>{panel};
      // Feature 0: share of the target beneath the source; 1: share of the source beneath it.
      QVERIFY(std::abs(graph.edge_features(e, 0) - (into_panel ? 1.0 : 0.0)) < 1e-9);
      QVERIFY(std::abs(graph.edge_features(e, 1) - (into_panel ? 0.0 : 1.0)) < 1e-9);
    }
  }

  void waistbandSitsOnTheSkirt() {
    // A straight waistband over a pencil skirt (GarmentCode).
    const Garment garment =
        build_garment(load_pattern(test::test_data("patterns/gc_0012_specification.json")));
    const int band = piece_named(garment, "wb_front"), skirt = piece_named(garment, "skirt_front");
    QVERIFY(band >= 0 && skirt >= 0);
    const SewingRelationship sewing(garment);
    const double skirt_area = garment.pieces[skirt].outline_area_m2;
    const double band_area = garment.pieces[band].outline_area_m2;
    QVERIFY2(sewing.score(band, skirt) > 0.8 * skirt_area,
             qPrintable(QString::number(sewing.score(band, skirt) / skirt_area)));
    QVERIFY(sewing.score(skirt, band) < 0.05 * band_area);
  }

  void radialProfileOfASquare() {
    Eigen::MatrixX2d square(4, 2);
    square << 0, 0, 2, 0, 2, 2, 0, 2;
    const Eigen::VectorXd profile = radial_profile({square});
    QCOMPARE(profile.size(), Eigen::Index{kRadialDirections});
    // θ = 0°: the side at distance 1; θ = 45°: the corner at √2, the largest.
    QVERIFY(std::abs(profile(0) - 1.0 / std::sqrt(2.0)) < 1e-12);
    QVERIFY(std::abs(profile(kRadialDirections / 8) - 1.0) < 1e-12);
    QVERIFY(std::abs(profile(kRadialDirections / 4) - profile(0)) < 1e-12);
    // The shape, not the size: a square twice as large, elsewhere, has the same profile.
    const Eigen::MatrixX2d moved = (2.0 * square).rowwise() + Eigen::RowVector2d(5.0, -3.0);
    QVERIFY((radial_profile({moved}) - profile).cwiseAbs().maxCoeff() < 1e-12);
  }

  void renamedPanelsClassifyTheSame_data() {
    QTest::addColumn<QString>("file");
    QTest::newRow("skirt with waistband") << "patterns/gc_0012_specification.json";
    QTest::newRow("top with collar") << "seeding/garmentcode_random/gc_0165_specification.json";
    QTest::newRow("dress with waistband")
        << "seeding/garmentcode_random/gc_0035_specification.json";
    // No panel_order: pieces are in name order, so renaming also reorders them.
    QTest::newRow("template tee") << "patterns/basic_tee__tee.json";
  }
  void renamedPanelsClassifyTheSame() {
    QFETCH(QString, file);
    const std::filesystem::path path = test::test_data(file.toStdString());
    const PieceClassifier classifier = PieceClassifier::load(default_classifier_weights_path());
    const Garment original = build_garment(load_pattern(path));
    const PieceClassification expected = classifier.classify(original);
    const SeedGraph expected_graph = build_seed_graph(original);
    for (unsigned seed : {1u, 2u, 3u}) {
      const auto [text, names] = renamed(read_file(path), seed);
      const Garment garment = build_garment(parse_pattern(text, "renamed.json"));
      const PieceClassification result = classifier.classify(garment);
      const SeedGraph graph = build_seed_graph(garment);
      QCOMPARE(result.groups.size(), expected.groups.size());
      for (std::size_t p = 0; p < original.pieces.size(); ++p) {
        const int q = piece_named(garment, names.at(original.pieces[p].name));
        QVERIFY(q >= 0);
        const int g = expected.piece_group[p], h = result.piece_group[q];
        QCOMPARE(result.groups[h].size(), expected.groups[g].size());
        QVERIFY((graph.node_features.row(h) - expected_graph.node_features.row(g))
                    .cwiseAbs()
                    .maxCoeff() < 1e-9);
        QCOMPARE(result.group_class(h), expected.group_class(g));
        QVERIFY(
            (result.probabilities.row(h) - expected.probabilities.row(g)).cwiseAbs().maxCoeff() <
            1e-9);
      }
    }
  }
};

QTEST_APPLESS_MAIN(SeedFeaturesTest)
#include "test_seed_features.moc"
