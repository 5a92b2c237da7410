#include "ui/window_screenshot.h"

#include <QWidget>

namespace garment::ui {

QImage grab_window(QWidget& window) {
  return window.grab().toImage();
}

bool save_window_screenshot(QWidget& window, const QString& path) {
  return grab_window(window).save(path, "PNG");
}

}  // namespace garment::ui
