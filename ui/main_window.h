#pragma once
// The garment-studio main window: pattern view and avatar view side by side.

#include <QMainWindow>

namespace garment::ui {

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  explicit MainWindow(QWidget* parent = nullptr);
};

}  // namespace garment::ui
