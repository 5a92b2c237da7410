// Scale-out (issue 44, item 3): `batch --shard K/N` splits a batch between machines and `summary`
// merges the shards' outputs into the summary that one batch over every pattern writes. Runs
// garment-init on real patterns (tests/data) with short budgets; the comparison leaves out only
// the timing, which differs between any two runs.

#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>

#include "support/garment_init_process.h"
#include "support/test_paths.h"

namespace fs = std::filesystem;

namespace {

using garment::test::file_contents;
using garment::test::garment_init;
using garment::test::ProcessResult;

// Small patterns, in the name order the batch sorts them in: five, so that the three shards get
// two, two and one, and a merge that interleaved them wrongly would show.
const char* const kPatterns[] = {"gc_0005_specification.json", "gc_0012_specification.json",
                                 "gc_0022_specification.json", "gc_0037_specification.json",
                                 "skirts__skirt_4_panels.json"};

QJsonObject summary_json(const QString& folder) {
  return QJsonDocument::fromJson(
             QByteArray::fromStdString(file_contents((folder + "/summary.json").toStdString())))
      .object();
}

double wall_seconds(const QString& folder) {
  return summary_json(folder)["seconds"].toObject()["wall"].toDouble();
}

// summary.json without its timing: the "seconds" object and each result's seconds.
QJsonObject timeless(QJsonObject summary) {
  summary.remove("seconds");
  QJsonArray results;
  for (const QJsonValue& value : summary["results"].toArray()) {
    QJsonObject result = value.toObject();
    result.remove("seconds");
    results.append(result);
  }
  summary["results"] = results;
  return summary;
}

// summary.md without its timing: every number printed with two decimals is a time (counts are
// whole, the success rate has one decimal).
QString timeless_markdown(const QString& folder) {
  return QString::fromStdString(file_contents((folder + "/summary.md").toStdString()))
      .replace(QRegularExpression("\\b\\d+\\.\\d\\d\\b"), "T");
}

QStringList names(const QJsonObject& summary) {
  QStringList list;
  for (const QJsonValue& value : summary["results"].toArray())
    list << value.toObject()["name"].toString();
  return list;
}

}  // namespace

class ShardsTest : public QObject {
  Q_OBJECT

  QTemporaryDir root_;
  QString patterns_, whole_;
  QStringList batch_options_;

  QString path(const QString& name) const { return root_.filePath(name); }
  QString shard(int k) const { return path("shard-" + QString::number(k)); }

 private slots:
  // The whole batch and its three shards, run once for every test below.
  void initTestCase() {
    QVERIFY(root_.isValid());
    patterns_ = path("patterns");
    QVERIFY(QDir().mkpath(patterns_));
    for (const char* name : kPatterns)
      fs::copy_file(garment::test::test_data(fs::path("patterns") / name),
                    fs::path(patterns_.toStdString()) / name);
    std::ofstream(path("fast.json").toStdString())
        << R"({"align": {"first": 10, "revisit": 10}, "body_round": {"first": 2, "revisit": 2},
              "body_final": {"first": 4, "revisit": 4}, "refine": {"first": 4, "revisit": 4},
              "settle": {"first": 2, "revisit": 2}, "seed_iterations": 20,
              "post_process_iterations": 5})";
    batch_options_ = {"--attempts", "1", "--parameters", path("fast.json")};
    whole_ = path("whole");
    const ProcessResult whole =
        garment_init(QStringList{"batch", patterns_, "-o", whole_, "--jobs", "2"} + batch_options_);
    QVERIFY2(whole.exit_code == 0, qPrintable(whole.err));
    for (int k = 1; k <= 3; ++k) {
      const ProcessResult result =
          garment_init(QStringList{"batch", patterns_, "-o", shard(k), "--jobs", "2", "--shard",
                                   QString("%1/3").arg(k)} +
                       batch_options_);
      QVERIFY2(result.exit_code == 0, qPrintable(result.err));
    }
  }

  // Round robin over the name-sorted patterns: shard k has positions i with i % 3 == k - 1, each
  // pattern is in exactly one shard, and each shard says which it is.
  void shards_split_the_patterns() {
    const QStringList all = names(summary_json(whole_));
    QCOMPARE(all.size(), 5);
    std::map<QString, int> seen;
    for (int k = 1; k <= 3; ++k) {
      const QJsonObject summary = summary_json(shard(k));
      QStringList expected;
      for (int i = k - 1; i < all.size(); i += 3)
        expected << all[i];
      QCOMPARE(names(summary), expected);
      for (const QString& name : names(summary))
        ++seen[name];
      const QJsonObject split = summary["shard"].toObject();
      QCOMPARE(split["index"].toInt(), k);
      QCOMPARE(split["count"].toInt(), 3);
      QCOMPARE(split["patterns"].toInt(), 5);
      QVERIFY(QFileInfo::exists(shard(k) + "/" + expected.front() + ".obj"));
      QVERIFY(!QFileInfo::exists(shard(k) + "/" + all[k % 3] + ".outcome.json"));
    }
    QCOMPARE(static_cast<int>(seen.size()), 5);
    for (const auto& [name, count] : seen)
      QVERIFY2(count == 1, qPrintable(name));
    QVERIFY(!summary_json(whole_).contains("shard"));
  }

  // The merged summary is the whole batch's, timing aside, in whatever order the shards are given.
  void merge_equals_the_whole_batch_data() {
    QTest::addColumn<QStringList>("order");
    QTest::newRow("1 2 3") << QStringList{"1", "2", "3"};
    QTest::newRow("3 1 2") << QStringList{"3", "1", "2"};
  }
  void merge_equals_the_whole_batch() {
    QFETCH(QStringList, order);
    const QString merged = path("merged-" + order.join(""));
    QStringList arguments{"summary"};
    for (const QString& k : order)
      arguments << shard(k.toInt());
    const ProcessResult result = garment_init(arguments + QStringList{"-o", merged});
    QVERIFY2(result.exit_code == 0, qPrintable(result.err));
    QVERIFY(result.out.contains("5 patterns: "));
    const QJsonObject expected = timeless(summary_json(whole_)),
                      actual = timeless(summary_json(merged));
    QCOMPARE(names(actual), names(expected));
    for (const QString& key : expected.keys())
      QVERIFY2(actual[key] == expected[key], qPrintable(key));
    QCOMPARE(actual, expected);
    QCOMPARE(timeless_markdown(merged), timeless_markdown(whole_));
    // The wall time of a merge is the slowest shard's.
    double slowest = 0.0;
    for (int k = 1; k <= 3; ++k)
      slowest = std::max(slowest, wall_seconds(shard(k)));
    QCOMPARE(wall_seconds(merged), slowest);
  }

  // Without -o the merge only prints.
  void merge_without_output_writes_nothing() {
    const auto before = QDir(root_.path()).entryList();
    const ProcessResult result = garment_init({"summary", shard(1), shard(2), shard(3)});
    QVERIFY2(result.exit_code == 0, qPrintable(result.err));
    QVERIFY(result.out.contains("5 patterns: ") && !result.out.contains("summary: "));
    QCOMPARE(QDir(root_.path()).entryList(), before);
  }

  void bad_shard_is_refused_data() {
    QTest::addColumn<QString>("value");
    for (const char* value : {"0/3", "4/3", "1/0", "a/3", "1/3x", "3", "-1/3", "1/-3", "/3", ""})
      QTest::newRow(*value ? value : "(empty)") << QString(value);
  }
  void bad_shard_is_refused() {
    QFETCH(QString, value);
    const QString output = path("refused");
    const ProcessResult result =
        garment_init({"batch", patterns_, "-o", output, "--attempts", "1", "--shard", value});
    QCOMPARE(result.exit_code, 2);
    QVERIFY2(result.err.contains("--shard K/N"), qPrintable(result.err));
    QVERIFY(!QFileInfo::exists(output));
  }

  // Bad input to the merge: an error naming the file and the key, exit 1, nothing written.
  void bad_summaries_are_refused_data() {
    QTest::addColumn<QString>("case_name");
    QTest::addColumn<QString>("message");
    QTest::newRow("not a folder") << "not a folder"
                                  << "nowhere: not a folder";
    QTest::newRow("no summary.json") << "no summary.json"
                                     << "patterns/summary.json: missing";
    QTest::newRow("corrupt") << "corrupt"
                             << "corrupt/summary.json: not valid JSON";
    QTest::newRow("missing key") << "missing key"
                                 << "key/summary.json: results[0].vertices: missing";
    QTest::newRow("wrong type") << "wrong type"
                                << "type/summary.json: results[0].name: expected a string";
    QTest::newRow("same shard twice") << "same shard twice"
                                      << "shard 1/3 given twice";
    QTest::newRow("overlapping shards") << "overlapping shards"
                                        << "shard.index: shard 1/3, as is";
    QTest::newRow("a pattern twice") << "a pattern twice"
                                     << "results[0].name: pattern '";
    QTest::newRow("a shard missing") << "a shard missing"
                                     << "shard 3/3 missing";
    QTest::newRow("another split") << "another split"
                                   << "not one split";
    QTest::newRow("a result missing") << "a result missing"
                                      << "results: 1 entries, but shard 1/3 of 5 patterns has 2";
  }
  void bad_summaries_are_refused() {
    QFETCH(QString, case_name);
    QFETCH(QString, message);
    const fs::path base = (root_.path() + "/bad-" + case_name).toStdString();
    fs::create_directories(base);
    // A copy of shard k whose summary.json `edit` changes, in base/name.
    const auto edited = [&](int k, const QString& name,
                            const std::function<void(QJsonObject&)>& edit) {
      const fs::path folder = base / name.toStdString();
      fs::create_directories(folder);
      QJsonObject summary = summary_json(shard(k));
      edit(summary);
      std::ofstream(folder / "summary.json") << QJsonDocument(summary).toJson().toStdString();
      return QString::fromStdString(folder.string());
    };
    const auto result_field = [](QJsonObject& summary, const QString& key,
                                 const QJsonValue& value) {
      QJsonArray results = summary["results"].toArray();
      QJsonObject first = results[0].toObject();
      if (value.isUndefined())
        first.remove(key);
      else
        first[key] = value;
      results[0] = first;
      summary["results"] = results;
    };
    QStringList inputs;
    if (case_name == "not a folder") {
      inputs = {shard(1), shard(2), root_.path() + "/nowhere"};
    } else if (case_name == "no summary.json") {
      inputs = {patterns_};
    } else if (case_name == "corrupt") {
      fs::create_directories(base / "corrupt");
      std::ofstream(base / "corrupt" / "summary.json") << "{\"results\": [";
      inputs = {shard(1), shard(2), QString::fromStdString((base / "corrupt").string())};
    } else if (case_name == "missing key") {
      inputs = {edited(1, "key",
                       [&](QJsonObject& s) {
                         result_field(s, "vertices", QJsonValue(QJsonValue::Undefined));
                       }),
                shard(2), shard(3)};
    } else if (case_name == "wrong type") {
      inputs = {edited(1, "type", [&](QJsonObject& s) { result_field(s, "name", 7); }), shard(2),
                shard(3)};
    } else if (case_name == "same shard twice") {
      inputs = {shard(1), shard(2), shard(3), shard(1)};
    } else if (case_name == "overlapping shards") {
      inputs = {shard(1), shard(2), shard(3), edited(1, "copy", [](QJsonObject&) {})};
    } else if (case_name == "a pattern twice") {
      const QString taken = names(summary_json(shard(1))).front();
      inputs = {shard(1),
                edited(2, "twice", [&](QJsonObject& s) { result_field(s, "name", taken); }),
                shard(3)};
    } else if (case_name == "a shard missing") {
      inputs = {shard(1), shard(2)};
    } else if (case_name == "another split") {
      inputs = {shard(1), shard(2), shard(3), whole_};
    } else if (case_name == "a result missing") {
      inputs = {edited(1, "short",
                       [](QJsonObject& s) {
                         QJsonArray results = s["results"].toArray();
                         results.removeLast();
                         s["results"] = results;
                       }),
                shard(2), shard(3)};
    }
    const QString merged = QString::fromStdString((base / "merged").string());
    const ProcessResult result =
        garment_init(QStringList{"summary"} + inputs + QStringList{"-o", merged});
    QCOMPARE(result.exit_code, 1);
    QVERIFY2(result.err.contains(message), qPrintable(result.err));
    QVERIFY(!QFileInfo::exists(merged));
  }

  // The merged summary may not replace a shard's: it would be read back as that shard.
  void merge_onto_an_input_is_refused() {
    const std::string before = file_contents((shard(1) + "/summary.json").toStdString());
    const ProcessResult result =
        garment_init({"summary", shard(1), shard(2), shard(3), "-o", shard(1)});
    QCOMPARE(result.exit_code, 2);
    QVERIFY2(result.err.contains("summary.json"), qPrintable(result.err));
    QCOMPARE(file_contents((shard(1) + "/summary.json").toStdString()), before);
  }
};

QTEST_GUILESS_MAIN(ShardsTest)
#include "test_shards.moc"
