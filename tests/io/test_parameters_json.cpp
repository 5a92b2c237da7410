// Arrangement parameters from JSON (`--parameters`): both spellings of a key take effect, and
// anything that would be silently ignored, or that the arrangement cannot use, is an error naming
// the file and the key.

#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

#include "engine/core/error.h"
#include "engine/io/parameters_json.h"

using namespace garment;

class ParametersJsonTest : public QObject {
  Q_OBJECT

  static ArrangementParameters applied(const std::string& text) {
    ArrangementParameters parameters;
    apply_parameters_json(text, "p.json", parameters);
    return parameters;
  }

  static QString error_of(const std::string& text) {
    try {
      applied(text);
    } catch (const InputError& error) {
      return QString::fromStdString(error.what());
    }
    return {};
  }

 private slots:
  void dottedKeysApply() {
    const ArrangementParameters defaults;
    const ArrangementParameters p =
        applied(R"({"energy.stretch_stiffness": 1234.5, "align.first": 7})");
    QCOMPARE(p.energy.stretch_stiffness, 1234.5);
    QCOMPARE(p.align.first, 7);
    QCOMPARE(p.energy.sewing_stiffness, defaults.energy.sewing_stiffness);
  }

  void nestedKeysApply() {
    const ArrangementParameters p =
        applied(R"({"energy": {"stretch_compression_factor": 0.25}, "refine": {"revisit": 9}})");
    QCOMPARE(p.energy.stretch_compression_factor, 0.25);
    QCOMPARE(p.refine.revisit, 9);
  }

  void unknownKeyNamesTheKey() {
    const QString message = error_of(R"({"energy.stretch_stifness": 1})");
    QVERIFY2(message.contains("p.json") && message.contains("energy.stretch_stifness"),
             qPrintable(message));
  }

  void wrongTypeNamesTheKey() {
    const QString message = error_of(R"({"energy": {"gravity": "strong"}})");
    QVERIFY2(message.contains("energy.gravity") && message.contains("number"), qPrintable(message));
    QVERIFY(!error_of("[1, 2]").isEmpty());
    QVERIFY(!error_of("{").isEmpty());
  }

  void outOfRangeStrainLimitNamesTheKey() {
    const QString factor = error_of(R"({"post_process_strain_limit_factor": 0.5})");
    QVERIFY2(factor.contains("p.json") && factor.contains("post_process_strain_limit_factor"),
             qPrintable(factor));
    const QString limit = error_of(R"({"post_process_strain_limit": -0.1})");
    QVERIFY2(limit.contains("post_process_strain_limit"), qPrintable(limit));
    QVERIFY(error_of(R"({"post_process_strain_limit_factor": 1})").isEmpty());
  }

  void outOfRangeSeamDrapeNamesTheKey() {
    for (const char* json :
         {R"({"seam_drape": {"flare_angle": 2}})", R"({"seam_drape": {"seam_extent": 0}})",
          R"({"seam_drape": {"flat_seam_ratio": -1}})"}) {
      const QString message = error_of(json);
      QVERIFY2(message.contains("p.json") && message.contains("seam_drape."), qPrintable(message));
    }
    QVERIFY(error_of(R"({"seam_drape": {"sideways_below": -1, "flare_angle": 0}})").isEmpty());
  }

  void outOfRangeLimbWrapNamesTheKey() {
    for (const auto& [json, key] :
         {std::pair{R"({"limb_wrap": {"reach": -0.1}})", "limb_wrap.reach"},
          std::pair{R"({"limb_wrap": {"above_armpit": -1}})", "limb_wrap.above_armpit"},
          std::pair{R"({"limb_wrap": {"least_turn": 7}})", "limb_wrap.least_turn"},
          std::pair{R"({"limb_wrap": {"clearance": -0.01}})", "limb_wrap.clearance"}}) {
      const QString message = error_of(json);
      QVERIFY2(message.contains("p.json") && message.contains(key), qPrintable(message));
    }
    QVERIFY(error_of(R"({"limb_wrap": {"reach": 0, "least_turn": 0}})").isEmpty());
  }

  void outOfRangeBodyBufferNamesTheKey() {
    const QString buffer = error_of(R"({"post_process_body_buffer": 0})");
    QVERIFY2(buffer.contains("post_process_body_buffer"), qPrintable(buffer));
    const QString edges = error_of(R"({"post_process_edge_repulsion_factor": -1})");
    QVERIFY2(edges.contains("post_process_edge_repulsion_factor"), qPrintable(edges));
    QVERIFY(error_of(R"({"post_process_edge_repulsion_factor": 0})").isEmpty());
  }

  void outOfRangeBendingFactorNamesTheKey() {
    const QString zero = error_of(R"({"post_process_bending_factor": 0})");
    QVERIFY2(zero.contains("post_process_bending_factor"), qPrintable(zero));
    QVERIFY(!error_of(R"({"post_process_bending_factor": -2})").isEmpty());
    QVERIFY(error_of(R"({"post_process_bending_factor": 0.5})").isEmpty());
  }

  void outOfRangeLiftTaperNamesTheKey() {
    const QString zero = error_of(R"({"lift_taper": 0})");
    QVERIFY2(zero.contains("lift_taper"), qPrintable(zero));
    QVERIFY(!error_of(R"({"lift_taper": -1})").isEmpty());
    QVERIFY(error_of(R"({"lift_taper": 2.5})").isEmpty());
  }

  void negativeOwnLayerRepulsionNamesTheKey() {
    const QString negative = error_of(R"({"post_process_own_layer_repulsion_factor": -0.5})");
    QVERIFY2(negative.contains("post_process_own_layer_repulsion_factor"), qPrintable(negative));
    QVERIFY(error_of(R"({"post_process_own_layer_repulsion_factor": 0})").isEmpty());
  }

  // Issue 40: these reached the solvers, which refused them with "the energy of the initial
  // positions is not finite" or "QuasiNewtonSettings out of range", naming neither file nor key.
  void unusableValuesNameTheFileAndTheKey() {
    for (const auto& [json, place] :
         {std::pair{R"({"energy": {"gravity": 1e308}})", "p.json: energy.gravity: 1e+308"},
          std::pair{R"({"energy.stretch_stiffness": -1000})",
                    "p.json: energy.stretch_stiffness: -1000"},
          std::pair{R"({"post_process_iterations": -1})", "p.json: post_process_iterations: -1"},
          std::pair{R"({"rings_per_round": 0})", "p.json: rings_per_round: 0"}}) {
      const QString message = error_of(json);
      QVERIFY2(message.startsWith(place) && message.contains("out of range: must be"),
               qPrintable(json + (" -> " + message)));
    }
    QCOMPARE(error_of(R"({"energy": {"gravity": 1e308}})"),
             QString("p.json: energy.gravity: 1e+308 is out of range: must be between 0 and 100 "
                     "(m/s²; 9.81 on Earth)"));
    QVERIFY(error_of(R"({"energy": {"gravity": 0}, "post_process_iterations": 0})").isEmpty());
  }

  // An iteration count of 2.5 was truncated to 2, and 1e308 converted to int (undefined).
  void wholeNumberKeysRefuseFractions() {
    QCOMPARE(error_of(R"({"align": {"first": 2.5}})"),
             QString("p.json: align.first: 2.5 is not a whole number"));
    QVERIFY2(error_of(R"({"align": {"first": 1e308}})").startsWith("p.json: align.first: 1e+308"),
             qPrintable(error_of(R"({"align": {"first": 1e308}})")));
    QCOMPARE(applied(R"({"align": {"first": 2.0}})").align.first, 2);
  }

  // Every key, spelt as the report writes it, refuses ±1e308: each has an upper and a lower bound.
  void everyKeyIsBounded() {
    const QJsonObject all =
        QJsonDocument::fromJson(QByteArray::fromStdString(parameters_json({}))).object();
    QStringList keys;
    for (auto group = all.begin(); group != all.end(); ++group) {
      if (group.value().isObject()) {
        for (const QString& key : group.value().toObject().keys())
          keys << group.key() + "." + key;
      } else {
        keys << group.key();
      }
    }
    QVERIFY2(keys.size() > 70, qPrintable(keys.join(", ")));
    for (const QString& key : keys)
      for (const char* huge : {"1e308", "-1e308"}) {
        const QString message = error_of("{\"" + key.toStdString() + "\": " + huge + "}");
        QVERIFY2(message.startsWith("p.json: " + key + ": "),
                 qPrintable(key + " = " + huge + " -> '" + message + "'"));
      }
  }

  void defaultsAreInRange() { QCOMPARE(error_of(parameters_json({})), QString()); }

  void reportedParametersReadBack() {
    ArrangementParameters changed;
    changed.energy.bending_stiffness = 0.004;
    changed.settle.first = 33;
    changed.post_process_gravity_factor = 0.5;
    const ArrangementParameters back = applied(parameters_json(changed));
    QCOMPARE(back.energy.bending_stiffness, 0.004);
    QCOMPARE(back.settle.first, 33);
    QCOMPARE(back.post_process_gravity_factor, 0.5);
  }
};

QTEST_APPLESS_MAIN(ParametersJsonTest)
#include "test_parameters_json.moc"
