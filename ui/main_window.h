#pragma once
// The garment-studio main window: the pattern view and the avatar view side by side in a splitter,
// docks for the classifier's verdict, the body locations, the arrangement order and the garment's
// quality, and a status bar for the arrangement's progress. Opens patterns and bodies (menus,
// recent files, drag and drop); a file that fails to open is reported and leaves what is open
// untouched. Several patterns open at once are an outfit (File › Add garment…, the Outfit dock):
// garment() is then all their pieces as one garment, named GARMENT:PANEL (pattern/outfit.h).
//
// The arrangement session plugs in from outside through plain data: the set* functions below take
// what a session snapshot holds, the signals carry what the user asked for, and sessionActions()
// are the Run/Pause, Step, Stop, Reset and export actions, disabled until something connects them.
// Call everything on the GUI thread.

#include <QList>
#include <QMainWindow>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "engine/body/body.h"
#include "engine/pattern/garment_mesh.h"
#include "engine/pattern/pattern.h"
#include "engine/quality/verdict.h"
#include "engine/recovery/cannot_fit.h"
#include "engine/seeding/scene.h"
#include "ui/arrangement_status_bar.h"
#include "ui/avatar_view_actions.h"
#include "ui/body_location_marker.h"
#include "ui/classifier_table_model.h"
#include "ui/piece_state.h"

class QAction;
class QDialog;
class QDockWidget;
class QToolBar;
class QListWidget;
class QMenu;
class QSplitter;
class QTableView;

namespace garment::ui {

class ArrangementOrderList;
class AvatarView;
class OutfitLayerList;
class PatternView;
class QualityPanel;

// Actions the session integration connects and enables.
struct SessionActions {
  QAction* run_pause = nullptr;  // Space
  QAction* step = nullptr;       // F10: one phase
  QAction* stop = nullptr;       // Esc
  QAction* reset = nullptr;      // Ctrl+R
  QAction* export_obj = nullptr;
  QAction* export_glb = nullptr;
  QAction* export_report = nullptr;
  // File › Export for simulators: sewn OBJ, sewn GLB, OBJ with sewing lines.
  QAction* export_sewn_obj = nullptr;
  QAction* export_sewn_glb = nullptr;
  QAction* export_sewing_obj = nullptr;
};

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  // Shows a failed file operation; the default is a modal QMessageBox.
  using ErrorPresenter = std::function<void(const QString& title, const QString& message)>;

  explicit MainWindow(QWidget* parent = nullptr);

  // Files. On failure the error is presented, false returned, and the open pattern and body stay.
  bool openPattern(const QString& path);
  bool openBody(const QString& path);
  // Outfits: a garment worn over the ones open (the outermost layer). On failure (a bad file, a
  // garment of the same name, other units) the error is presented and the outfit stays.
  bool addGarment(const QString& path);
  // The outfit's layers in a new order: order[i] is the layer (before the change) now at layer i.
  void setOutfitOrder(const QList<int>& order);
  void removeGarment(int layer);
  // The patterns open, innermost first, and their garments' names (outfit_garment_name).
  std::vector<Pattern> outfitPatterns() const;
  std::vector<std::string> outfitNames() const;
  // The bundled demo pattern and default body (resources/), not remembered among the recent
  // files.
  bool openDemoPattern();
  bool openDefaultBody();
  void setErrorPresenter(ErrorPresenter presenter);
  // Shows an error through the presenter (a dialog by default); changes nothing else.
  void showError(const QString& title, const QString& message);
  // A dock on the right, listed in the View menu (for the session's panels).
  QDockWidget* addPanel(const QString& title, const QString& name, QWidget* widget);
  // Restores the saved dock layout again, once panels added after construction exist.
  void restoreDockLayout();
  QMenu* arrangementMenu() const { return arrange_menu_; }
  QMenu* editMenu() const { return edit_menu_; }  // empty until the session integration fills it
  QToolBar* mainToolBar() const { return toolbar_; }

  std::shared_ptr<const Garment> garment() const { return garment_; }
  // A quilt's regions and pieces (seeding/scene.h), when the one pattern open is a quilt: garment()
  // is then its regions, the units the arrangement moves and the views show; the pieces are what
  // exports write and the verdict judges.
  const std::optional<RegionGarments>& quiltRegions() const { return quilt_; }
  // The body with its signed distance field and 15 locations.
  std::shared_ptr<const Body> body() const { return body_; }

  // What the arrangement shows.
  void setPieceStates(const std::vector<PieceState>& states);
  void setGarmentPositions(std::shared_ptr<const Eigen::MatrixX3d> positions);
  void setClassifications(const QStringList& class_names, std::vector<PieceClassification> rows);
  void setBodyLocations(std::vector<BodyLocationMarker> locations);
  void setArrangementOrder(const std::vector<int>& pieces);
  void setArrangementStatus(const ArrangementStatus& status);
  // The Quality panel's verdict (nullopt: nothing judged) and the design's misfit when it cannot
  // fit; piece_names in the verdict's garment's piece order. Opening a pattern or a body clears it,
  // and the status bar's verdict (and the arrangement shown: positions, piece states, order and
  // progress).
  void setQualityVerdict(const std::optional<QualityVerdict>& verdict,
                         const QStringList& piece_names,
                         const std::optional<CannotFit>& cannot_fit = std::nullopt);

  void selectPieces(const QList<int>& pieces);  // in both views; does not emit
  QList<int> selectedPieces() const;

  PatternView* patternView() const { return pattern_view_; }
  AvatarView* avatarView() const { return avatar_view_; }
  ArrangementOrderList* orderList() const { return order_list_; }
  QListWidget* locationList() const { return location_list_; }
  OutfitLayerList* outfitList() const { return outfit_list_; }
  QAction* addGarmentAction() const { return add_garment_; }
  ClassifierTableModel* classifierModel() const { return classifier_model_; }
  ArrangementStatusBar* arrangementStatusBar() const { return status_bar_; }
  QualityPanel* qualityPanel() const { return quality_panel_; }
  const SessionActions& sessionActions() const { return session_actions_; }
  const AvatarViewActions& avatarViewActions() const { return avatar_view_actions_; }
  QMenu* recentFilesMenu() const { return recent_menu_; }
  // Help menu: the dialogs it opens (non-modal, deleted on close).
  QDialog* showShortcuts();
  QDialog* showAbout();

 signals:
  void garmentOpened(std::shared_ptr<const garment::Garment> garment);
  void bodyOpened(std::shared_ptr<const garment::Body> body);
  // The user selected pieces in either view, or chose a failure in the Quality panel.
  void pieceSelectionChanged(const QList<int>& pieces);
  // The user chose a body location in the list or by clicking its marker (-1: none).
  void bodyLocationSelected(int location);
  // The user dropped pieces on a location's marker: both are chosen (as selectPieces and the
  // location list show) and the manual seed there is asked for.
  void seedDropped(const QList<int>& pieces, int location);
  // The user reordered the arrangement order list.
  void arrangementOrderChanged(const QList<int>& order);

 protected:
  void closeEvent(QCloseEvent* event) override;
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;
  void showEvent(QShowEvent* event) override;

 private:
  void createActions();
  void createDocks();
  void createHelpMenu();
  void rebuildRecentFilesMenu();
  void openRecent(const QString& path);
  bool openPatternFile(const QString& path, bool remember);
  bool openBodyFile(const QString& path, bool remember);
  // Shows these patterns as the open garment (an outfit when more than one) and tells the session;
  // on failure presents the error under `error_title` and changes nothing.
  struct OutfitLayer {
    QString path;
    Pattern pattern;
  };
  static std::vector<Pattern> patternsOf(const std::vector<OutfitLayer>& layers);
  static std::vector<std::string> namesOf(const std::vector<OutfitLayer>& layers);
  bool showOutfit(std::vector<OutfitLayer> layers, const QString& error_title);
  void presentError(const QString& title, const QString& message);
  // Shows no arrangement: the garment as its file lays it out, every piece waiting, no order,
  // progress or verdict.
  void clearArrangement();
  void updateTitle();
  void restoreSettings();
  void saveSettings() const;

  PatternView* pattern_view_ = nullptr;
  AvatarView* avatar_view_ = nullptr;
  QSplitter* splitter_ = nullptr;
  ClassifierTableModel* classifier_model_ = nullptr;
  QTableView* classifier_table_ = nullptr;
  QListWidget* location_list_ = nullptr;
  ArrangementOrderList* order_list_ = nullptr;
  QualityPanel* quality_panel_ = nullptr;
  OutfitLayerList* outfit_list_ = nullptr;
  QAction* add_garment_ = nullptr;
  ArrangementStatusBar* status_bar_ = nullptr;
  QMenu* recent_menu_ = nullptr;
  QMenu* view_menu_ = nullptr;
  QMenu* arrange_menu_ = nullptr;
  QMenu* edit_menu_ = nullptr;
  QToolBar* toolbar_ = nullptr;
  SessionActions session_actions_;
  AvatarViewActions avatar_view_actions_;
  ErrorPresenter error_presenter_;

  std::shared_ptr<const Garment> garment_;
  std::optional<RegionGarments> quilt_;
  std::shared_ptr<const Body> body_;
  std::vector<OutfitLayer> layers_;  // innermost first
  QString body_path_;
};

}  // namespace garment::ui
