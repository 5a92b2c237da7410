// garment-studio: the desktop editor. Wiring only; the window lives in ui/.
//
//   garment-studio [PATTERN.json] [--body BODY.obj] [--select PIECE] [--location NAME]
//                  [--screenshot OUT.png [--after-ms N]] [--size WIDTHxHEIGHT]
// Without a pattern the bundled demo opens, without a body the bundled default body. --screenshot
// saves the window after N ms (default 1500) and exits (0 saved, 1 not saved, 2 bad arguments, 3 a
// file failed to open), with fresh settings.

#include <QApplication>
#include <QCommandLineParser>
#include <QListWidget>
#include <QRegularExpression>
#include <QSettings>
#include <QTemporaryDir>
#include <QTimer>
#include <cstdio>

#include "ui/main_window.h"
#include "ui/opengl_format.h"
#include "ui/window_screenshot.h"

int main(int argc, char** argv) {
  garment::ui::use_opengl_core_profile();
  QApplication application(argc, argv);
  QApplication::setApplicationName("garment-studio");
  QApplication::setOrganizationName("garment-studio");

  QCommandLineParser parser;
  parser.setApplicationDescription("Turns a sewing pattern into a 3D garment on a body.");
  parser.addHelpOption();
  parser.addPositionalArgument("pattern",
                               "GarmentCode pattern (.json); the bundled demo if absent.");
  const QCommandLineOption body_option("body", "Body mesh (.obj).", "file");
  const QCommandLineOption select_option("select", "Select the piece of this name.", "piece");
  const QCommandLineOption location_option("location", "Highlight the body location of this name.",
                                           "location");
  const QCommandLineOption screenshot_option("screenshot", "Save the window as PNG and exit.",
                                             "file");
  const QCommandLineOption after_option("after-ms", "Delay before the screenshot.", "ms", "1500");
  const QCommandLineOption size_option("size", "Window size, e.g. 1440x900.", "size");
  parser.addOptions(
      {body_option, select_option, location_option, screenshot_option, after_option, size_option});
  parser.process(application);

  bool delay_ok = false;
  const int delay_ms = parser.value(after_option).toInt(&delay_ok);
  const QRegularExpressionMatch size =
      QRegularExpression("^(\\d+)x(\\d+)$").match(parser.value(size_option));
  if (!delay_ok || delay_ms < 0 || (parser.isSet(size_option) && !size.hasMatch()) ||
      parser.positionalArguments().size() > 1) {
    std::fprintf(stderr, "garment-studio: bad arguments (see --help)\n");
    return 2;
  }

  const bool scripted = parser.isSet(screenshot_option);
  // Screenshots start from default settings (no saved layout, no recent files) and leave the
  // user's settings alone, so that they come out the same on every machine.
  QTemporaryDir scratch_settings;
  if (scripted) {
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, scratch_settings.path());
  }
  garment::ui::MainWindow window;
  if (scripted)  // a script has nobody to close a dialog: errors go to stderr
    window.setErrorPresenter([](const QString& title, const QString& message) {
      std::fprintf(stderr, "garment-studio: %s: %s\n", qPrintable(title), qPrintable(message));
    });
  if (size.hasMatch()) window.resize(size.captured(1).toInt(), size.captured(2).toInt());

  const QStringList positional = parser.positionalArguments();
  bool opened =
      positional.isEmpty() ? window.openDemoPattern() : window.openPattern(positional.front());
  opened = (parser.isSet(body_option) ? window.openBody(parser.value(body_option))
                                      : window.openDefaultBody()) &&
           opened;
  if (parser.isSet(select_option) && window.garment()) {
    const int piece =
        window.garment()->pattern.panel_index(parser.value(select_option).toStdString());
    if (piece >= 0) window.selectPieces({piece});
  }
  if (parser.isSet(location_option)) {
    const QList<QListWidgetItem*> found =
        window.locationList()->findItems(parser.value(location_option), Qt::MatchExactly);
    if (!found.isEmpty()) window.locationList()->setCurrentItem(found.front());
  }
  window.show();
  if (scripted && !opened) return 3;

  if (scripted) {
    const QString path = parser.value(screenshot_option);
    QTimer::singleShot(delay_ms, &window, [&window, path] {
      const bool saved = garment::ui::save_window_screenshot(window, path);
      if (!saved) std::fprintf(stderr, "garment-studio: cannot write %s\n", qPrintable(path));
      QApplication::exit(saved ? 0 : 1);
    });
  }
  return QApplication::exec();
}
