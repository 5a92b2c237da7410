// Issue 42, items 4 and 7, on real patterns and the bundled body with a real session:
// - clicking a body location's marker (at AvatarView::projectToView of the location) chooses that
//   location: the Body locations list's current row, the marker highlighted, the seed panel's
//   choice; every one of the body's locations can be clicked from one of the four side views;
// - pieces dropped on a marker seed them there (SessionState::seed afterwards). The drag-move and
//   drop events are built as Qt's drag manager builds them and handed to the 3D view's event():
//   QDrag::exec runs the platform's drag loop, which QtTest cannot drive, so the pattern view's
//   start of the drag is not simulated;
// - pattern labels: for every pattern in tests/data (bad/ aside), framed and zoomed in, no two
//   shown labels overlap, none overlaps the legend, each lies inside the view;
// - at 1600×1000 no label or button in the docks is clipped or elided;
// - every action's tooltip gives its shortcut; Help › Keyboard shortcuts lists every action with
//   its shortcut, read from the actions (one added later shows too); Help › About.

#include <QAction>
#include <QDialog>
#include <QDirIterator>
#include <QDockWidget>
#include <QDragMoveEvent>
#include <QDropEvent>
#include <QEventLoop>
#include <QLabel>
#include <QListWidget>
#include <QMenuBar>
#include <QPushButton>
#include <QTableWidget>
#include <QToolBar>
#include <QToolButton>
#include <QtTest>
#include <functional>
#include <set>

#include "tests/ui/ui_test_support.h"
#include "ui/avatar_view.h"
#include "ui/help_dialogs.h"
#include "ui/main_window.h"
#include "ui/manual_seed_panel.h"
#include "ui/pattern_view.h"
#include "ui/piece_drag.h"
#include "ui/studio_controller.h"

using namespace garment;

class StudioMarkersTest : public QObject {
  Q_OBJECT

 private:
  std::unique_ptr<ui::MainWindow> window_;
  std::unique_ptr<ui::StudioController> controller_;
  QStringList errors_;

  // The window at 1600×1000 with the demo on the bundled body, its session ready.
  void open() {
    controller_.reset();
    window_ = std::make_unique<ui::MainWindow>();
    window_->setErrorPresenter([this](const QString& title, const QString& message) {
      errors_ << title + ": " + message;
    });
    window_->resize(1600, 1000);
    controller_ = std::make_unique<ui::StudioController>(window_.get(), test::quick_options());
    QVERIFY(window_->openDemoPattern());
    QVERIFY(window_->openDefaultBody());
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
    QVERIFY(QTest::qWaitFor([this] { return controller_->state().has_session; }, 60000));
  }

  bool waitFor(const std::function<bool(const ui::SessionState&)>& predicate, int timeout_ms) {
    if (predicate(controller_->state())) return true;
    QEventLoop loop;
    QTimer::singleShot(timeout_ms, &loop, &QEventLoop::quit);
    connect(controller_.get(), &ui::StudioController::stateApplied, &loop, [&] {
      if (predicate(controller_->state())) loop.quit();
    });
    loop.exec();
    return predicate(controller_->state());
  }

  int piece(const char* name) const { return window_->garment()->pattern.panel_index(name); }

  // Turns the 3D view to a side from which location `i`'s marker is the one a click at its
  // projection picks; false when no side does.
  bool faceLocation(int i) {
    ui::AvatarView* view = window_->avatarView();
    for (auto side : {ui::AvatarView::Side::Front, ui::AvatarView::Side::Back,
                      ui::AvatarView::Side::Left, ui::AvatarView::Side::Right}) {
      view->viewFrom(side);
      view->frameAll();
      const QPointF p = view->projectToView(view->bodyLocations()[i].centre);
      if (QRectF(view->rect()).contains(p) && view->locationAt(p) == i) return true;
    }
    return false;
  }

  // Hands a drag event to the widget as the drag manager does (QApplication::notify delivers drag
  // events only while a platform drag is in progress).
  static void deliver(QWidget* widget, QEvent* event) {
    static_cast<QObject*>(widget)->event(event);
  }

  QPoint markerPoint(int i) const {
    return window_->avatarView()
        ->projectToView(window_->avatarView()->bodyLocations()[i].centre)
        .toPoint();
  }

 private slots:
  void clickingAMarkerChoosesItsLocation() {
    open();
    ui::AvatarView* view = window_->avatarView();
    const int count = static_cast<int>(view->bodyLocations().size());
    QCOMPARE(count, 15);
    QCOMPARE(window_->locationList()->currentRow(), -1);
    for (int i = 0; i < count; ++i) {
      const QString name = QString::fromStdString(view->bodyLocations()[i].name);
      QVERIFY2(faceLocation(i), qPrintable(name + ": no side shows its marker apart"));
      QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, markerPoint(i));
      QCOMPARE(window_->locationList()->currentRow(), i);
      QCOMPARE(window_->locationList()->currentItem()->text(), name);
      QCOMPARE(view->highlightedLocation(), i);
    }
    // The seed panel's choice names the location clicked last.
    window_->selectPieces({piece("right_ftorso")});
    Q_EMIT window_->pieceSelectionChanged(window_->selectedPieces());
    QVERIFY(controller_->seedPanel()->seedButton()->isEnabled());

    // A click away from every marker chooses nothing new (it picks pieces as before).
    const int chosen = window_->locationList()->currentRow();
    QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, QPoint(3, 3));
    QCOMPARE(view->locationAt(QPointF(3, 3)), -1);
    QCOMPARE(window_->locationList()->currentRow(), chosen);
    // Hidden markers (M) cannot be clicked.
    const int other = chosen == 0 ? 1 : 0;
    QVERIFY(faceLocation(other));
    window_->avatarViewActions().markers->trigger();
    QVERIFY(!view->markersShown());
    QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, markerPoint(other));
    QCOMPARE(window_->locationList()->currentRow(), chosen);
    window_->avatarViewActions().markers->trigger();
    QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, markerPoint(other));
    QCOMPARE(window_->locationList()->currentRow(), other);
    QVERIFY2(errors_.isEmpty(), qPrintable(errors_.join('\n')));
  }

  void droppingPiecesOnAMarkerSeedsThemThere() {
    open();
    ui::AvatarView* view = window_->avatarView();
    // right_ftorso alone at the first location the classifier's seed does not use.
    std::set<std::string> used;
    for (const SeedPart& part : controller_->state().seed.parts)
      used.insert(part.location);
    int location = -1;
    for (int i = 0; i < static_cast<int>(view->bodyLocations().size()) && location < 0; ++i)
      if (!used.count(view->bodyLocations()[i].name) && faceLocation(i)) location = i;
    QVERIFY(location >= 0);
    const std::string location_name = view->bodyLocations()[location].name;
    const int dropped = piece("right_ftorso");
    QVERIFY(dropped >= 0);
    QVERIFY(!controller_->state().seed.manual);

    std::unique_ptr<QMimeData> data(ui::piece_mime_data({dropped}));
    // Over the background the drag is refused, over the marker accepted.
    QDragMoveEvent away(QPoint(3, 3), Qt::CopyAction, data.get(), Qt::LeftButton, Qt::NoModifier);
    deliver(view, &away);
    QVERIFY(!away.isAccepted());
    QDragMoveEvent over(markerPoint(location), Qt::CopyAction, data.get(), Qt::LeftButton,
                        Qt::NoModifier);
    deliver(view, &over);
    QVERIFY(over.isAccepted());
    // Text that is not pieces is refused at the marker too.
    QMimeData text;
    text.setText(QString::number(dropped));
    QVERIFY(!view->dropPieces(&text, markerPoint(location)));

    QDropEvent drop(QPointF(markerPoint(location)), Qt::CopyAction, data.get(), Qt::LeftButton,
                    Qt::NoModifier);
    deliver(view, &drop);
    QVERIFY(drop.isAccepted());
    // Both choices show as if made by hand, and the seed is asked for.
    QCOMPARE(window_->selectedPieces(), QList<int>{dropped});
    QCOMPARE(window_->locationList()->currentRow(), location);
    QVERIFY(waitFor([](const ui::SessionState& s) { return s.seed.manual && s.done; }, 120000));
    const SeedPlan& seed = controller_->state().seed;
    QCOMPARE(seed.parts.size(), std::size_t{1});
    QCOMPARE(seed.parts[0].location, location_name);
    QCOMPARE(seed.parts[0].pieces, std::vector<int>{dropped});
    QVERIFY2(errors_.isEmpty(), qPrintable(errors_.join('\n')));
  }

  void patternLabelsNeitherOverlapNorLeaveTheView() {
    ui::MainWindow window;
    window.setErrorPresenter([](const QString& title, const QString& message) {
      QFAIL(qPrintable(title + ": " + message));
    });
    window.resize(1600, 1000);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QStringList patterns;
    QDirIterator files(GARMENT_TEST_DATA "/patterns", {"*.json"}, QDir::Files,
                       QDirIterator::Subdirectories);
    while (files.hasNext()) {
      const QString path = files.next();
      if (!path.contains("/bad/")) patterns << path;
    }
    patterns.sort();
    QVERIFY(patterns.size() >= 10);
    ui::PatternView* view = window.patternView();
    int shown_total = 0, label_total = 0;
    for (const QString& path : patterns) {
      QVERIFY2(window.openPattern(path), qPrintable(path));
      const int pieces = static_cast<int>(window.garment()->pieces.size());
      // Framed, then zoomed in twice at the centre (labels keep their size, pieces grow).
      for (int zoom = 0; zoom < 3; ++zoom) {
        if (zoom > 0) {
          QWheelEvent wheel(
              QPointF(view->viewport()->rect().center()),
              view->viewport()->mapToGlobal(QPointF(view->viewport()->rect().center())), QPoint(),
              QPoint(0, 240), Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
          QApplication::sendEvent(view->viewport(), &wheel);
        }
        const QRectF bounds(view->viewport()->rect());
        const QRectF legend =
            QRectF(view->legend()->geometry()).translated(-QPointF(view->viewport()->pos()));
        std::vector<QRectF> shown;
        for (int p = 0; p < pieces; ++p) {
          const QRectF rect = view->labelRect(p);
          if (rect.isEmpty()) continue;
          const QString where = QString("%1 zoom %2 piece %3").arg(path).arg(zoom).arg(p);
          QVERIFY2(bounds.contains(rect), qPrintable(where + " runs off the view"));
          QVERIFY2(!legend.intersects(rect), qPrintable(where + " is under the legend"));
          for (const QRectF& other : shown)
            QVERIFY2(!other.intersects(rect), qPrintable(where + " overlaps another label"));
          shown.push_back(rect);
        }
        if (zoom == 0) {
          // Framed, the labels mostly fit; the count is printed to watch it.
          qInfo("%s: %zu of %d labels shown", qPrintable(QFileInfo(path).fileName()), shown.size(),
                pieces);
          shown_total += static_cast<int>(shown.size());
          label_total += pieces;
          QVERIFY2(!shown.empty(), qPrintable(path));
        }
      }
    }
    qInfo("framed: %d of %d labels shown", shown_total, label_total);
    QVERIFY(2 * shown_total >= label_total);
  }

  void docksShowTheirTextUnclippedAt1600x1000() {
    open();
    // After an arrangement, with the quality verdict, the seed texts and the order filled in.
    window_->sessionActions().run_pause->trigger();
    QVERIFY(waitFor([](const ui::SessionState& s) { return s.done && !s.running; }, 120000));
    QTest::qWait(0);  // let the layouts settle (no timing involved: one pass of the event loop)
    QCOMPARE(window_->size(), QSize(1600, 1000));
    QStringList clipped;
    int checked = 0;
    for (QDockWidget* dock : window_->findChildren<QDockWidget*>()) {
      if (!dock->isVisible()) continue;  // a tab behind another
      QList<QWidget*> widgets;
      for (QLabel* label : dock->findChildren<QLabel*>())
        widgets << label;
      // Buttons with text (the title bars' float and close buttons show only an icon).
      for (QAbstractButton* button : dock->findChildren<QAbstractButton*>())
        if (!button->text().isEmpty()) widgets << button;
      for (QWidget* widget : widgets) {
        if (!widget->isVisible()) continue;
        ++checked;
        auto* label = qobject_cast<QLabel*>(widget);
        const QString name =
            dock->objectName() + "/" + widget->metaObject()->className() + " \"" +
            (label ? label->text() : static_cast<QAbstractButton*>(widget)->text()).left(40) + "\"";
        if (label && label->wordWrap()) {
          // A wrapped label needs its height for its width.
          if (label->heightForWidth(label->width()) > label->height())
            clipped << QString("%1: needs %2 px high, has %3")
                           .arg(name)
                           .arg(label->heightForWidth(label->width()))
                           .arg(label->height());
        } else if (widget->sizeHint().width() > widget->width()) {
          clipped << QString("%1: needs %2 px wide, has %3")
                         .arg(name)
                         .arg(widget->sizeHint().width())
                         .arg(widget->width());
        }
      }
    }
    qInfo("%d labels and buttons checked in the docks", checked);
    QVERIFY(checked >= 8);
    QVERIFY2(clipped.isEmpty(), qPrintable(clipped.join('\n')));
  }

  void tooltipsAndTheShortcutsDialogComeFromTheActions() {
    open();
    const QList<QAction*> actions = ui::window_actions(window_.get());
    int with_shortcut = 0;
    for (QAction* action : actions) {
      const QString shortcut = action->shortcut().toString(QKeySequence::NativeText);
      if (shortcut.isEmpty()) continue;
      ++with_shortcut;
      QVERIFY2(action->toolTip().endsWith("(" + shortcut + ")"),
               qPrintable(action->text() + ": " + action->toolTip()));
    }
    QVERIFY(with_shortcut >= 25);
    // The toolbar's buttons show the same tooltips.
    for (QToolButton* button : window_->mainToolBar()->findChildren<QToolButton*>())
      if (button->defaultAction() && !button->defaultAction()->shortcut().isEmpty())
        QVERIFY(button->toolTip().contains(
            button->defaultAction()->shortcut().toString(QKeySequence::NativeText)));
    // A text that changes keeps the shortcut (Run becomes Pause).
    window_->sessionActions().run_pause->setText("Pause");
    QCOMPARE(window_->sessionActions().run_pause->toolTip(), QString("Pause (Space)"));
    QVERIFY(controller_->arrangeNextAction()->toolTip().endsWith(" (Ctrl+N)"));

    // Help › Keyboard shortcuts: one row per action, its shortcut read from the action.
    QAction* help_shortcuts = nullptr;
    QAction* help_about = nullptr;
    for (QAction* action : actions) {
      if (action->text() == "&Keyboard shortcuts") help_shortcuts = action;
      if (action->text() == "&About garment-studio") help_about = action;
    }
    QVERIFY(help_shortcuts && help_about);
    QCOMPARE(help_shortcuts->shortcut(), QKeySequence(QKeySequence::HelpContents));
    auto rows = [](QDialog* dialog) {
      auto* table = dialog->findChild<QTableWidget*>("shortcuts_table");
      std::map<QString, QString> by_shortcut;  // shortcut → action
      for (int row = 0; table && row < table->rowCount(); ++row)
        if (!table->item(row, 0)->text().isEmpty())
          by_shortcut[table->item(row, 0)->text()] = table->item(row, 1)->text();
      return std::make_pair(table ? table->rowCount() : -1, by_shortcut);
    };
    help_shortcuts->trigger();
    auto* dialog = window_->findChild<QDialog*>("shortcuts_dialog");
    QVERIFY(dialog && dialog->isVisible());
    auto [row_count, listed] = rows(dialog);
    QCOMPARE(row_count, static_cast<int>(actions.size()));
    QCOMPARE(static_cast<int>(listed.size()), with_shortcut);
    QCOMPARE(listed["Space"], QString("Pause"));
    QVERIFY(listed["Ctrl+Z"].startsWith("Undo"));
    QCOMPARE(listed["Ctrl+Shift+Z"].left(4), QString("Redo"));
    QCOMPARE(listed["F10"], QString("Step one phase"));
    QCOMPARE(listed["Ctrl+N"], QString("Arrange selected next"));
    QCOMPARE(listed["M"], window_->avatarViewActions().markers->text().remove('&'));
    QCOMPARE(listed["F1"], QString("Keyboard shortcuts"));
    dialog->close();
    QTest::qWait(0);  // the dialog deletes itself on close
    // An action added later is listed the next time, and its tooltip gives its shortcut.
    QAction* added = window_->editMenu()->addAction("Added later");
    added->setShortcut(QKeySequence("Ctrl+Alt+K"));
    dialog = window_->showShortcuts();
    QCOMPARE(rows(dialog).second["Ctrl+Alt+K"], QString("Added later"));
    dialog->close();

    // Help › About: name, version, the paper, the data's licences.
    help_about->trigger();
    auto* about = window_->findChild<QDialog*>("about_dialog");
    QVERIFY(about && about->isVisible());
    const QString text = about->findChild<QLabel*>("about_text")->text();
    for (const char* part : {"garment-studio 0.1.0", "Liu, Xu, Yang, Wang, SIGGRAPH 2024",
                             "MIT licence", "Maria Korosteleva", "GarmentCodeData"})
      QVERIFY2(text.contains(part), part);
    about->close();
  }
};

GARMENT_UI_TEST_MAIN(StudioMarkersTest)
#include "test_studio_markers.moc"
