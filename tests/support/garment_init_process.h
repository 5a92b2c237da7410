#pragma once
// The command-line tests' way of running garment-init (GARMENT_INIT_EXE, tests/CMakeLists.txt) and
// reading back what it wrote.

#include <QProcess>
#include <QString>
#include <QStringList>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace garment::test {

struct ProcessResult {
  int exit_code;  // -1 when it crashed or ran past the 5 minutes
  QString out, err;
};

inline ProcessResult garment_init(const QStringList& arguments) {
  QProcess process;
  process.start(GARMENT_INIT_EXE, arguments);
  if (!process.waitForFinished(300000)) {
    process.kill();
    process.waitForFinished();
    return {-1, {}, "timed out"};
  }
  return {process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1,
          process.readAllStandardOutput(), process.readAllStandardError()};
}

// The file's bytes ("" when it cannot be read).
inline std::string file_contents(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace garment::test
