#include "ui/recent_files.h"

#include <QFileInfo>
#include <QSettings>

namespace garment::ui {

namespace {
constexpr const char* kKey = "recent/files";
}

QStringList RecentFiles::load() {
  return QSettings().value(kKey).toStringList();
}

void RecentFiles::save(const QStringList& paths) {
  QSettings().setValue(kKey, paths);
}

void RecentFiles::add(const QString& path) {
  const QString absolute = QFileInfo(path).absoluteFilePath();
  QStringList paths = load();
  paths.removeAll(absolute);
  paths.prepend(absolute);
  while (paths.size() > kMaximum)
    paths.removeLast();
  save(paths);
}

void RecentFiles::remove(const QString& path) {
  QStringList paths = load();
  paths.removeAll(QFileInfo(path).absoluteFilePath());
  save(paths);
}

void RecentFiles::clear() {
  save({});
}

}  // namespace garment::ui
