// The engine's folders form layers (DESIGN.md: "dependency direction is the architecture"): a file
// includes headers of its own folder and of folders below it, never above. The order, lowest
// first, is the one below; a folder missing from it fails the test, so that a new folder gets its
// place on purpose. Read from the source tree: every `#include "engine/<folder>/..."` of every
// file under engine/.

#include <QtTest>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "support/test_paths.h"

namespace {

const std::vector<std::string> kLayers = {"core",         "pattern",  "body",        "energy",
                                          "solver",       "quality",  "seeding",     "selection",
                                          "start_shapes", "arrange",  "termination", "post_process",
                                          "session",      "recovery", "io"};

int layer_of(const std::string& folder) {
  const auto found = std::find(kLayers.begin(), kLayers.end(), folder);
  return found == kLayers.end() ? -1 : static_cast<int>(found - kLayers.begin());
}

}  // namespace

class LayeringTest : public QObject {
  Q_OBJECT
 private slots:
  void noEngineFolderIncludesAHigherOne() {
    const std::filesystem::path engine = garment::test::test_data("../../engine");
    QVERIFY(std::filesystem::is_directory(engine));
    const std::regex include("#include \"engine/(\\w+)/");
    int files = 0, includes = 0;
    for (const auto& folder : std::filesystem::directory_iterator(engine)) {
      if (!folder.is_directory()) continue;
      const std::string name = folder.path().filename().string();
      QVERIFY2(layer_of(name) >= 0, ("engine/" + name + " has no place in the layers").c_str());
      for (const auto& file : std::filesystem::directory_iterator(folder.path())) {
        std::ifstream in(file.path());
        std::string line;
        int line_number = 0;
        ++files;
        while (std::getline(in, line)) {
          ++line_number;
          std::smatch match;
          if (!std::regex_search(line, match, include)) continue;
          ++includes;
          const std::string place = file.path().lexically_relative(engine).string() + ":" +
                                    std::to_string(line_number) + " includes engine/" +
                                    match[1].str();
          QVERIFY2(layer_of(match[1]) >= 0, (place + ", a folder with no place").c_str());
          QVERIFY2(layer_of(match[1]) <= layer_of(name), (place + ", a higher layer").c_str());
        }
      }
    }
    QVERIFY(files > 100 && includes > 300);  // the tree was read, not an empty folder
  }
};

QTEST_GUILESS_MAIN(LayeringTest)
#include "test_layering.moc"
