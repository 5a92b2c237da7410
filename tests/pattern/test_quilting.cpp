// Quilting (issue 43): every panel cut into grid cells, the cells sewn along the cuts and the
// original stitches split to match. The checks measure the output through the importer and
// EdgeCurve only: areas against the original outlines, lengths of sewn and free boundary against
// the original pattern's, and every sub-edge located back on the original edge it came from.

#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include "engine/core/error.h"
#include "engine/pattern/garment_mesh.h"
#include "engine/pattern/outline.h"
#include "engine/pattern/quilting.h"
#include "support/test_paths.h"

using namespace garment;

namespace {

Pattern quilted(const Pattern& original, double cell, std::vector<std::string> keep = {}) {
  QuiltOptions options;
  options.cell = cell;
  options.keep = std::move(keep);
  return parse_pattern(quilt_pattern(original, options).specification,
                       original.source + " (quilted)");
}

// The original panel a piece was cut from: its name before "__".
std::string original_name(const std::string& piece) {
  return piece.substr(0, piece.find("__"));
}

double edge_length(const Pattern& pattern, const EdgeRef& ref) {
  const Panel& panel = pattern.panels[ref.panel];
  return EdgeCurve(panel, panel.edges[ref.edge]).length();
}

// The edge of the original pattern that an output edge lies on (its midpoint within 0.2 mm of it,
// the panels in one frame), or edge -1 when it lies inside the panel (a cut).
EdgeRef locate(const Pattern& original, const Pattern& output, const EdgeRef& ref) {
  const Panel& piece = output.panels[ref.panel];
  const int p = original.panel_index(original_name(piece.name));
  const Eigen::Vector2d middle = EdgeCurve(piece, piece.edges[ref.edge]).point(0.5);
  const Panel& panel = original.panels[p];
  for (std::size_t e = 0; e < panel.edges.size(); ++e)
    if (EdgeCurve(panel, panel.edges[e]).distance_to(middle) < 2e-4)
      return {p, static_cast<int>(e)};
  return {p, -1};
}

std::vector<std::filesystem::path> sample_patterns() {
  std::vector<std::filesystem::path> files;
  for (const char* name :
       {"gc_0000_specification.json", "basic_tee__tee.json", "skirts__skirt_4_panels.json",
        "gc_0005_specification.json", "gc_0195_specification.json", "gc_0473_specification.json"})
    files.push_back(test::test_data(std::filesystem::path("patterns") / name));
  if (test::shared_data_available())
    for (const char* name : {"garmentcode_random/gc_0002_specification.json",
                             "garmentcode_random/gc_0010_specification.json"})
      if (const auto path = test::shared_data(std::filesystem::path("patterns") / name);
          std::filesystem::exists(path))
        files.push_back(path);
  return files;
}

}  // namespace

class QuiltingTest : public QObject {
  Q_OBJECT
 private slots:
  void quiltedPatternIsValidAndEquivalent_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<double>("cell");
    for (const auto& path : sample_patterns())
      for (double cell : {0.15, 0.06}) {
        const std::string row = path.filename().string() + " cell " + std::to_string(cell);
        QTest::newRow(row.c_str()) << QString::fromStdString(path.string()) << cell;
      }
  }

  void quiltedPatternIsValidAndEquivalent() {
    QFETCH(QString, file);
    QFETCH(double, cell);
    const Pattern original = load_pattern(file.toStdString());
    const Pattern output = quilted(original, cell);
    QVERIFY(output.panels.size() > original.panels.size());

    // The project's own mesher accepts it.
    const Garment garment = build_garment(output);
    QVERIFY(garment.vertex_count() > 0);

    // The cells tile each panel: their areas add up to the panel's. No sliver is left alone.
    std::map<std::string, double> area;
    for (const Panel& piece : output.panels) {
      const double piece_area = std::abs(build_outline(piece).signed_area);
      area[original_name(piece.name)] += piece_area;
      const bool cut = piece.name.find("__") != std::string::npos;  // not a whole small panel
      QVERIFY2(
          !cut || piece_area > 0.05 * cell * cell,
          qPrintable(QString("%1: %2 m²").arg(QString::fromStdString(piece.name)).arg(piece_area)));
    }
    for (const Panel& panel : original.panels) {
      const double expected = std::abs(build_outline(panel).signed_area);
      QVERIFY2(std::abs(area[panel.name] - expected) < 1e-3 * expected,
               qPrintable(QString("%1: cells %2 m², panel %3 m²")
                              .arg(QString::fromStdString(panel.name))
                              .arg(area[panel.name])
                              .arg(expected)));
    }

    // Every edge in at most one stitch; cuts sewn with equal lengths; parts of an original stitch
    // sewn to parts of the same stitch, in its proportion.
    std::map<std::pair<int, int>, int> stitches_of_edge;
    std::map<std::pair<int, int>, const Stitch*> original_stitch;
    for (const Stitch& stitch : original.stitches) {
      original_stitch[{stitch.a.panel, stitch.a.edge}] = &stitch;
      original_stitch[{stitch.b.panel, stitch.b.edge}] = &stitch;
    }
    double sewn_boundary = 0.0;
    for (const Stitch& stitch : output.stitches) {
      for (const EdgeRef& side : {stitch.a, stitch.b})
        QCOMPARE(++stitches_of_edge[std::make_pair(side.panel, side.edge)], 1);
      const EdgeRef a = locate(original, output, stitch.a), b = locate(original, output, stitch.b);
      const double length_a = edge_length(output, stitch.a),
                   length_b = edge_length(output, stitch.b);
      if (a.edge < 0 || b.edge < 0) {
        QVERIFY2(a.edge < 0 && b.edge < 0, "a cut sewn to the panel's boundary");
        QCOMPARE(a.panel, b.panel);
        QVERIFY(std::abs(length_a - length_b) < 1e-6);
        continue;
      }
      const auto found = original_stitch.find({a.panel, a.edge});
      QVERIFY2(found != original_stitch.end(),
               qPrintable(QString("%1 edge %2 (%3 m) sewn, its edge %4 was not")
                              .arg(QString::fromStdString(output.panels[stitch.a.panel].name))
                              .arg(stitch.a.edge)
                              .arg(length_a)
                              .arg(a.edge)));
      const Stitch& source = *found->second;
      const bool same = (source.a.panel == a.panel && source.a.edge == a.edge &&
                         source.b.panel == b.panel && source.b.edge == b.edge) ||
                        (source.b.panel == a.panel && source.b.edge == a.edge &&
                         source.a.panel == b.panel && source.a.edge == b.edge);
      QVERIFY2(same, qPrintable(QString("%1 edge %2 (%3 m) and %4 edge %5 (%6 m): parts of two "
                                        "different stitches sewn together")
                                    .arg(QString::fromStdString(output.panels[stitch.a.panel].name))
                                    .arg(stitch.a.edge)
                                    .arg(length_a)
                                    .arg(QString::fromStdString(output.panels[stitch.b.panel].name))
                                    .arg(stitch.b.edge)
                                    .arg(length_b)));
      QCOMPARE(stitch.right_wrong, source.right_wrong);
      const double ratio = edge_length(original, a) / edge_length(original, b);
      QVERIFY2(std::abs(length_a - ratio * length_b) < 4e-3,
               qPrintable(QString("%1 vs %2 (ratio %3)").arg(length_a).arg(length_b).arg(ratio)));
      sewn_boundary += length_a + length_b;
    }

    // Sewn and free boundary keep their lengths; every cut is sewn.
    double sewn_before = 0.0, free_before = 0.0, free_after = 0.0;
    for (const Stitch& stitch : original.stitches)
      sewn_before += edge_length(original, stitch.a) + edge_length(original, stitch.b);
    for (std::size_t p = 0; p < original.panels.size(); ++p)
      for (std::size_t e = 0; e < original.panels[p].edges.size(); ++e)
        if (!original_stitch.count({static_cast<int>(p), static_cast<int>(e)}))
          free_before += edge_length(original, {static_cast<int>(p), static_cast<int>(e)});
    for (std::size_t p = 0; p < output.panels.size(); ++p)
      for (std::size_t e = 0; e < output.panels[p].edges.size(); ++e) {
        const EdgeRef ref{static_cast<int>(p), static_cast<int>(e)};
        if (stitches_of_edge.count({ref.panel, ref.edge})) continue;
        QVERIFY2(locate(original, output, ref).edge >= 0,
                 qPrintable("an unsewn cut on " + QString::fromStdString(output.panels[p].name)));
        free_after += edge_length(output, ref);
      }
    QVERIFY2(std::abs(sewn_boundary - sewn_before) < 1e-3 * sewn_before + 1e-6,
             qPrintable(QString("sewn %1 m, was %2 m").arg(sewn_boundary).arg(sewn_before)));
    QVERIFY2(std::abs(free_after - free_before) < 1e-3 * free_before + 1e-6,
             qPrintable(QString("free %1 m, was %2 m").arg(free_after).arg(free_before)));
  }

  void smallerCellsMakeMorePieces() {
    const Pattern original = load_pattern(test::test_data("patterns/basic_tee__tee.json"));
    std::size_t previous = original.panels.size();
    for (double cell : {0.3, 0.15, 0.08, 0.04}) {
      const std::size_t pieces = quilted(original, cell).panels.size();
      QVERIFY2(pieces > previous, qPrintable(QString("cell %1: %2 pieces").arg(cell).arg(pieces)));
      previous = pieces;
    }
    // The tee's front is about 50 × 60 cm: at 4 cm, well over a hundred cells.
    QVERIFY(previous > 150);
  }

  void keptPanelsStayWhole() {
    const Pattern original = load_pattern(test::test_data("patterns/basic_tee__tee.json"));
    const Pattern output = quilted(original, 0.08, {"sleeve"});
    for (const Panel& panel : original.panels) {
      const bool sleeve = panel.name.find("sleeve") != std::string::npos;
      const int whole = output.panel_index(panel.name);
      int cells = 0;
      for (const Panel& piece : output.panels)
        if (piece.name.rfind(panel.name + "__", 0) == 0) ++cells;
      if (sleeve) {
        QVERIFY2(whole >= 0 && cells == 0, panel.name.c_str());
        // Its stitched edges may gain vertices (exact sub-curves, flattened afresh): the same area
        // to a fraction of a square centimetre.
        QVERIFY(std::abs(build_outline(output.panels[whole]).signed_area -
                         build_outline(panel).signed_area) < 1e-5);
      } else {
        QVERIFY2(whole < 0 && cells > 1, panel.name.c_str());
      }
    }
  }

  void badInputIsRefused() {
    const Pattern original = load_pattern(test::test_data("patterns/gc_0000_specification.json"));
    QuiltOptions options;
    options.cell = 0.0;
    QVERIFY_THROWS_EXCEPTION(InputError, quilt_pattern(original, options));
    options.cell = 1e-6;  // millions of cells
    QVERIFY_THROWS_EXCEPTION(InputError, quilt_pattern(original, options));

    QTemporaryDir dir;
    const QString input = QString::fromStdString(original.source);
    const QString output = dir.filePath("quilted_specification.json");
    const auto run = [](const QStringList& arguments) {
      QProcess process;
      process.start(GARMENT_INIT_EXE, arguments);
      process.waitForFinished(60000);
      return std::make_pair(process.exitCode(), QString::fromUtf8(process.readAllStandardError()) +
                                                    process.readAllStandardOutput());
    };
    QCOMPARE(run({"quilt", input, "-o", output}).first, 2);                  // no --cell
    QCOMPARE(run({"quilt", input, "--cell", "-3", "-o", output}).first, 2);  // not positive
    QCOMPARE(run({"quilt", input, "--cell", "10", "-o", input}).first, 2);   // onto the input
    const auto bad = run(
        {"quilt", QString::fromStdString(test::test_data("patterns/bad/open_loop.json").string()),
         "--cell", "10", "-o", output});
    QCOMPARE(bad.first, 1);
    QVERIFY2(bad.second.contains("open_loop.json"), qPrintable(bad.second));
    const auto good = run({"quilt", input, "--cell", "10", "-o", output});
    QCOMPARE(good.first, 0);
    QVERIFY2(good.second.contains(" pieces"), qPrintable(good.second));
    QVERIFY(load_pattern(output.toStdString()).panels.size() > original.panels.size());
  }
};

QTEST_GUILESS_MAIN(QuiltingTest)
#include "test_quilting.moc"
