#pragma once
// A PNG of a window as it is on screen, OpenGL views included (for docs/ and for tests).

#include <QImage>
#include <QString>

class QWidget;

namespace garment::ui {

QImage grab_window(QWidget& window);
// Returns false when the file cannot be written.
bool save_window_screenshot(QWidget& window, const QString& path);

}  // namespace garment::ui
