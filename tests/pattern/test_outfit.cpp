// Outfits as one pattern (engine/pattern/outfit.h), on real patterns (tests/data/patterns:
// gc_0022, a sleeveless top in front and back halves, and gc_0340, a maxi pencil skirt with darts,
// both made for f_smpl_average_A40, from the tuning half):
// - every panel of each garment, in order, named GARMENT:PANEL; every stitch and dart on the
//   panels of its own garment, between the same edges as in its file;
// - garment names from file names; the panel's and garment's parts of a piece name;
// - two files with one garment name, or with different units, are refused naming the file.

#include <QtTest>

#include "engine/core/error.h"
#include "engine/pattern/outfit.h"
#include "support/test_paths.h"

using namespace garment;

namespace {

const std::filesystem::path kTop = "patterns/gc_0022_specification.json";
const std::filesystem::path kSkirt = "patterns/gc_0340_specification.json";

}  // namespace

class OutfitPatternTest : public QObject {
  Q_OBJECT
 private slots:
  void garmentNamesComeFromFileNames() {
    QCOMPARE(outfit_garment_name("/data/gc_0022_specification.json"), std::string("gc_0022"));
    QCOMPARE(outfit_garment_name("shirt.json"), std::string("shirt"));
    QCOMPARE(outfit_garment_name("dir/coat.v2.json"), std::string("coat.v2"));
    QCOMPARE(std::string(panel_name_in_garment("shirt:left_ftorso")), std::string("left_ftorso"));
    QCOMPARE(std::string(panel_name_in_garment("left_ftorso")), std::string("left_ftorso"));
    QCOMPARE(std::string(outfit_garment_of("shirt:left_ftorso")), std::string("shirt"));
    QVERIFY(outfit_garment_of("left_ftorso").empty());
  }

  void panelsAndStitchesStayWithTheirGarment() {
    const Pattern top = load_pattern(test::test_data(kTop));
    const Pattern skirt = load_pattern(test::test_data(kSkirt));
    std::vector<OutfitPart> parts;
    const Pattern outfit =
        load_outfit_pattern({test::test_data(kTop), test::test_data(kSkirt)}, &parts);
    QCOMPARE(parts.size(), std::size_t(2));
    QCOMPARE(parts[0].name, std::string("gc_0022"));
    QCOMPARE(parts[1].name, std::string("gc_0340"));
    QCOMPARE(parts[0].first_panel, 0);
    QCOMPARE(parts[1].first_panel, static_cast<int>(top.panels.size()));
    QCOMPARE(outfit.panels.size(), top.panels.size() + skirt.panels.size());
    QCOMPARE(outfit.stitches.size(), top.stitches.size() + skirt.stitches.size());
    for (std::size_t p = 0; p < top.panels.size(); ++p) {
      QCOMPARE(outfit.panels[p].name, "gc_0022:" + top.panels[p].name);
      QCOMPARE(outfit.panels[p].vertices.size(), top.panels[p].vertices.size());
    }
    for (std::size_t p = 0; p < skirt.panels.size(); ++p)
      QCOMPARE(outfit.panels[top.panels.size() + p].name, "gc_0340:" + skirt.panels[p].name);
    const int offset = static_cast<int>(top.panels.size());
    for (std::size_t s = 0; s < skirt.stitches.size(); ++s) {
      const Stitch& own = skirt.stitches[s];
      const Stitch& merged = outfit.stitches[top.stitches.size() + s];
      QCOMPARE(merged.a.panel, own.a.panel + offset);
      QCOMPARE(merged.b.panel, own.b.panel + offset);
      QCOMPARE(merged.a.edge, own.a.edge);
      QCOMPARE(merged.b.edge, own.b.edge);
      QCOMPARE(merged.is_dart(), own.is_dart());
      QCOMPARE(merged.file_index, own.file_index);
    }
    int darts = 0;
    for (const Stitch& stitch : skirt.stitches)
      darts += stitch.is_dart();
    QVERIFY(darts > 0);  // the skirt's darts came along as darts
  }

  void sameGarmentNameTwiceIsRefused() {
    try {
      load_outfit_pattern({test::test_data(kTop), test::test_data(kTop)});
      QFAIL("the same garment twice was accepted");
    } catch (const InputError& error) {
      const std::string message = error.what();
      QVERIFY2(message.find("gc_0022") != std::string::npos, message.c_str());
      QVERIFY2(message.find("already in the outfit") != std::string::npos, message.c_str());
    }
  }

  void differentUnitsAreRefused() {
    Pattern top = load_pattern(test::test_data(kTop));
    Pattern other = load_pattern(test::test_data(kSkirt));
    other.units_in_meter = 1000.0;
    try {
      merge_patterns({top, other}, {"top", "skirt"});
      QFAIL("different units were accepted");
    } catch (const InputError& error) {
      const std::string message = error.what();
      QVERIFY2(message.find("units_in_meter") != std::string::npos, message.c_str());
      QVERIFY2(message.find(other.source) != std::string::npos, message.c_str());
    }
  }
};

QTEST_GUILESS_MAIN(OutfitPatternTest)
#include "test_outfit.moc"
