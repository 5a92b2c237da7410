// Replays the fuzz regression corpus (tests/fuzz/corpus/<target>/) through the fuzz targets' own
// entry functions (fuzz_entries.h), built with the normal compiler: every input that once crashed,
// hung or leaked, and the seeds, must now return (a result or an InputError) within a time bound.

#include <QtTest>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "fuzz_entries.h"
#include "support/test_paths.h"

namespace fs = std::filesystem;

namespace {

// Per input, generous for a sanitizer build on a loaded machine; libFuzzer ran with -timeout=10.
constexpr double kSecondsPerInput = 20.0;

std::vector<fs::path> corpus(const char* target) {
  std::vector<fs::path> files;
  for (const auto& entry :
       fs::directory_iterator(garment::test::test_data("../fuzz/corpus") / target))
    if (entry.is_regular_file()) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<std::uint8_t> bytes_of(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void add_rows(const char* target) {
  QTest::addColumn<QString>("path");
  const auto files = corpus(target);
  QVERIFY2(files.size() >= 10, "the corpus is missing");
  for (const fs::path& file : files)
    QTest::newRow(file.filename().string().c_str()) << QString::fromStdString(file.string());
}

template <typename Entry>
void replay(const QString& path, Entry entry) {
  const std::vector<std::uint8_t> data = bytes_of(path.toStdString());
  const auto start = std::chrono::steady_clock::now();
  entry(data.data(), data.size());
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  QVERIFY2(seconds < kSecondsPerInput, qPrintable(QString("%1 took %2 s").arg(path).arg(seconds)));
}

}  // namespace

class CorpusReplay : public QObject {
  Q_OBJECT
 private slots:
  void pattern_data() { add_rows("pattern"); }
  void pattern() {
    QFETCH(QString, path);
    replay(path, garment::fuzz::fuzz_pattern_input);
  }
  void obj_data() { add_rows("obj"); }
  void obj() {
    QFETCH(QString, path);
    replay(path, garment::fuzz::fuzz_obj_input);
  }
};

QTEST_GUILESS_MAIN(CorpusReplay)
#include "test_corpus_replay.moc"
