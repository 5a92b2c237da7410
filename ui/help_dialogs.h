#pragma once
// The Help menu's dialogs and the shortcuts in tooltips. Both read the window's actions at the time
// they are asked for, so a shortcut added or changed anywhere shows in them without a list to
// keep up to date.

#include <QList>
#include <QString>

class QAction;
class QDialog;
class QMainWindow;
class QWidget;

namespace garment::ui {

// Every action of the window's menus (submenus included) and toolbars, once each, in menu order;
// no separators and no submenu entries.
QList<QAction*> window_actions(const QMainWindow* window);

// Keeps "(shortcut)" at the end of each action's tooltip, also when its text or shortcut changes
// later (Run becomes Pause); an action's own tooltip is kept and the shortcut appended to it.
void show_shortcuts_in_tooltips(const QList<QAction*>& actions);

// A dialog (object name shortcuts_dialog) whose table (shortcuts_table) lists every action of the
// window with its shortcut and menu, those with a shortcut first.
QDialog* create_shortcuts_dialog(QMainWindow* window);

// The About text: name, version, the paper, and the licences of the bundled data (resources/).
QString about_text();
// A dialog (object name about_dialog) showing about_text().
QDialog* create_about_dialog(QWidget* parent);

}  // namespace garment::ui
