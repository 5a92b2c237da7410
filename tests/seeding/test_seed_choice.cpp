// The seed choice (engine/seeding/seed_choice.h, paper §5) on a hand-made garment of four panels
// with given class probabilities: the waist piece wins over chest and pelvis pieces, and the neck
// piece over pelvis pieces but not chest pieces, when it closes into a ring (else it is passed
// over), front and back pieces go to their two locations, a pair of identical panels that the
// classifier puts on one side is split into front and back (when it gives the other side a real
// chance, or cannot tell the two apart), a side found alone takes the piece sewn to it that is
// most probably the other side, names that say a side overrule the classifier's side (and bring
// in a piece the classifier nearly put in the region), a waistband sewn to chest pieces that reach
// too far from it for the body is passed over as a long top's hem band, the halves
// of an open front named left and right make one part, and without any seed class the rule picks
// the piece with the most garment below its seams.

#include <QtTest>

#include <algorithm>
#include <string>
#include <vector>

#include "engine/pattern/garment_mesh.h"
#include "engine/pattern/pattern.h"
#include "engine/seeding/seed_choice.h"
#include "support/rectangle_patterns.h"

using namespace garment;
using garment::test::rectangle;
using garment::test::stitch;

namespace {

// Pieces 0 and 1: two identical skirt panels 50×60 sewn at both sides; piece 2: a band 100×5 sewn
// on top of piece 0; piece 3: a flap 50×10 sewn below piece 1. Named as given.
Garment four_panels_named(const std::string& first, const std::string& second,
                          const std::string& band = "band", const std::string& flap = "flap") {
  return build_garment(parse_pattern(
      "{\"pattern\": {\"panels\": {" + rectangle(first, 50, 60) + ", " + rectangle(second, 50, 60) +
          ", " + rectangle(band, 100, 5) + ", " + rectangle(flap, 50, 10) +
          "}, \"panel_order\": [\"" + first + "\", \"" + second + "\", \"" + band + "\", \"" +
          flap + "\"], \"stitches\": [" + stitch(first, 1, second, 3) + ", " +
          stitch(second, 1, first, 3) + ", " + stitch(first, 2, band, 0) + ", " +
          stitch(second, 0, flap, 2) + "]}, \"properties\": {\"units_in_meter\": 100}}",
      "seed_choice.json"));
}

// The four panels with names that say no side.
const Garment& four_panels() {
  static const Garment built = four_panels_named("one", "two");
  return built;
}

// The same skirt panels (0, 1) with a waistband in a front and a back (2, 3, 50×10 each) sewn on
// top of them and to each other at both sides: a ring.
const Garment& banded_skirt() {
  static const Garment built = build_garment(parse_pattern(
      "{\"pattern\": {\"panels\": {" + rectangle("one", 50, 60) + ", " + rectangle("two", 50, 60) +
          ", " + rectangle("band_one", 50, 10) + ", " + rectangle("band_two", 50, 10) +
          "}, \"panel_order\": [\"one\", \"two\", \"band_one\", \"band_two\"], \"stitches\": [" +
          stitch("one", 1, "two", 3) + ", " + stitch("two", 1, "one", 3) + ", " +
          stitch("one", 2, "band_one", 0) + ", " + stitch("two", 2, "band_two", 0) + ", " +
          stitch("band_one", 1, "band_two", 3) + ", " + stitch("band_two", 1, "band_one", 3) +
          "]}, \"properties\": {\"units_in_meter\": 100}}",
      "banded_skirt.json"));
  return built;
}

// An open front: front halves 25×60 (pieces 0 "front_left", 1 "front_right") each sewn to a back
// 50×60 (piece 2) at one side, not to each other.
const Garment& open_front() {
  static const Garment built = build_garment(parse_pattern(
      "{\"pattern\": {\"panels\": {" + rectangle("front_left", 25, 60) + ", " +
          rectangle("front_right", 25, 60) + ", " + rectangle("back", 50, 60) +
          "}, \"panel_order\": [\"front_left\", \"front_right\", \"back\"], \"stitches\": [" +
          stitch("front_left", 1, "back", 3) + ", " + stitch("back", 1, "front_right", 3) +
          "]}, \"properties\": {\"units_in_meter\": 100}}",
      "open_front.json"));
  return built;
}

// One group per piece; row g: the probabilities of piece g, the rest of the mass on `other`.
PieceClassification classification(
    const std::vector<std::vector<std::pair<SeedClass, double>>>& rows) {
  PieceClassification result;
  result.probabilities =
      Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(rows.size()), kSeedClassCount);
  for (std::size_t g = 0; g < rows.size(); ++g) {
    result.groups.push_back({static_cast<int>(g)});
    result.piece_group.push_back(static_cast<int>(g));
    double total = 0.0;
    for (const auto& [seed_class, probability] : rows[g]) {
      result.probabilities(static_cast<Eigen::Index>(g), static_cast<int>(seed_class)) =
          probability;
      total += probability;
    }
    result.probabilities(static_cast<Eigen::Index>(g), static_cast<int>(SeedClass::Other)) +=
        1.0 - total;
  }
  return result;
}

using Parts = std::vector<std::pair<std::string, std::vector<int>>>;

Parts parts_of(const SeedPlan& plan) {
  Parts parts;
  for (const SeedPart& part : plan.parts)
    parts.emplace_back(part.location, part.pieces);
  return parts;
}

constexpr SeedClass kFrontPelvis = SeedClass::FrontPelvis, kBackPelvis = SeedClass::BackPelvis;

}  // namespace

class SeedChoiceTest : public QObject {
  Q_OBJECT

 private slots:
  void waistPieceComesFirst() {
    const SeedPlan plan = choose_seed(banded_skirt(), classification({{{kFrontPelvis, 0.9}},
                                                                      {{kBackPelvis, 0.9}},
                                                                      {{SeedClass::Waist, 0.6}},
                                                                      {{SeedClass::Waist, 0.5}}}));
    QCOMPARE(parts_of(plan), (Parts{{"waist", {2, 3}}}));
  }

  // A skirt panel the classifier also calls "waist", sewn below the band, joins the seed part:
  // the part still has its ring.
  void waistPartWithARingAndMoreIsKept() {
    const SeedPlan plan = choose_seed(banded_skirt(), classification({{{SeedClass::Waist, 0.55}},
                                                                      {{kBackPelvis, 0.9}},
                                                                      {{SeedClass::Waist, 0.6}},
                                                                      {{SeedClass::Waist, 0.5}}}));
    QCOMPARE(parts_of(plan), (Parts{{"waist", {0, 2, 3}}}));
  }

  // Half a waistband does not go round the body: the pelvis pieces are the seed.
  void waistPieceThatIsNoRingIsPassedOver() {
    const SeedPlan plan = choose_seed(banded_skirt(), classification({{{kFrontPelvis, 0.9}},
                                                                      {{kBackPelvis, 0.9}},
                                                                      {{SeedClass::Waist, 0.6}},
                                                                      {{SeedClass::Other, 0.5}}}));
    QCOMPARE(parts_of(plan), (Parts{{"pelvis_front", {0}}, {"pelvis_back", {1}}}));
  }

  // The flap is sewn to nothing at its sides: it cannot wrap the neck, however sure the
  // classifier is, and the pelvis pieces (which come after a collar ring) are the seed.
  void neckPieceThatIsNoRingIsPassedOver() {
    const SeedPlan plan = choose_seed(
        four_panels(),
        classification(
            {{{kFrontPelvis, 0.8}}, {{kBackPelvis, 0.7}}, {}, {{SeedClass::Neck, 0.95}}}));
    QCOMPARE(parts_of(plan), (Parts{{"pelvis_front", {0}}, {"pelvis_back", {1}}}));
  }

  // The bands of banded_skirt() close into a ring. As a collar, it gives way to chest pieces...
  void collarRingGivesWayToChestPieces() {
    const SeedPlan plan =
        choose_seed(banded_skirt(), classification({{{SeedClass::FrontChest, 0.8}},
                                                    {{SeedClass::BackChest, 0.7}},
                                                    {{SeedClass::Neck, 0.95}},
                                                    {{SeedClass::Neck, 0.9}}}));
    QCOMPARE(parts_of(plan), (Parts{{"chest_front", {0}}, {"chest_back", {1}}}));
    QCOMPARE(plan.reason, std::string("chest pieces (classifier)"));
  }

  // ...but not to pelvis pieces,...
  void collarRingComesBeforePelvisPieces() {
    const SeedPlan plan = choose_seed(banded_skirt(), classification({{{kFrontPelvis, 0.9}},
                                                                      {{kBackPelvis, 0.9}},
                                                                      {{SeedClass::Neck, 0.6}},
                                                                      {{SeedClass::Neck, 0.5}}}));
    QCOMPARE(parts_of(plan), (Parts{{"neck", {2, 3}}}));
    QCOMPARE(plan.reason, std::string("neck piece (classifier)"));
  }

  // ...and as a waistband it comes before the chest pieces.
  void waistRingComesBeforeChestPieces() {
    const SeedPlan plan =
        choose_seed(banded_skirt(), classification({{{SeedClass::FrontChest, 0.9}},
                                                    {{SeedClass::BackChest, 0.9}},
                                                    {{SeedClass::Waist, 0.6}},
                                                    {{SeedClass::Waist, 0.5}}}));
    QCOMPARE(parts_of(plan), (Parts{{"waist", {2, 3}}}));
  }

  // Measured against a body, a ring whose chest pieces reach far from it is a long top's hem band:
  // the chest pieces (60 cm from the band's seam) are the seed on a body 25 cm from waist to neck
  // (the limit is twice that), the band on one of 35 cm.
  void hemBandOfALongTopGivesWayToChestPieces() {
    const PieceClassification classes = classification({{{SeedClass::FrontChest, 0.9}},
                                                        {{SeedClass::BackChest, 0.9}},
                                                        {{SeedClass::Waist, 0.6}},
                                                        {{SeedClass::Waist, 0.5}}});
    const SeedPlan long_top = choose_seed(banded_skirt(), classes, 0.25);
    QCOMPARE(parts_of(long_top), (Parts{{"chest_front", {0}}, {"chest_back", {1}}}));
    QCOMPARE(long_top.reason,
             std::string("chest pieces (classifier; the waist piece is a long top's hem band)"));
    QCOMPARE(parts_of(choose_seed(banded_skirt(), classes, 0.35)), (Parts{{"waist", {2, 3}}}));
  }

  void frontAndBackGoToTheirLocations() {
    const SeedPlan plan = choose_seed(four_panels(), classification({{{SeedClass::FrontChest, 0.8}},
                                                                     {{SeedClass::BackChest, 0.7}},
                                                                     {},
                                                                     {{kFrontPelvis, 0.6}}}));
    QCOMPARE(parts_of(plan), (Parts{{"chest_front", {0}}, {"chest_back", {1}}}));
  }

  // Identical panels get the same probabilities; both on the back would put the front panel
  // behind the body. The second most probable back group goes to the front.
  void identicalPanelsOnOneSideAreSplit() {
    const SeedPlan plan =
        choose_seed(four_panels(), classification({{{kBackPelvis, 0.54}, {kFrontPelvis, 0.46}},
                                                   {{kBackPelvis, 0.55}, {kFrontPelvis, 0.45}},
                                                   {},
                                                   {}}));
    QCOMPARE(parts_of(plan), (Parts{{"pelvis_front", {0}}, {"pelvis_back", {1}}}));
    QCOMPARE(plan.reason, std::string("pelvis pieces (classifier)"));
  }

  // However sure the classifier is of the side, it cannot tell identical panels apart (it gives
  // them the same probabilities): one of them is the other side.
  void indistinguishablePanelsOnOneSideAreSplit() {
    const SeedPlan plan =
        choose_seed(four_panels(), classification({{{kBackPelvis, 0.78}, {kFrontPelvis, 0.08}},
                                                   {{kBackPelvis, 0.78}, {kFrontPelvis, 0.08}},
                                                   {},
                                                   {}}));
    QCOMPARE(parts_of(plan), (Parts{{"pelvis_front", {1}}, {"pelvis_back", {0}}}));
  }

  // Two pieces the classifier firmly puts on the back (the two halves of a back panel) stay
  // there together.
  void firmlyOneSidedPiecesStayTogether() {
    const SeedPlan plan =
        choose_seed(four_panels(), classification({{{kBackPelvis, 0.9}, {kFrontPelvis, 0.05}},
                                                   {{kBackPelvis, 0.8}, {kFrontPelvis, 0.2}},
                                                   {},
                                                   {}}));
    QCOMPARE(parts_of(plan), (Parts{{"pelvis_back", {0, 1}}}));
  }

  // The classifier finds a front chest only; the back, sewn to it, is its second guess for piece 1.
  // Seeded alone, the front leaves the back to be laid flat beside it, outside it.
  void oneSidedChestTakesItsSewnPartner() {
    const SeedPlan plan = choose_seed(
        four_panels(), classification({{{SeedClass::FrontChest, 0.8}},
                                       {{kFrontPelvis, 0.5}, {SeedClass::BackChest, 0.15}},
                                       {{SeedClass::BackChest, 0.05}},
                                       {}}));
    QCOMPARE(parts_of(plan), (Parts{{"chest_front", {0}}, {"chest_back", {1}}}));
  }

  // A partner the classifier gives no real chance of being the other side stays out.
  void oneSidedChestWithoutAPlausiblePartnerStaysAlone() {
    const SeedPlan plan = choose_seed(
        four_panels(), classification({{{SeedClass::FrontChest, 0.8}},
                                       {{kFrontPelvis, 0.5}, {SeedClass::BackChest, 0.05}},
                                       {{SeedClass::BackChest, 0.05}},
                                       {}}));
    QCOMPARE(parts_of(plan), (Parts{{"chest_front", {0}}}));
  }

  // A pattern that names its sides is believed over the classifier's side: the Garment-Pattern-
  // Generator jacket's back comes out of the classifier a sure front chest, its front a back chest.
  void namedSidesOverruleTheClassifiersSides() {
    const SeedPlan plan = choose_seed(
        four_panels_named("back", "front"),
        classification({{{SeedClass::FrontChest, 0.99}}, {{SeedClass::BackChest, 0.99}}, {}, {}}));
    QCOMPARE(parts_of(plan), (Parts{{"chest_front", {1}}, {"chest_back", {0}}}));
  }

  // Names split identical panels the classifier cannot tell apart the way the pattern says, not
  // by their order (indistinguishablePanelsOnOneSideAreSplit puts piece 1 in front).
  void namesSplitIndistinguishablePanels() {
    const SeedPlan plan = choose_seed(four_panels_named("skirt_front", "skirt_back"),
                                      classification({{{kBackPelvis, 0.78}, {kFrontPelvis, 0.08}},
                                                      {{kBackPelvis, 0.78}, {kFrontPelvis, 0.08}},
                                                      {},
                                                      {}}));
    QCOMPARE(parts_of(plan), (Parts{{"pelvis_front", {0}}, {"pelvis_back", {1}}}));
  }

  // A piece named for a side that the classifier leaves out of the region by a hair joins that
  // side: the templates' flared trousers' left front (back pelvis 0.493, other 0.503). One it
  // hardly sees in the region stays out, whatever its name.
  void namedPieceNearlyInTheRegionJoinsItsSide() {
    const SeedPlan plan =
        choose_seed(four_panels_named("skirt_front", "skirt_back", "band_front", "flap_back"),
                    classification({{{kFrontPelvis, 0.8}},
                                    {{kBackPelvis, 0.8}},
                                    {{kBackPelvis, 0.45}},
                                    {{kBackPelvis, 0.2}}}));
    QCOMPARE(parts_of(plan), (Parts{{"pelvis_front", {0, 2}}, {"pelvis_back", {1}}}));
  }

  // A side found alone takes the piece sewn to it that is named for the other side, even when the
  // classifier gives that piece no chance of it (oneSidedChestWithoutAPlausiblePartnerStaysAlone).
  void oneSidedPartTakesItsPartnerNamedForTheOtherSide() {
    const SeedPlan plan = choose_seed(
        four_panels_named("front", "back"),
        classification({{{SeedClass::FrontChest, 0.8}}, {{kFrontPelvis, 0.5}}, {}, {}}));
    QCOMPARE(parts_of(plan), (Parts{{"chest_front", {0}}, {"chest_back", {1}}}));
  }

  // The two halves of an open front, not sewn to each other, are one front part, the body's
  // right half (−x) first as the front plane is seen: seeded alone, one half would take the
  // middle of the chest and leave the other to be laid flat beside the garment.
  void openFrontHalvesAreOnePart() {
    const SeedPlan plan =
        choose_seed(open_front(), classification({{{SeedClass::FrontChest, 0.9}},
                                                  {{SeedClass::FrontChest, 0.8}},
                                                  {{SeedClass::BackChest, 0.9}}}));
    QCOMPARE(parts_of(plan), (Parts{{"chest_front", {1, 0}}, {"chest_back", {2}}}));
  }

  // Without seed classes: the piece with the most garment hanging below its seams, the band
  // (piece 0, 0.3 m², below it), not piece 1 (the 0.05 m² flap below; pieces 0 and 1 are sewn
  // at their sides, which carries nothing).
  void ruleWithoutSeedClasses() {
    const SeedPlan plan = choose_seed(four_panels(), classification({{}, {}, {}, {}}));
    QCOMPARE(parts_of(plan), (Parts{{"waist", {2}}}));
    QCOMPARE(plan.reason, std::string("rule: most garment hanging below its seams"));
  }
};

QTEST_APPLESS_MAIN(SeedChoiceTest)
#include "test_seed_choice.moc"
