// The trained seeding classifier: its weight file is validated on load; training is reproducible;
// and on patterns it was not trained on it finds the seeds as often as the paper reports (shared
// held-out split), with a looser bar on the small held-out subset kept in tests/data/seeding.

#include <QtTest>

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "engine/core/error.h"
#include "engine/core/input_file.h"
#include "engine/pattern/garment_mesh.h"
#include "engine/pattern/pattern.h"
#include "engine/pattern/pattern_files.h"
#include "engine/seeding/classification_report.h"
#include "engine/seeding/classifier_training.h"
#include "engine/seeding/classifier_weights.h"
#include "engine/seeding/piece_classifier.h"
#include "support/test_paths.h"

using namespace garment;

namespace {

QString message_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const InputError& error) {
    return QString::fromStdString(error.what());
  }
  return {};
}

std::vector<std::filesystem::path> held_out_files(const std::filesystem::path& folder) {
  const auto files = pattern_files(folder);
  std::vector<std::filesystem::path> held_out;
  for (std::size_t i = 0; i < files.size(); ++i)
    if (is_held_out(i)) held_out.push_back(files[i]);
  return held_out;
}

// The GarmentCode subset in tests/data/seeding, loaded as is and with its training variants.
struct SubsetWithVariants {
  std::vector<std::filesystem::path> files;
  std::vector<LabelledPattern> plain, variants;
};

SubsetWithVariants subset_with_variants() {
  const PanelLabeller labeller = PanelLabeller::load(test::test_data("seeding/panel_regions.json"));
  SubsetWithVariants subset;
  subset.files = pattern_files(test::test_data("seeding/garmentcode_random"));
  subset.plain = load_labelled_patterns(subset.files, labeller);
  subset.variants = load_labelled_patterns(subset.files, labeller, true);
  return subset;
}

}  // namespace

class ClassifierTest : public QObject {
  Q_OBJECT
 private slots:
  void bundledWeightsLoad() {
    const PieceClassifier classifier = PieceClassifier::load(default_classifier_weights_path());
    QVERIFY(!classifier.members().empty());
    for (const GatModel& member : classifier.members()) {
      QCOMPARE(member.shape().node_features, kNodeFeatureCount);
      QVERIFY(member.parameters.allFinite());
    }
  }

  void badWeightFilesAreRefused_data() {
    QTest::addColumn<QString>("edit");
    QTest::addColumn<QString>("expected");
    QTest::newRow("truncated") << "truncate"
                               << "not a valid JSON weight file";
    QTest::newRow("format") << "format"
                            << "format: expected";
    QTest::newRow("version") << "version"
                             << "expected version 1";
    QTest::newRow("short parameters") << "short"
                                      << "numbers, found";
    QTest::newRow("text parameter") << "text"
                                    << "parameters[0][3]: not a number";
    QTest::newRow("member count") << "members"
                                  << "one array per member";
    QTest::newRow("zero scale") << "scale"
                                << "node_scale[0]: expected a positive";
    QTest::newRow("feature layout") << "features"
                                    << "another feature layout";
    QTest::newRow("missing shape") << "shape"
                                   << "missing key 'shape'";
  }
  void badWeightFilesAreRefused() {
    QFETCH(QString, edit);
    QFETCH(QString, expected);
    const std::string good = read_file(default_classifier_weights_path());
    nlohmann::json root = nlohmann::json::parse(good);
    std::string text;
    if (edit == "truncate") {
      text = good.substr(0, good.size() / 2);
    } else {
      if (edit == "format") root["format"] = "something else";
      if (edit == "version") root["version"] = 2;
      if (edit == "short") root["parameters"][0].erase(root["parameters"][0].size() - 1);
      if (edit == "text") root["parameters"][0][3] = "x";
      if (edit == "members") root["members"] = root["members"].get<int>() + 1;
      if (edit == "scale") root["normalisation"]["node_scale"][0] = 0.0;
      if (edit == "features") root["node_features"][0] = "radial_1";
      if (edit == "shape") root.erase("shape");
      text = root.dump();
    }
    const QString message = message_of([&] { parse_classifier_weights(text, "bad_weights.json"); });
    QVERIFY2(message.startsWith("bad_weights.json"), qPrintable(message));
    QVERIFY2(message.contains(expected), qPrintable(message));
  }

  void missingWeightFileIsAClearError() {
    const QString message =
        message_of([] { PieceClassifier::load("/nonexistent/gat_weights.json"); });
    QVERIFY2(message.contains("/nonexistent/gat_weights.json"), qPrintable(message));
    QVERIFY2(message.contains("not found"), qPrintable(message));
  }

  void trainingIsReproducible() {
    const PanelLabeller labeller =
        PanelLabeller::load(test::test_data("seeding/panel_regions.json"));
    const auto patterns = load_labelled_patterns(
        pattern_files(test::test_data("seeding/garmentcode_random")), labeller, true);
    QVERIFY(patterns.size() > 20);  // 20 files and their variants (whole chests, tops)
    TrainingOptions options;
    options.epochs = 3;
    options.ensemble = 2;
    const auto weights = [&](std::uint64_t seed) {
      options.seed = seed;
      return classifier_weights_json(train_classifier(patterns, options).members, {});
    };
    const std::string first = weights(1);
    QCOMPARE(weights(1), first);
    QVERIFY(weights(2) != first);
    // What is written is what is read.
    const std::vector<GatModel> members = parse_classifier_weights(first, "trained.json");
    QCOMPARE(members.size(), std::size_t{2});
    QVERIFY(members[0].parameters != members[1].parameters);
    QCOMPARE(classifier_weights_json(members, {}), first);
  }

  // The training variants of a pattern follow it: the same pieces with whole chests, then the
  // top alone (chests and what is sewn to them, no waist or pelvis piece) and the chests alone,
  // each a sub-set of the pattern's pieces keeping their labels.
  void trainingVariantsAddTopsAndChests() {
    const auto [files, plain, variants] = subset_with_variants();
    QCOMPARE(plain.size(), files.size());
    int tops = 0, chests_alone = 0;
    std::size_t original = 0;
    for (const LabelledPattern& variant : variants) {
      if (original < plain.size() && variant.file == plain[original].file &&
          variant.piece_names == plain[original].piece_names &&
          variant.graph.node_count() == plain[original].graph.node_count()) {
        ++original;  // the pattern itself
        continue;
      }
      QVERIFY(original > 0);
      const LabelledPattern& source = plain[original - 1];
      QCOMPARE(variant.file, source.file);
      // Pieces are a sub-set of the pattern's, each labelled as in the pattern.
      for (std::size_t g = 0; g < variant.group_labels.size(); ++g) {
        const std::string& name = variant.piece_names[variant.graph.groups[g].front()];
        const auto at = std::find(source.piece_names.begin(), source.piece_names.end(), name);
        QVERIFY2(at != source.piece_names.end(), name.c_str());
        const int piece = static_cast<int>(at - source.piece_names.begin());
        QCOMPARE(variant.group_labels[g], source.group_labels[source.graph.piece_group[piece]]);
      }
      if (variant.piece_names.size() == source.piece_names.size()) continue;  // whole chests
      const auto& labels = variant.group_labels;
      QVERIFY(std::none_of(labels.begin(), labels.end(), is_lower_or_waist));
      QVERIFY(std::any_of(labels.begin(), labels.end(), is_chest));
      if (std::all_of(labels.begin(), labels.end(), is_chest))
        ++chests_alone;
      else
        ++tops;
    }
    QCOMPARE(original, plain.size());
    qInfo("%zu patterns: %d tops, %d chests alone", plain.size(), tops, chests_alone);
    QVERIFY(tops > 0);
    QVERIFY(chests_alone > 0);
  }

  // The taller and shorter cuts: the same pieces, grouped alike, whose single-piece seed pieces
  // are kHeightStretches times as tall and as large, and exactly as wide, as in the pattern.
  void trainingVariantsStretchHeightsOnly() {
    const auto [files, plain, variants] = subset_with_variants();
    const std::vector<std::string> names = node_feature_names();
    const auto column = [&](const char* name) {
      return static_cast<Eigen::Index>(std::find(names.begin(), names.end(), name) - names.begin());
    };
    const Eigen::Index width = column("log_width_m"), height = column("log_height_m"),
                       area = column("log_area_m2");
    std::vector<int> stretched(kHeightStretches.size(), 0);
    for (const LabelledPattern& source : plain) {
      for (const LabelledPattern& variant : variants) {
        if (variant.file != source.file || variant.piece_names != source.piece_names ||
            variant.graph.groups != source.graph.groups)
          continue;
        const double log_factor =
            variant.graph.node_features(0, height) - source.graph.node_features(0, height);
        if (std::abs(log_factor) < 1e-9) continue;  // the pattern itself
        const auto factor =
            std::find_if(kHeightStretches.begin(), kHeightStretches.end(),
                         [&](double f) { return std::abs(std::log(f) - log_factor) < 1e-6; });
        QVERIFY2(factor != kHeightStretches.end(), qPrintable(QString::number(log_factor)));
        ++stretched[factor - kHeightStretches.begin()];
        for (int g = 0; g < source.graph.node_count(); ++g) {
          if (source.graph.groups[g].size() != 1) continue;
          QVERIFY(std::abs(variant.graph.node_features(g, height) -
                           source.graph.node_features(g, height) - log_factor) < 1e-6);
          QVERIFY(std::abs(variant.graph.node_features(g, area) -
                           source.graph.node_features(g, area) - log_factor) < 1e-6);
          QVERIFY(std::abs(variant.graph.node_features(g, width) -
                           source.graph.node_features(g, width)) < 1e-9);
        }
        QCOMPARE(variant.group_labels, source.group_labels);
      }
    }
    // Both cuts of most patterns: a stretch can change what the waist merge joins (a strip's aspect
    // crosses 3), and those variants are grouped differently from their pattern.
    for (int count : stretched) {
      qInfo("%d stretched variants of %zu patterns", count, plain.size());
      QVERIFY(2 * count >= static_cast<int>(plain.size()));
    }
  }

  // The tops lengthened at the hem: every piece keeps its widths and the upper half of its cut;
  // below the middle of its height, every point is `factor` times as far from that middle, and the
  // piece's area grows as its mesh's does.
  void hemLengtheningKeepsTheUpperHalf() {
    int pieces_lengthened = 0;
    for (const std::filesystem::path& file :
         pattern_files(test::test_data("seeding/garmentcode_random"))) {
      const Garment garment = build_garment(load_pattern(file));
      const Garment lengthened = lengthened_at_hem(garment, kHemLengthening);
      QCOMPARE(lengthened.rest_positions.rows(), garment.rest_positions.rows());
      QVERIFY(lengthened.rest_positions.col(0) == garment.rest_positions.col(0));
      const auto mesh_area = [](const Garment& g, int piece) {
        double area = 0.0;
        for (Eigen::Index t = 0; t < g.triangles.rows(); ++t) {
          if (g.triangle_piece(t) != piece) continue;
          const Eigen::RowVector2d a = g.rest_positions.row(g.triangles(t, 0));
          const Eigen::Vector2d ab = g.rest_positions.row(g.triangles(t, 1)) - a;
          const Eigen::Vector2d ac = g.rest_positions.row(g.triangles(t, 2)) - a;
          area += 0.5 * (ab.x() * ac.y() - ab.y() * ac.x());
        }
        return area;
      };
      for (int p = 0; p < static_cast<int>(garment.pieces.size()); ++p) {
        const Piece& piece = garment.pieces[p];
        const auto before =
            garment.rest_positions.col(1).segment(piece.first_vertex, piece.vertex_count);
        const auto after =
            lengthened.rest_positions.col(1).segment(piece.first_vertex, piece.vertex_count);
        const double middle = 0.5 * (before.minCoeff() + before.maxCoeff());
        for (Eigen::Index v = 0; v < before.size(); ++v) {
          const double expected =
              before(v) >= middle ? before(v) : middle - kHemLengthening * (middle - before(v));
          QVERIFY(std::abs(after(v) - expected) < 1e-12);
        }
        const double growth = mesh_area(lengthened, p) / mesh_area(garment, p);
        QVERIFY(growth > 1.0 && growth < kHemLengthening);
        QVERIFY(std::abs(lengthened.pieces[p].outline_area_m2 / piece.outline_area_m2 - growth) <
                1e-3 * growth);
        ++pieces_lengthened;
      }
    }
    QVERIFY(pieces_lengthened > 100);
  }

  void heldOutSubsetFindsSeeds() {
    // 20 held-out GarmentCode patterns copied into tests/data (see LICENSES.md there).
    const PanelLabeller labeller =
        PanelLabeller::load(test::test_data("seeding/panel_regions.json"));
    const PieceClassifier classifier = PieceClassifier::load(default_classifier_weights_path());
    const ClassificationReport report = evaluate_classifier(
        classifier, load_labelled_patterns(
                        pattern_files(test::test_data("seeding/garmentcode_random")), labeller));
    qInfo("%s", format_classification_report(report).c_str());
    QCOMPARE(report.patterns, 20);
    QVERIFY(report.neck_or_waist.patterns >= 10);
    QVERIFY(report.chest.patterns >= 12);
    QVERIFY(report.neck_or_waist.rate() >= 0.85);
    QVERIFY(report.chest.rate() >= 0.85);
    QVERIFY(report.accuracy() >= 0.75);
    QVERIFY(report.recall(SeedClass::Waist) >= 0.8);

    const ClassificationReport templates = evaluate_classifier(
        classifier,
        load_labelled_patterns(
            pattern_files(test::test_data("seeding/pattern_generator_templates")), labeller));
    QCOMPARE(templates.neck_or_waist.patterns, 2);
    QCOMPARE(templates.neck_or_waist.found, 2);
  }

  void sharedHeldOutSplitMatchesThePaper() {
    if (!test::shared_data_available()) QSKIP("shared dataset not present");
    const PanelLabeller labeller =
        PanelLabeller::load(test::shared_data("patterns/panel_regions.json"));
    const PieceClassifier classifier = PieceClassifier::load(default_classifier_weights_path());
    const ClassificationReport report = evaluate_classifier(
        classifier,
        load_labelled_patterns(held_out_files(test::shared_data("patterns/garmentcode_random")),
                               labeller));
    qInfo("%s", format_classification_report(report).c_str());
    QCOMPARE(report.patterns, 100);
    // Paper §8.3.1: neck or waist found in 96 %, chest in 89 %.
    QVERIFY(report.neck_or_waist.rate() >= 0.96);
    QVERIFY(report.chest.rate() >= 0.89);
    QVERIFY(report.neck_or_waist_false_alarms <= report.patterns_without_neck_or_waist / 5);
  }

  void templatesGeneralisation() {
    if (!test::shared_data_available()) QSKIP("shared dataset not present");
    const PanelLabeller labeller =
        PanelLabeller::load(test::shared_data("patterns/panel_regions.json"));
    const PieceClassifier classifier = PieceClassifier::load(default_classifier_weights_path());
    const ClassificationReport report = evaluate_classifier(
        classifier,
        load_labelled_patterns(
            pattern_files(test::shared_data("patterns/pattern_generator_templates")), labeller));
    qInfo("%s", format_classification_report(report).c_str());
    QCOMPARE(report.patterns, 23);
    QCOMPARE(report.neck_or_waist.found, report.neck_or_waist.patterns);
    QVERIFY(report.neck_or_waist_false_alarms <= report.patterns_without_neck_or_waist / 5);
    // The paper's chest rate on another pattern set: its tees are cut whole and to the hip, where
    // GarmentCode cuts bodices in halves and to the waist (the training variants teach both).
    QVERIFY(report.chest.rate() >= 0.89);
  }
};

QTEST_APPLESS_MAIN(ClassifierTest)
#include "test_classifier.moc"
