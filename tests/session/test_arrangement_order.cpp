// Where an explicit order puts each piece (engine/session/arrangement_order.h), on the bundled demo
// (resources/demo/demo_pattern.json: a top whose left half has a sleeve of two panels with a cuff
// of two panels; each cuff panel is sewn to the other and to its sleeve panel only):
// - an order that respects the seams is kept as asked;
// - a cuff panel asked before its sleeve panel waits for it (the partners are named), and the
//   pieces asked after it move up;
// - the seed goes first wherever the order puts it, and says so;
// - bad entries (out of range, repeated) are left out, never a crash.

#include <QtTest>

#include <string>

#include "engine/body/default_body.h"
#include "engine/pattern/pattern.h"
#include "engine/session/arrangement_order.h"

using namespace garment;

class ArrangementOrderTest : public QObject {
  Q_OBJECT

  Garment garment_;

  int piece(const std::string& name) const {
    for (std::size_t p = 0; p < garment_.pieces.size(); ++p)
      if (garment_.pieces[p].name == name) return static_cast<int>(p);
    return -1;
  }
  std::vector<int> pieces(std::initializer_list<const char*> names) const {
    std::vector<int> result;
    for (const char* name : names)
      result.push_back(piece(name));
    return result;
  }

 private slots:
  void initTestCase() {
    garment_ = build_garment(load_pattern(resource_directory() / "demo" / "demo_pattern.json"));
    QCOMPARE(garment_.pieces.size(), std::size_t{8});
    QVERIFY(piece("sl_left_cuff_f") >= 0 && piece("left_sleeve_f") >= 0);
  }

  void partners_are_the_pieces_sewn_to() {
    QCOMPARE(sewing_partners(garment_, piece("sl_left_cuff_f")), [&] {
      std::vector<int> expected = pieces({"left_sleeve_f", "sl_left_cuff_b"});
      std::sort(expected.begin(), expected.end());
      return expected;
    }());
    std::vector<bool> arranged(8, false);
    arranged[piece("left_sleeve_b")] = true;
    QVERIFY(!sewn_to_arranged(garment_, piece("sl_left_cuff_f"), arranged));
    QVERIFY(sewn_to_arranged(garment_, piece("sl_left_cuff_b"), arranged));
  }

  void an_order_along_the_seams_is_kept() {
    const std::vector<int> seed = pieces({"right_ftorso", "right_btorso"});
    const std::vector<int> asked = pieces({"right_ftorso", "right_btorso", "left_ftorso",
                                           "left_sleeve_f", "sl_left_cuff_f", "left_btorso"});
    const OrderPlan plan = plan_order(garment_, seed, asked);
    QCOMPARE(plan.order, asked);
    QVERIFY(plan.moved.empty());
  }

  void a_cuff_before_its_sleeve_waits_for_it() {
    const std::vector<int> seed = pieces({"right_ftorso", "right_btorso"});
    const OrderPlan plan = plan_order(garment_, seed,
                                      pieces({"right_ftorso", "right_btorso", "left_ftorso",
                                              "sl_left_cuff_f", "left_sleeve_f", "left_btorso"}));
    QCOMPARE(plan.order, pieces({"right_ftorso", "right_btorso", "left_ftorso", "left_sleeve_f",
                                 "sl_left_cuff_f", "left_btorso"}));
    QCOMPARE(plan.moved.size(), std::size_t{1});
    const OrderPlan::Moved& moved = plan.moved.front();
    QCOMPARE(moved.piece, piece("sl_left_cuff_f"));
    QCOMPARE(moved.requested_position, 3);
    QCOMPARE(moved.position, 4);
    QVERIFY(!moved.seed);
    std::vector<int> partners = pieces({"left_sleeve_f", "sl_left_cuff_b"});
    std::sort(partners.begin(), partners.end());
    QCOMPARE(moved.waits_for, partners);

    // Nothing it is sewn to asked for at all: it goes last, still waiting.
    const OrderPlan alone =
        plan_order(garment_, seed, pieces({"right_ftorso", "right_btorso", "sl_left_cuff_b"}));
    QCOMPARE(alone.order, pieces({"right_ftorso", "right_btorso", "sl_left_cuff_b"}));
    QVERIFY(alone.moved.empty());  // where it was asked, though only the selection can place it
  }

  void the_seed_goes_first() {
    const std::vector<int> seed = pieces({"right_ftorso", "right_btorso"});
    const OrderPlan plan =
        plan_order(garment_, seed, pieces({"left_ftorso", "right_ftorso", "right_btorso"}));
    QCOMPARE(plan.order, pieces({"right_ftorso", "right_btorso", "left_ftorso"}));
    QCOMPARE(plan.moved.size(), std::size_t{3});
    for (const OrderPlan::Moved& moved : plan.moved)
      QVERIFY(moved.seed);
  }

  void bad_entries_are_left_out() {
    const std::vector<int> seed = pieces({"right_ftorso", "right_btorso"});
    const OrderPlan plan = plan_order(garment_, seed,
                                      {piece("right_ftorso"), piece("right_btorso"), -3, 99,
                                       piece("left_ftorso"), piece("left_ftorso")});
    QCOMPARE(plan.order, pieces({"right_ftorso", "right_btorso", "left_ftorso"}));
    QVERIFY(plan.moved.empty());
    QCOMPARE(plan_order(garment_, {42}, {}).order, std::vector<int>{});
  }
};

QTEST_APPLESS_MAIN(ArrangementOrderTest)
#include "test_arrangement_order.moc"
