#include "ui/main_window.h"

#include <QLabel>
#include <QSplitter>

namespace garment::ui {

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
  setWindowTitle(tr("garment-studio"));
  auto* splitter = new QSplitter(this);
  splitter->addWidget(new QLabel(tr("Pattern"), splitter));
  splitter->addWidget(new QLabel(tr("Avatar"), splitter));
  setCentralWidget(splitter);
  resize(1280, 800);
}

}  // namespace garment::ui
