#include "ui/main_window.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QHeaderView>
#include <QListWidget>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QSettings>
#include <QSplitter>
#include <QTableView>
#include <QToolBar>
#include <exception>

#include "engine/body/default_body.h"
#include "engine/pattern/outfit.h"
#include "engine/pattern/pattern.h"
#include "engine/quality/flat_placement.h"
#include "ui/arrangement_order_list.h"
#include "ui/avatar_view.h"
#include "ui/bundled_resources.h"
#include "ui/help_dialogs.h"
#include "ui/outfit_layer_list.h"
#include "ui/pattern_view.h"
#include "ui/quality_panel.h"
#include "ui/recent_files.h"

namespace garment::ui {

namespace {

bool is_pattern_file(const QString& path) {
  return QFileInfo(path).suffix().compare("json", Qt::CaseInsensitive) == 0;
}

bool is_body_file(const QString& path) {
  return QFileInfo(path).suffix().compare("obj", Qt::CaseInsensitive) == 0;
}

QStringList dropped_files(const QMimeData* data) {
  QStringList files;
  for (const QUrl& url : data->urls())
    if (url.isLocalFile() &&
        (is_pattern_file(url.toLocalFile()) || is_body_file(url.toLocalFile())))
      files << url.toLocalFile();
  return files;
}

// Loading a pattern meshes it, which takes a moment on large patterns.
class BusyCursor {
 public:
  BusyCursor() { QApplication::setOverrideCursor(Qt::WaitCursor); }
  ~BusyCursor() { QApplication::restoreOverrideCursor(); }
  BusyCursor(const BusyCursor&) = delete;
  BusyCursor& operator=(const BusyCursor&) = delete;
};

}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
  setObjectName("main_window");
  pattern_view_ = new PatternView(this);
  avatar_view_ = new AvatarView(this);
  splitter_ = new QSplitter(Qt::Horizontal, this);
  splitter_->setObjectName("views");
  splitter_->addWidget(pattern_view_);
  splitter_->addWidget(avatar_view_);
  splitter_->setStretchFactor(0, 1);
  splitter_->setStretchFactor(1, 1);
  splitter_->setChildrenCollapsible(false);
  setCentralWidget(splitter_);

  status_bar_ = new ArrangementStatusBar(this);
  setStatusBar(status_bar_);
  // Before the docks: the Outfit dock carries it as a button too.
  add_garment_ = new QAction(tr("&Add garment…"), this);
  add_garment_->setShortcut(QKeySequence(tr("Ctrl+Shift+A")));
  add_garment_->setToolTip(tr("Add a garment worn over the ones open"));
  add_garment_->setEnabled(false);
  connect(add_garment_, &QAction::triggered, this, [this] {
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Add garment"),
        QFileInfo(layers_.empty() ? QString() : layers_.back().path).absolutePath(),
        tr("GarmentCode patterns (*.json)"));
    if (!path.isEmpty()) addGarment(path);
  });
  createDocks();
  createActions();
  setAcceptDrops(true);

  connect(pattern_view_, &PatternView::pieceSelectionChanged, this, [this](const QList<int>& p) {
    avatar_view_->setSelectedPieces(p);
    Q_EMIT pieceSelectionChanged(p);
  });
  connect(avatar_view_, &AvatarView::pieceSelectionChanged, this, [this](const QList<int>& p) {
    pattern_view_->setSelectedPieces(p);
    Q_EMIT pieceSelectionChanged(p);
  });
  // A marker clicked is the location chosen in the list (which highlights it and tells others).
  connect(avatar_view_, &AvatarView::locationClicked, location_list_,
          [this](int location) { location_list_->setCurrentRow(location); });
  connect(avatar_view_, &AvatarView::piecesDroppedOnLocation, this,
          [this](const QList<int>& pieces, int location) {
            selectPieces(pieces);
            Q_EMIT pieceSelectionChanged(selectedPieces());
            location_list_->setCurrentRow(location);
            Q_EMIT seedDropped(selectedPieces(), location);
          });

  error_presenter_ = [this](const QString& title, const QString& message) {
    QMessageBox::critical(this, title, message);
  };
  resize(1440, 900);
  splitter_->setSizes({500, 600});
  restoreSettings();
  updateTitle();
}

void MainWindow::createDocks() {
  setDockNestingEnabled(true);
  auto add_dock = [this](const QString& title, const QString& name, QWidget* widget) {
    auto* dock = new QDockWidget(title, this);
    dock->setObjectName(name);
    dock->setWidget(widget);
    addDockWidget(Qt::RightDockWidgetArea, dock);
    return dock;
  };

  classifier_model_ = new ClassifierTableModel(this);
  classifier_table_ = new QTableView(this);
  classifier_table_->setModel(classifier_model_);
  classifier_table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  classifier_table_->verticalHeader()->hide();
  classifier_table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  add_dock(tr("Seeding classifier"), "classifier_dock", classifier_table_);

  location_list_ = new QListWidget(this);
  location_list_->setSelectionMode(QAbstractItemView::SingleSelection);
  connect(location_list_, &QListWidget::currentRowChanged, this, [this](int row) {
    avatar_view_->setHighlightedLocation(row);
    Q_EMIT bodyLocationSelected(row);
  });
  add_dock(tr("Body locations"), "locations_dock", location_list_);

  order_list_ = new ArrangementOrderList(this);
  connect(order_list_, &ArrangementOrderList::orderChanged, this,
          &MainWindow::arrangementOrderChanged);
  add_dock(tr("Arrangement order"), "order_dock", order_list_);

  outfit_list_ = new OutfitLayerList(add_garment_, this);
  connect(outfit_list_, &OutfitLayerList::orderChanged, this, &MainWindow::setOutfitOrder);
  connect(outfit_list_, &OutfitLayerList::removeRequested, this, &MainWindow::removeGarment);
  add_dock(tr("Outfit"), "outfit_dock", outfit_list_);

  quality_panel_ = new QualityPanel(this);
  connect(quality_panel_, &QualityPanel::piecesChosen, this, [this](const QList<int>& pieces) {
    selectPieces(pieces);
    Q_EMIT pieceSelectionChanged(selectedPieces());
  });
  add_dock(tr("Quality"), "quality_dock", quality_panel_);
}

void MainWindow::createActions() {
  QMenu* file_menu = menuBar()->addMenu(tr("&File"));
  QAction* open_pattern = file_menu->addAction(tr("Open &pattern…"), this, [this] {
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Open pattern"),
        QFileInfo(layers_.empty() ? QString() : layers_.front().path).absolutePath(),
        tr("GarmentCode patterns (*.json)"));
    if (!path.isEmpty()) openPattern(path);
  });
  open_pattern->setShortcut(QKeySequence::Open);
  QAction* open_body = file_menu->addAction(tr("Open &body…"), this, [this] {
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Open body"), QFileInfo(body_path_).absolutePath(), tr("Body meshes (*.obj)"));
    if (!path.isEmpty()) openBody(path);
  });
  open_body->setShortcut(QKeySequence(tr("Ctrl+Shift+O")));
  file_menu->addAction(add_garment_);
  recent_menu_ = file_menu->addMenu(tr("Open &recent"));
  connect(recent_menu_, &QMenu::aboutToShow, this, &MainWindow::rebuildRecentFilesMenu);
  rebuildRecentFilesMenu();
  file_menu->addSeparator();

  // Export needs the arranged garment (the session) and the writers (engine/io): disabled until
  // the session integration connects them.
  session_actions_.export_obj = file_menu->addAction(tr("Export &OBJ…"));
  session_actions_.export_obj->setShortcut(QKeySequence(tr("Ctrl+E")));
  session_actions_.export_glb = file_menu->addAction(tr("Export &GLB…"));
  session_actions_.export_report = file_menu->addAction(tr("Export quality &report…"));
  QMenu* simulators = file_menu->addMenu(tr("Export for &simulators"));
  session_actions_.export_sewn_obj = simulators->addAction(tr("&Sewn OBJ (one mesh, UVs)…"));
  session_actions_.export_sewn_glb = simulators->addAction(tr("Sewn &GLB (one mesh)…"));
  session_actions_.export_sewing_obj =
      simulators->addAction(tr("OBJ with sewing &lines (Blender cloth)…"));
  file_menu->addSeparator();
  QAction* quit = file_menu->addAction(tr("&Quit"), this, &QWidget::close);
  quit->setShortcut(QKeySequence::Quit);
  edit_menu_ = menuBar()->addMenu(tr("&Edit"));

  view_menu_ = menuBar()->addMenu(tr("&View"));
  QAction* frame_all = view_menu_->addAction(tr("&Frame all"), this, [this] {
    pattern_view_->frameAll();
    avatar_view_->frameAll();
  });
  frame_all->setShortcut(QKeySequence(Qt::Key_F));
  frame_all->setToolTip(tr("Frame all (F)"));
  avatar_view_actions_ = add_avatar_view_actions(view_menu_, avatar_view_);
  view_menu_->addSeparator();
  for (QDockWidget* dock : findChildren<QDockWidget*>())
    view_menu_->addAction(dock->toggleViewAction());

  QMenu* arrange_menu = menuBar()->addMenu(tr("&Arrangement"));
  arrange_menu_ = arrange_menu;
  session_actions_.run_pause = arrange_menu->addAction(tr("&Run / pause"));
  session_actions_.run_pause->setShortcut(QKeySequence(Qt::Key_Space));
  session_actions_.step = arrange_menu->addAction(tr("&Step one phase"));
  session_actions_.step->setShortcut(QKeySequence(Qt::Key_F10));
  session_actions_.stop = arrange_menu->addAction(tr("S&top"));
  session_actions_.stop->setShortcut(QKeySequence(Qt::Key_Escape));
  session_actions_.reset = arrange_menu->addAction(tr("R&eset"));
  session_actions_.reset->setShortcut(QKeySequence(tr("Ctrl+R")));

  for (QAction* action :
       {session_actions_.run_pause, session_actions_.step, session_actions_.stop,
        session_actions_.reset, session_actions_.export_obj, session_actions_.export_glb,
        session_actions_.export_report, session_actions_.export_sewn_obj,
        session_actions_.export_sewn_glb, session_actions_.export_sewing_obj})
    action->setEnabled(false);

  QToolBar* toolbar = addToolBar(tr("Main"));
  toolbar_ = toolbar;
  toolbar->setObjectName("main_toolbar");
  toolbar->addAction(open_pattern);
  toolbar->addAction(open_body);
  toolbar->addSeparator();
  toolbar->addAction(session_actions_.run_pause);
  toolbar->addAction(session_actions_.step);
  toolbar->addAction(session_actions_.stop);
  toolbar->addAction(session_actions_.reset);
  toolbar->addSeparator();
  toolbar->addAction(frame_all);
  createHelpMenu();
}

void MainWindow::createHelpMenu() {
  QMenu* help = menuBar()->addMenu(tr("&Help"));
  help->addAction(tr("&Keyboard shortcuts"), this, &MainWindow::showShortcuts)
      ->setShortcut(QKeySequence::HelpContents);
  help->addAction(tr("&About garment-studio"), this, &MainWindow::showAbout);
}

QDialog* MainWindow::showShortcuts() {
  QDialog* dialog = create_shortcuts_dialog(this);
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  dialog->show();
  return dialog;
}

QDialog* MainWindow::showAbout() {
  QDialog* dialog = create_about_dialog(this);
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  dialog->show();
  return dialog;
}

void MainWindow::showEvent(QShowEvent* event) {
  // By now the session integration has added its actions too.
  show_shortcuts_in_tooltips(window_actions(this));
  QMainWindow::showEvent(event);
}

void MainWindow::rebuildRecentFilesMenu() {
  recent_menu_->clear();
  const QStringList paths = RecentFiles::load();
  for (const QString& path : paths)
    recent_menu_->addAction(QFileInfo(path).fileName() + "   " + QFileInfo(path).absolutePath(),
                            this, [this, path] { openRecent(path); });
  if (!paths.isEmpty()) recent_menu_->addSeparator();
  QAction* clear = recent_menu_->addAction(tr("Clear"), this, [] { RecentFiles::clear(); });
  clear->setEnabled(!paths.isEmpty());
}

void MainWindow::openRecent(const QString& path) {
  if (!QFileInfo::exists(path)) {
    RecentFiles::remove(path);
    presentError(tr("Cannot open recent file"), tr("%1: the file no longer exists").arg(path));
    return;
  }
  if (is_body_file(path))
    openBody(path);
  else
    openPattern(path);
}

void MainWindow::setErrorPresenter(ErrorPresenter presenter) {
  error_presenter_ = std::move(presenter);
}

void MainWindow::showError(const QString& title, const QString& message) {
  presentError(title, message);
}

QDockWidget* MainWindow::addPanel(const QString& title, const QString& name, QWidget* widget) {
  auto* dock = new QDockWidget(title, this);
  dock->setObjectName(name);
  dock->setWidget(widget);
  addDockWidget(Qt::RightDockWidgetArea, dock);
  view_menu_->addAction(dock->toggleViewAction());
  return dock;
}

void MainWindow::restoreDockLayout() {
  restoreState(QSettings().value("window/state").toByteArray());
}

void MainWindow::presentError(const QString& title, const QString& message) {
  if (error_presenter_) error_presenter_(title, message);
}

bool MainWindow::openPattern(const QString& path) {
  return openPatternFile(path, true);
}

bool MainWindow::openDemoPattern() {
  return openPatternFile(demo_pattern_path(), false);
}

bool MainWindow::openDefaultBody() {
  return openBodyFile(QString::fromStdString(default_body_path().string()), false);
}

bool MainWindow::openPatternFile(const QString& path, bool remember) {
  std::vector<OutfitLayer> layers(1);
  try {
    layers.front() = {path, load_pattern(path.toStdString())};
  } catch (const std::exception& error) {
    presentError(tr("Cannot open pattern"), QString::fromStdString(error.what()));
    return false;
  }
  if (!showOutfit(std::move(layers), tr("Cannot open pattern"))) return false;
  // A location chosen for the old pattern's seed: it would seed the new one where nobody chose to.
  location_list_->setCurrentRow(-1);
  if (remember) RecentFiles::add(path);
  return true;
}

bool MainWindow::addGarment(const QString& path) {
  std::vector<OutfitLayer> layers = layers_;
  try {
    layers.push_back({path, load_pattern(path.toStdString())});
  } catch (const std::exception& error) {
    presentError(tr("Cannot add garment"), QString::fromStdString(error.what()));
    return false;
  }
  return showOutfit(std::move(layers), tr("Cannot add garment"));
}

void MainWindow::setOutfitOrder(const QList<int>& order) {
  if (order.size() != static_cast<int>(layers_.size())) return;
  std::vector<OutfitLayer> layers;
  for (int layer : order)
    layers.push_back(layers_[static_cast<std::size_t>(layer)]);
  showOutfit(std::move(layers), tr("Cannot reorder the outfit"));
}

void MainWindow::removeGarment(int layer) {
  if (layer < 0 || layer >= static_cast<int>(layers_.size()) || layers_.size() < 2) return;
  std::vector<OutfitLayer> layers = layers_;
  layers.erase(layers.begin() + layer);
  showOutfit(std::move(layers), tr("Cannot remove the garment"));
}

std::vector<Pattern> MainWindow::outfitPatterns() const {
  return patternsOf(layers_);
}

std::vector<std::string> MainWindow::outfitNames() const {
  return namesOf(layers_);
}

std::vector<Pattern> MainWindow::patternsOf(const std::vector<OutfitLayer>& layers) {
  std::vector<Pattern> patterns;
  for (const OutfitLayer& layer : layers)
    patterns.push_back(layer.pattern);
  return patterns;
}

std::vector<std::string> MainWindow::namesOf(const std::vector<OutfitLayer>& layers) {
  std::vector<std::string> names;
  for (const OutfitLayer& layer : layers)
    names.push_back(outfit_garment_name(layer.path.toStdString()));
  return names;
}

bool MainWindow::showOutfit(std::vector<OutfitLayer> layers, const QString& error_title) {
  std::shared_ptr<const Garment> garment;
  std::optional<RegionGarments> quilt;
  const std::vector<std::string> names = namesOf(layers);
  try {
    BusyCursor busy;
    // One pattern keeps its panels' own names; an outfit's are GARMENT:PANEL. A quilt is shown and
    // arranged as its regions, as `garment-init run` arranges it.
    const std::vector<Pattern> patterns = patternsOf(layers);
    if (patterns.size() == 1) quilt = mesh_region_garments(patterns.front());
    garment = quilt
                  ? quilt->region_garment
                  : std::make_shared<const Garment>(build_garment(
                        patterns.size() == 1 ? patterns.front() : merge_patterns(patterns, names)));
  } catch (const std::exception& error) {
    presentError(error_title, QString::fromStdString(error.what()));
    return false;
  }
  garment_ = garment;
  quilt_ = std::move(quilt);
  layers_ = std::move(layers);
  pattern_view_->setGarment(garment_);
  if (quilt_) pattern_view_->setQuiltCells(*quilt_);
  avatar_view_->setGarment(garment_);
  classifier_model_->setClassifications({}, {});
  clearArrangement();
  QStringList layer_names;
  for (const std::string& name : names)
    layer_names << QString::fromStdString(name);
  outfit_list_->setLayers(layer_names);
  add_garment_->setEnabled(true);
  updateTitle();
  Q_EMIT garmentOpened(garment_);
  return true;
}

bool MainWindow::openBody(const QString& path) {
  return openBodyFile(path, true);
}

bool MainWindow::openBodyFile(const QString& path, bool remember) {
  std::shared_ptr<const Body> body;
  try {
    BusyCursor busy;
    // The whole body (signed distance field included, cached on disk after the first load), so
    // that an arrangement can start from it.
    body = std::make_shared<const Body>(load_body(path.toStdString()));
  } catch (const std::exception& error) {
    presentError(tr("Cannot open body"), QString::fromStdString(error.what()));
    return false;
  }
  body_ = body;
  body_path_ = path;
  avatar_view_->setBody(std::shared_ptr<const BodyMesh>(body_, &body_->mesh));
  setBodyLocations(body_location_markers(body_->locations));
  // The arrangement shown was of the garment on the body before.
  clearArrangement();
  if (remember) RecentFiles::add(path);
  updateTitle();
  Q_EMIT bodyOpened(body_);
  return true;
}

void MainWindow::updateTitle() {
  QStringList parts;
  QStringList patterns;
  for (const OutfitLayer& layer : layers_)
    patterns << QFileInfo(layer.path).fileName();
  if (!patterns.isEmpty()) parts << patterns.join(tr(" + "));
  // A quilt says what the views show: its regions, not its pieces.
  if (quilt_)
    parts.back() += tr(" (%1 pieces sewn flat into %2 regions)")
                        .arg(quilt_->pieces->pieces.size())
                        .arg(quilt_->region_garment->pieces.size());
  if (!body_path_.isEmpty()) parts << QFileInfo(body_path_).fileName();
  setWindowTitle(parts.isEmpty() ? tr("garment-studio")
                                 : tr("%1 — garment-studio").arg(parts.join(tr(" on "))));
}

void MainWindow::setPieceStates(const std::vector<PieceState>& states) {
  pattern_view_->setPieceStates(states);
  avatar_view_->setPieceStates(states);
}

void MainWindow::setGarmentPositions(std::shared_ptr<const Eigen::MatrixX3d> positions) {
  avatar_view_->setGarmentPositions(std::move(positions));
}

void MainWindow::setClassifications(const QStringList& class_names,
                                    std::vector<PieceClassification> rows) {
  classifier_model_->setClassifications(class_names, std::move(rows));
}

void MainWindow::setBodyLocations(std::vector<BodyLocationMarker> locations) {
  const QSignalBlocker blocker(location_list_);
  location_list_->clear();
  for (const BodyLocationMarker& location : locations)
    location_list_->addItem(QString::fromStdString(location.name));
  avatar_view_->setBodyLocations(std::move(locations));
  avatar_view_->setHighlightedLocation(-1);
}

void MainWindow::setArrangementOrder(const std::vector<int>& pieces) {
  QStringList names;
  if (garment_)
    for (const Piece& piece : garment_->pieces)
      names << QString::fromStdString(piece.name);
  order_list_->setOrder(pieces, names);
}

void MainWindow::setArrangementStatus(const ArrangementStatus& status) {
  status_bar_->setStatus(status);
}

void MainWindow::setQualityVerdict(const std::optional<QualityVerdict>& verdict,
                                   const QStringList& piece_names,
                                   const std::optional<CannotFit>& cannot_fit) {
  quality_panel_->setVerdict(verdict, piece_names, cannot_fit);
}

void MainWindow::clearArrangement() {
  if (garment_) {
    // Until an arrangement runs, the 3D view shows the pieces where the file puts them (on the
    // pattern's own mesh, whatever mesh a fix arranged).
    avatar_view_->setGarment(garment_);
    avatar_view_->setGarmentPositions(
        std::make_shared<const Eigen::MatrixX3d>(flat_placement(*garment_)));
    setPieceStates({});
  }
  order_list_->clear();
  status_bar_->setStatus({});
  setQualityVerdict(std::nullopt, {});
  quality_panel_->setAttempts({}, -1, false);
  outfit_list_->setCrossingsBetweenGarments({});
}

void MainWindow::selectPieces(const QList<int>& pieces) {
  pattern_view_->setSelectedPieces(pieces);
  avatar_view_->setSelectedPieces(pattern_view_->selectedPieces());
}

QList<int> MainWindow::selectedPieces() const {
  return pattern_view_->selectedPieces();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
  if (!dropped_files(event->mimeData()).isEmpty())
    event->acceptProposedAction();
  else
    event->ignore();
}

void MainWindow::dropEvent(QDropEvent* event) {
  const QStringList files = dropped_files(event->mimeData());
  if (files.isEmpty()) {
    event->ignore();
    return;
  }
  event->acceptProposedAction();
  for (const QString& file : files) {
    if (is_pattern_file(file))
      openPattern(file);
    else
      openBody(file);
  }
}

void MainWindow::restoreSettings() {
  QSettings settings;
  restoreGeometry(settings.value("window/geometry").toByteArray());
  restoreState(settings.value("window/state").toByteArray());
  splitter_->restoreState(settings.value("window/splitter").toByteArray());
}

void MainWindow::saveSettings() const {
  QSettings settings;
  settings.setValue("window/geometry", saveGeometry());
  settings.setValue("window/state", saveState());
  settings.setValue("window/splitter", splitter_->saveState());
}

void MainWindow::closeEvent(QCloseEvent* event) {
  saveSettings();
  QMainWindow::closeEvent(event);
}

}  // namespace garment::ui
