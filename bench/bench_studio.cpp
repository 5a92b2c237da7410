// The studio against the command line on the same garment (issue 42, item 8): what the live 3D
// updates, the window and the worker thread cost the arrangement. Each garment is arranged
// `--repeats` times both ways, alternating, so that both see the same machine:
//  - cli: a Session on the scene, run to the end in this process, as `garment-init run` does
//    (all cores);
//  - studio: the real main window (1600×1000) with its controller, Run triggered, waited until
//  done.
// Both print the engine's own clock of the arrangement's phases (SessionReport::seconds, what the
// studio's status bar shows) and the wall time from run to done; the ratios compare medians.
// Needs a display: run it under `xvfb-run -a`. The OpenGL rasteriser of Xvfb runs on the same
// cores as the solver, which a workstation's GPU would not: the studio's figures here are an upper
// bound.
// Usage: xvfb-run -a bench_studio [--repeats R] [PATTERN BODY]...
//        (default: the bundled demo on the default body, and gc_0488, 9,990 vertices, on mean_all)

#include <QAction>
#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFileInfo>
#include <QTimer>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "engine/body/default_body.h"
#include "engine/quality/garment_metrics.h"
#include "engine/quality/verdict.h"
#include "engine/seeding/scene.h"
#include "engine/session/session.h"
#include "ui/main_window.h"
#include "ui/opengl_format.h"
#include "ui/studio_controller.h"

namespace {

using namespace garment;

// A garment to arrange: its pattern and body files.
struct Subject {
  QString pattern, body;  // empty: the bundled demo, the default body
};

struct Timing {
  double engine_seconds = 0.0;  // SessionReport::seconds: the phases' own clock
  double wall_seconds = 0.0;    // from run to done
  // The process's processor time from run to done, every thread: the solver's, and in the studio
  // also the GUI's and the OpenGL rasteriser's. Less sensitive than the clock to other processes.
  double cpu_seconds = 0.0;
  bool ok = false;             // the garment passes its quality verdict
  Eigen::MatrixX3d positions;  // #V×3, the garment at the end
};

double process_cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

std::string load_average() {
  std::ifstream file("/proc/loadavg");
  std::string one, five, fifteen;
  file >> one >> five >> fifteen;
  return one + " " + five + " " + fifteen;
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n == 0 ? 0.0 : (n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]));
}

std::shared_ptr<const Scene> load(const Subject& garment) {
  const std::filesystem::path pattern =
      garment.pattern.isEmpty()
          ? std::filesystem::path(GARMENT_RESOURCES) / "demo/demo_pattern.json"
          : std::filesystem::path(garment.pattern.toStdString());
  return load_scene(pattern,
                    garment.body.isEmpty() ? default_body_path()
                                           : std::filesystem::path(garment.body.toStdString()),
                    {});
}

// The scene is loaded once: the studio too builds it before Run, off the clock.
Timing run_cli(const std::shared_ptr<const Scene>& scene) {
  Session session(scene, SessionOptions{});
  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = process_cpu_seconds();
  session.run();
  // Judged, as `garment-init run` judges and as the studio's "done" includes.
  const BodyReference reference(scene->body->mesh);
  const QualityVerdict verdict = judge_garment(
      *scene->garment, measure_garment(*scene->garment, session.positions(), &reference,
                                       expected_regions_from_names(*scene->garment)));
  Timing timing;
  timing.ok = verdict.ok();
  timing.positions = session.positions();
  timing.cpu_seconds = process_cpu_seconds() - cpu_start;
  timing.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  timing.engine_seconds = session.report().seconds;
  return timing;
}

// Waits in a real event loop (as the application runs), until `done` or the timeout.
bool wait_until(ui::StudioController& controller, bool (*done)(const ui::SessionState&),
                int timeout_ms) {
  if (done(controller.state())) return true;
  QEventLoop loop;
  QTimer::singleShot(timeout_ms, &loop, &QEventLoop::quit);
  QObject::connect(&controller, &ui::StudioController::stateApplied, &loop, [&] {
    if (done(controller.state())) loop.quit();
  });
  loop.exec();
  return done(controller.state());
}

bool run_studio(const Subject& garment, Timing& timing, std::string& error) {
  ui::MainWindow window;
  window.setErrorPresenter([&](const QString& title, const QString& message) {
    error = (title + ": " + message).toStdString();
  });
  window.resize(1600, 1000);
  SessionOptions exp;
  if (getenv("EXP_INTERVAL")) exp.snapshot_interval = atof(getenv("EXP_INTERVAL"));
  ui::StudioController controller(&window, exp);
  const bool opened =
      (garment.pattern.isEmpty() ? window.openDemoPattern()
                                 : window.openPattern(garment.pattern)) &&
      (garment.body.isEmpty() ? window.openDefaultBody() : window.openBody(garment.body));
  if (!opened) return false;
  window.show();
  if (!wait_until(
          controller, [](const ui::SessionState& s) { return s.has_session; }, 120000)) {
    error = "no session after 120 s";
    return false;
  }
  QElapsedTimer clock;
  clock.start();
  const double cpu_start = process_cpu_seconds();
  window.sessionActions().run_pause->trigger();
  if (!wait_until(
          controller, [](const ui::SessionState& s) { return s.done; }, 600000)) {
    error = "not done after 600 s";
    return false;
  }
  timing.wall_seconds = clock.nsecsElapsed() * 1e-9;
  timing.cpu_seconds = process_cpu_seconds() - cpu_start;
  timing.engine_seconds = controller.lastUpdate().elapsed_seconds;
  timing.ok = controller.state().verdict && controller.state().verdict->ok();
  timing.positions = *controller.lastUpdate().positions;
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  ui::use_opengl_core_profile();  // as garment-studio
  QApplication application(argc, argv);
  ui::drop_multisampling_on_software_opengl();
  int repeats = 3;
  std::vector<Subject> garments;
  const QStringList arguments = QCoreApplication::arguments();
  for (int i = 1; i < arguments.size(); ++i) {
    if (arguments[i] == "--repeats" && i + 1 < arguments.size()) {
      repeats = std::max(1, arguments[++i].toInt());
    } else if (i + 1 < arguments.size()) {
      garments.push_back({arguments[i], arguments[i + 1]});
      ++i;
    } else {
      std::fprintf(stderr, "usage: bench_studio [--repeats R] [PATTERN BODY]...\n");
      return 2;
    }
  }
  if (garments.empty()) {
    const QString shared = GARMENT_SHARED_DATA;
    garments.push_back({});
    garments.push_back({shared + "/patterns/garmentcode_random/gc_0488_specification.json",
                        shared + "/bodies/mean_all.obj"});
  }
  std::printf("bench_studio: %u hardware threads, %d repeats, load average %s\n",
              std::thread::hardware_concurrency(), repeats, load_average().c_str());
  std::printf("%-28s %8s | %-22s | %-22s | %-22s\n", "", "", "engine clock, s",
              "wall, run to done, s", "processor time, s");
  std::printf("%-28s %8s | %7s %7s %7s | %7s %7s %7s | %7s %7s %7s | %-4s %s\n", "garment",
              "vertices", "cli", "studio", "ratio", "cli", "studio", "ratio", "cli", "studio",
              "ratio", "same", "verdict");
  for (const Subject& garment : garments) {
    const auto scene = load(garment);
    std::vector<double> cli_engine, cli_wall, cli_cpu, studio_engine, studio_wall, studio_cpu;
    // Every run, either way, gives the very same garment (the same threads: all cores).
    bool same = true, ok = true;
    Eigen::MatrixX3d first;
    for (int repeat = 0; repeat < repeats; ++repeat) {
      const Timing cli = run_cli(scene);
      cli_engine.push_back(cli.engine_seconds);
      cli_wall.push_back(cli.wall_seconds);
      cli_cpu.push_back(cli.cpu_seconds);
      Timing studio;
      std::string error;
      if (!run_studio(garment, studio, error)) {
        std::fprintf(stderr, "studio failed on %s: %s\n", qPrintable(garment.pattern),
                     error.c_str());
        return 1;
      }
      studio_engine.push_back(studio.engine_seconds);
      studio_wall.push_back(studio.wall_seconds);
      studio_cpu.push_back(studio.cpu_seconds);
      if (repeat == 0) first = cli.positions;
      same = same && cli.positions == first && studio.positions == first;
      ok = ok && cli.ok && studio.ok;
    }
    const QString name = garment.pattern.isEmpty() ? "demo" : QFileInfo(garment.pattern).fileName();
    const double ce = median(cli_engine), se = median(studio_engine);
    const double cw = median(cli_wall), sw = median(studio_wall);
    const double cc = median(cli_cpu), sc = median(studio_cpu);
    std::printf(
        "%-28s %8lld | %7.2f %7.2f %6.2fx | %7.2f %7.2f %6.2fx | %7.2f %7.2f %6.2fx | %-4s %s\n",
        qPrintable(name), static_cast<long long>(scene->initial_positions.rows()), ce, se, se / ce,
        cw, sw, sw / cw, cc, sc, sc / cc, same ? "yes" : "no", ok ? "clean" : "fails");
  }
  std::printf(
      "(medians; ratio = studio / cli; same: every run gave the same garment both ways; load "
      "average at the end %s)\n",
      load_average().c_str());
  return 0;
}
