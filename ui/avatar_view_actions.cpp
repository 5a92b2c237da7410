#include "ui/avatar_view_actions.h"

#include <QAction>
#include <QActionGroup>
#include <QMenu>

namespace garment::ui {

namespace {

// An entry of `menu` with a shortcut that its tooltip repeats.
QAction* add_action(QMenu* menu, const QString& text, const QString& name,
                    const QKeySequence& shortcut) {
  QAction* action = menu->addAction(text);
  action->setObjectName(name);
  action->setShortcut(shortcut);
  action->setToolTip(QString("%1 (%2)").arg(QString(text).remove('&'),
                                            shortcut.toString(QKeySequence::NativeText)));
  return action;
}

QAction* add_toggle(QMenu* menu, const QString& text, const QString& name,
                    const QKeySequence& shortcut, bool checked) {
  QAction* action = add_action(menu, text, name, shortcut);
  action->setCheckable(true);
  action->setChecked(checked);
  return action;
}

}  // namespace

AvatarViewActions add_avatar_view_actions(QMenu* menu, AvatarView* view) {
  AvatarViewActions actions;
  menu->setToolTipsVisible(true);
  QMenu* overlays = menu->addMenu(QObject::tr("3D &overlays"));
  overlays->setToolTipsVisible(true);
  const struct {
    AvatarView::Overlay overlay;
    const char* text;
    const char* name;
    Qt::Key key;
  } overlay_entries[] = {
      {AvatarView::Overlay::Strain, "&Strain map", "view_overlay_strain", Qt::Key_F2},
      {AvatarView::Overlay::Penetration, "&Penetrations (body and cloth)",
       "view_overlay_penetration", Qt::Key_F3},
      {AvatarView::Overlay::Seams, "S&eams by gap", "view_overlay_seams", Qt::Key_F4},
      {AvatarView::Overlay::Folds, "&Folds", "view_overlay_folds", Qt::Key_F5},
      {AvatarView::Overlay::Batch, "&Batch in progress", "view_overlay_batch", Qt::Key_F6},
  };
  for (const auto& entry : overlay_entries) {
    QAction* action = add_toggle(overlays, QObject::tr(entry.text), entry.name,
                                 QKeySequence(entry.key), view->overlay(entry.overlay));
    QObject::connect(action, &QAction::toggled, view,
                     [view, overlay = entry.overlay](bool on) { view->setOverlay(overlay, on); });
    actions.overlays[static_cast<int>(entry.overlay)] = action;
  }

  QMenu* display = menu->addMenu(QObject::tr("3D &display"));
  display->setToolTipsVisible(true);
  actions.wireframe = add_toggle(display, QObject::tr("&Wireframe"), "view_wireframe",
                                 QKeySequence(Qt::Key_W), view->wireframe());
  QObject::connect(actions.wireframe, &QAction::toggled, view, &AvatarView::setWireframe);
  display->addSeparator();
  auto* body_group = new QActionGroup(display);
  const auto add_body = [&](const QString& text, const QString& name, const QKeySequence& key,
                            AvatarView::BodyDisplay mode) {
    QAction* action = add_toggle(display, text, name, key, view->bodyDisplay() == mode);
    body_group->addAction(action);
    QObject::connect(action, &QAction::triggered, view,
                     [view, mode] { view->setBodyDisplay(mode); });
    return action;
  };
  actions.body_shown = add_body(QObject::tr("&Body shown"), "view_body_shown",
                                QKeySequence(Qt::Key_B), AvatarView::BodyDisplay::Shown);
  actions.body_see_through =
      add_body(QObject::tr("Body &see-through"), "view_body_see_through",
               QKeySequence(Qt::SHIFT | Qt::Key_B), AvatarView::BodyDisplay::SeeThrough);
  actions.body_hidden =
      add_body(QObject::tr("Body &hidden"), "view_body_hidden", QKeySequence(Qt::CTRL | Qt::Key_B),
               AvatarView::BodyDisplay::Hidden);
  display->addSeparator();
  actions.markers = add_toggle(display, QObject::tr("Body location &markers"), "view_markers",
                               QKeySequence(Qt::Key_M), view->markersShown());
  QObject::connect(actions.markers, &QAction::toggled, view, &AvatarView::setMarkersShown);

  QMenu* camera = menu->addMenu(QObject::tr("3D &camera"));
  camera->setToolTipsVisible(true);
  const auto add_side = [&](const QString& text, const QString& name, const QKeySequence& key,
                            AvatarView::Side side) {
    QAction* action = add_action(camera, text, name, key);
    QObject::connect(action, &QAction::triggered, view, [view, side] { view->viewFrom(side); });
    return action;
  };
  actions.view_front = add_side(QObject::tr("&Front"), "view_front", QKeySequence(Qt::Key_1),
                                AvatarView::Side::Front);
  actions.view_back = add_side(QObject::tr("&Back"), "view_back",
                               QKeySequence(Qt::CTRL | Qt::Key_1), AvatarView::Side::Back);
  actions.view_right = add_side(QObject::tr("&Right"), "view_right", QKeySequence(Qt::Key_3),
                                AvatarView::Side::Right);
  actions.view_left = add_side(QObject::tr("&Left"), "view_left",
                               QKeySequence(Qt::CTRL | Qt::Key_3), AvatarView::Side::Left);
  camera->addSeparator();
  actions.frame_selected = add_action(camera, QObject::tr("Frame &selected"), "view_frame_selected",
                                      QKeySequence(Qt::SHIFT | Qt::Key_F));
  QObject::connect(actions.frame_selected, &QAction::triggered, view, &AvatarView::frameSelected);
  return actions;
}

}  // namespace garment::ui
