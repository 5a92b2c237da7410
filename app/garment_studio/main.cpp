// garment-studio: the desktop editor. Wiring only; the window lives in ui/.
//
//   garment-studio [PATTERN.json [OUTER.json…]] [--body BODY.obj] [--run | --steps N] [--select
//   PIECE[,PIECE…]]
//                  [--location NAME] [--click-location NAME] [--seed] [--arrange-next PIECE]
//                  [--fix] [--actions NAME[,NAME…]] [--threads N]
//                  [--screenshot OUT.png [--after-ms N] [--when-idle]] [--size WIDTHxHEIGHT]
// Without a pattern the bundled demo opens, without a body the bundled default body. Several
// patterns open as an outfit, the first innermost (as `garment-init run` takes them). --run starts
// the arrangement at once; --steps runs that many phases; --seed seeds the arrangement with the
// selected pieces at the chosen location and runs; --click-location clicks that location's marker
// in the 3D view once the session is ready; --arrange-next, once the arrangement is done, arranges
// that piece next and re-runs; --fix, once it is done, presses the Quality panel's "Fix
// automatically" (the screenshot waits for the fix to end). --actions triggers the window's actions
// of these object names once the window shows (view_overlay_strain, view_body_see_through, …:
// ui/avatar_view_actions.h). --threads N arranges on N threads (default 0: every core, as
// `garment-init run`): the result depends on the count, so the same N gives the CLI's garment.
// --screenshot saves the window after N ms (default 1500;
// with --when-idle, N ms after the arrangement has come to rest) and exits (0 saved, 1 not saved
// or timed out, 2 bad arguments, 3 a file failed to open), with fresh settings.

#include <tbb/global_control.h>
#include <QAction>
#include <QApplication>
#include <QCommandLineParser>
#include <QListWidget>
#include <QMouseEvent>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QTemporaryDir>
#include <QTimer>
#include <cstdio>
#include <optional>

#include "ui/avatar_view.h"
#include "ui/main_window.h"
#include "ui/manual_seed_panel.h"
#include "ui/opengl_format.h"
#include "ui/studio_controller.h"
#include "ui/window_screenshot.h"

int main(int argc, char** argv) {
  garment::ui::use_opengl_core_profile();
  QApplication application(argc, argv);
  garment::ui::drop_multisampling_on_software_opengl();
  QApplication::setApplicationName("garment-studio");
  QApplication::setOrganizationName("garment-studio");

  QCommandLineParser parser;
  parser.setApplicationDescription("Turns a sewing pattern into a 3D garment on a body.");
  parser.addHelpOption();
  parser.addPositionalArgument("pattern",
                               "GarmentCode pattern (.json); the bundled demo if absent. More "
                               "patterns: an outfit, the first innermost.",
                               "[pattern…]");
  const QCommandLineOption body_option("body", "Body mesh (.obj).", "file");
  const QCommandLineOption run_option("run", "Start the arrangement at launch.");
  const QCommandLineOption steps_option("steps", "Run this many phases at launch.", "n");
  const QCommandLineOption select_option("select", "Select the pieces of these names (a,b).",
                                         "pieces");
  const QCommandLineOption location_option("location", "Choose the body location of this name.",
                                           "location");
  const QCommandLineOption seed_option(
      "seed", "Seed with the selected pieces at the chosen location, and run.");
  const QCommandLineOption next_option(
      "arrange-next", "Once arranged, arrange this piece next and run again.", "piece");
  const QCommandLineOption click_option(
      "click-location", "Click the marker of this body location once ready.", "location");
  const QCommandLineOption fix_option("fix", "Once arranged, press Fix automatically.");
  const QCommandLineOption screenshot_option("screenshot", "Save the window as PNG and exit.",
                                             "file");
  const QCommandLineOption after_option("after-ms", "Delay before the screenshot.", "ms", "1500");
  const QCommandLineOption idle_option("when-idle",
                                       "Count the delay from when the arrangement comes to rest.");
  const QCommandLineOption size_option("size", "Window size, e.g. 1440x900.", "size");
  const QCommandLineOption actions_option(
      "actions", "Trigger the window's actions of these object names (a,b).", "names");
  const QCommandLineOption threads_option(
      "threads", "Threads to arrange on (0: every core); as garment-init run --threads.", "n", "0");
  parser.addOptions({body_option, run_option, steps_option, select_option, location_option,
                     seed_option, next_option, screenshot_option, after_option, idle_option,
                     size_option, actions_option, fix_option, click_option, threads_option});
  parser.process(application);

  bool delay_ok = false, steps_ok = true, threads_ok = false;
  const int delay_ms = parser.value(after_option).toInt(&delay_ok);
  const int threads = parser.value(threads_option).toInt(&threads_ok);
  const int steps = parser.isSet(steps_option) ? parser.value(steps_option).toInt(&steps_ok) : 0;
  const QRegularExpressionMatch size =
      QRegularExpression("^(\\d+)x(\\d+)$").match(parser.value(size_option));
  if (!delay_ok || delay_ms < 0 || !steps_ok || steps < 0 || !threads_ok || threads < 0 ||
      (parser.isSet(size_option) && !size.hasMatch())) {
    std::fprintf(stderr, "garment-studio: bad arguments (see --help)\n");
    return 2;
  }

  std::optional<tbb::global_control> thread_limit;
  if (threads > 0) thread_limit.emplace(tbb::global_control::max_allowed_parallelism, threads);

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
  garment::ui::StudioController controller(&window);
  controller.setRunWhenOpened(parser.isSet(run_option));

  const QStringList positional = parser.positionalArguments();
  bool opened =
      positional.isEmpty() ? window.openDemoPattern() : window.openPattern(positional.front());
  for (qsizetype i = 1; opened && i < positional.size(); ++i)
    opened = window.addGarment(positional[i]);
  opened = (parser.isSet(body_option) ? window.openBody(parser.value(body_option))
                                      : window.openDefaultBody()) &&
           opened;
  auto piece_index = [&window](const QString& name) {
    return window.garment() ? window.garment()->pattern.panel_index(name.toStdString()) : -1;
  };
  if (parser.isSet(select_option)) {
    QList<int> pieces;
    for (const QString& name : parser.value(select_option).split(',', Qt::SkipEmptyParts))
      if (piece_index(name) >= 0) pieces << piece_index(name);
    window.selectPieces(pieces);
  }
  if (parser.isSet(location_option)) {
    const QList<QListWidgetItem*> found =
        window.locationList()->findItems(parser.value(location_option), Qt::MatchExactly);
    if (!found.isEmpty()) window.locationList()->setCurrentItem(found.front());
  }
  window.show();
  if (scripted && !opened) return 3;
  for (const QString& name : parser.value(actions_option).split(',', Qt::SkipEmptyParts)) {
    auto* action = window.findChild<QAction*>(name);
    if (!action) {
      std::fprintf(stderr, "garment-studio: no action named %s\n", qPrintable(name));
      return 2;
    }
    action->trigger();
  }

  // What the command line asks for once the session is ready, and when the screenshot is due.
  const bool seed = parser.isSet(seed_option);
  const QString arrange_next = parser.value(next_option);
  const bool when_idle = parser.isSet(idle_option);
  const bool fix = parser.isSet(fix_option);
  bool started = false, next_done = false, fix_done = false, shot_due = false;
  // A left click on the marker's projection, as a user's (AvatarView picks it by position).
  auto click_marker = [&window](const QString& name) {
    garment::ui::AvatarView* view = window.avatarView();
    for (std::size_t i = 0; i < view->bodyLocations().size(); ++i) {
      if (view->bodyLocations()[i].name != name.toStdString()) continue;
      const QPointF at = view->projectToView(view->bodyLocations()[i].centre);
      for (QEvent::Type type : {QEvent::MouseButtonPress, QEvent::MouseButtonRelease}) {
        QMouseEvent event(type, at, view->mapToGlobal(at), Qt::LeftButton,
                          type == QEvent::MouseButtonPress ? Qt::LeftButton : Qt::NoButton,
                          Qt::NoModifier);
        QApplication::sendEvent(view, &event);
      }
      return;
    }
    std::fprintf(stderr, "garment-studio: no body location named %s\n", qPrintable(name));
  };
  auto take_screenshot = [&window, path = parser.value(screenshot_option), delay_ms] {
    QTimer::singleShot(delay_ms, &window, [&window, path] {
      const bool saved = garment::ui::save_window_screenshot(window, path);
      if (!saved) std::fprintf(stderr, "garment-studio: cannot write %s\n", qPrintable(path));
      QApplication::exit(saved ? 0 : 1);
    });
  };
  QObject::connect(&controller, &garment::ui::StudioController::stateApplied, &window,
                   [&](const garment::ui::SessionState& state) {
                     if (!state.has_session) return;
                     if (!started) {
                       started = true;
                       if (parser.isSet(click_option)) click_marker(parser.value(click_option));
                       if (seed) controller.seedPanel()->seedButton()->click();
                       for (int i = 0; i < steps; ++i)
                         controller.sessionThread()->stepSession();
                       return;
                     }
                     const bool at_rest =
                         !state.running && !state.fixing &&
                         (steps > 0 ? state.phases_completed >= steps : state.done);
                     if (!at_rest) return;
                     if (!arrange_next.isEmpty() && !next_done) {
                       next_done = true;
                       window.selectPieces({piece_index(arrange_next)});
                       controller.arrangeNextAction()->trigger();
                       return;
                     }
                     if (fix && !fix_done) {
                       fix_done = true;
                       auto* button = window.findChild<QPushButton*>("fix_automatically");
                       if (button && button->isEnabled()) {
                         button->click();
                         return;
                       }
                       std::fprintf(stderr, "garment-studio: nothing to fix\n");
                     }
                     if (scripted && when_idle && !shot_due) {
                       shot_due = true;
                       take_screenshot();
                     }
                   });

  if (scripted && !when_idle) take_screenshot();
  if (scripted && when_idle) {  // an arrangement (and a fix) that never comes to rest fails
    const int limit_s = fix ? 900 : 180;  // a fix solves several attempts
    QTimer::singleShot(limit_s * 1000, &window, [limit_s] {
      std::fprintf(stderr, "garment-studio: the arrangement did not come to rest in %d s\n",
                   limit_s);
      QApplication::exit(1);
    });
  }
  return QApplication::exec();
}
