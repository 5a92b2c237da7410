// garment-studio: the desktop editor. Wiring only; the window lives in ui/.

#include <QApplication>

#include "ui/main_window.h"

int main(int argc, char** argv) {
  QApplication application(argc, argv);
  QApplication::setApplicationName("garment-studio");
  QApplication::setOrganizationName("garment-studio");
  garment::ui::MainWindow window;
  window.show();
  return QApplication::exec();
}
