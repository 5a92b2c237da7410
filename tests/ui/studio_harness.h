#pragma once
// Shared by the studio's GUI tests: a main window with its controller on a pattern and a body, the
// errors the window would have shown in dialogs, and a wait for a session state. A test class
// derives from QObject and from StudioHarness, and resets controller_ before window_ in cleanup().

#include <QEventLoop>
#include <QSize>
#include <QString>
#include <QStringList>
#include <QTimer>
#include <QtTest>
#include <functional>
#include <memory>

#include "engine/session/session.h"
#include "ui/main_window.h"
#include "ui/studio_controller.h"

namespace garment::test {

class StudioHarness {
 protected:
  struct Opening {
    SessionOptions options;
    // Small enough that the software renderer under Xvfb keeps up, like a laptop window would.
    QSize size{1100, 700};
    QString pattern;        // empty: the bundled demo
    QString body;           // empty: the default body
    bool activate = false;  // make it the active window (for its shortcuts)
  };

  // A window as `opening` says, with a session ready (nothing run yet).
  void openStudio(Opening opening) {
    controller_.reset();
    window_ = std::make_unique<ui::MainWindow>();
    window_->setErrorPresenter([this](const QString& title, const QString& message) {
      errors_ << title + ": " + message;
    });
    window_->resize(opening.size);
    controller_ = std::make_unique<ui::StudioController>(window_.get(), std::move(opening.options));
    QVERIFY2(opening.pattern.isEmpty() ? window_->openDemoPattern()
                                       : window_->openPattern(opening.pattern),
             qPrintable(errors_.join("\n")));
    QVERIFY2(opening.body.isEmpty() ? window_->openDefaultBody() : window_->openBody(opening.body),
             qPrintable(errors_.join("\n")));
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
    if (opening.activate) {
      window_->activateWindow();
      QVERIFY(QTest::qWaitForWindowActive(window_.get()));
    }
    QVERIFY(QTest::qWaitFor([this] { return state().has_session; }, 120000));
  }

  const ui::SessionState& state() const { return controller_->state(); }

  // Waits in a real event loop, as the application does: QTest::qWaitFor sleeps 10 ms between
  // rounds of event processing, which would count against the window's latency.
  bool waitFor(const std::function<bool(const ui::SessionState&)>& predicate, int timeout_ms) {
    if (predicate(state())) return true;
    QEventLoop loop;
    QTimer::singleShot(timeout_ms, &loop, &QEventLoop::quit);
    QObject::connect(controller_.get(), &ui::StudioController::stateApplied, &loop, [&] {
      if (predicate(state())) loop.quit();
    });
    loop.exec();
    return predicate(state());
  }

  std::unique_ptr<ui::MainWindow> window_;
  std::unique_ptr<ui::StudioController> controller_;
  QStringList errors_;
};

}  // namespace garment::test
