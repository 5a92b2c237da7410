#pragma once
// The View menu's entries for the 3D view: the diagnostic overlays, the display (wireframe, body,
// markers), the four side views and framing the selection. Each shows its shortcut in its tooltip;
// each has an object name (view_overlay_strain, view_body_see_through, …) by which scripts find it
// (garment-studio --actions).

#include <QKeySequence>

#include "ui/avatar_view.h"

class QAction;
class QMenu;

namespace garment::ui {

struct AvatarViewActions {
  // Checkable, indexed by AvatarView::Overlay: F2 strain, F3 penetrations, F4 seams, F5 folds,
  // F6 batch in progress.
  QAction* overlays[AvatarView::kOverlayCount] = {};
  QAction* wireframe = nullptr;  // W
  // Exclusive: B shown, Shift+B see-through, Ctrl+B hidden.
  QAction* body_shown = nullptr;
  QAction* body_see_through = nullptr;
  QAction* body_hidden = nullptr;
  QAction* markers = nullptr;  // M
  // As Blender's numeric keypad: 1 front, Ctrl+1 back, 3 right, Ctrl+3 left.
  QAction* view_front = nullptr;
  QAction* view_back = nullptr;
  QAction* view_right = nullptr;
  QAction* view_left = nullptr;
  QAction* frame_selected = nullptr;  // Shift+F
};

// Adds the actions to `menu`, acting on `view`, checked as the view is set now.
AvatarViewActions add_avatar_view_actions(QMenu* menu, AvatarView* view);

}  // namespace garment::ui
