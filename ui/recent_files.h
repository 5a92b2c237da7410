#pragma once
// The most recently opened patterns and bodies, newest first, kept in QSettings.

#include <QString>
#include <QStringList>

namespace garment::ui {

class RecentFiles {
 public:
  static constexpr int kMaximum = 10;

  static QStringList load();
  static void add(const QString& path);  // moves it to the front
  static void remove(const QString& path);
  static void clear();

 private:
  static void save(const QStringList& paths);
};

}  // namespace garment::ui
