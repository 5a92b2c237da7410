#pragma once
// The 3D avatar view (OpenGL 3.3 core, shaders from shaders/): the shaded body, the garment with an
// outside and an inside colour (a flipped piece shows the inside colour among outside-coloured
// neighbours), and the body locations as markers. Left drag orbits, middle or right drag or
// Shift+left drag pans, the wheel zooms towards the point under the cursor, frameAll() frames body
// and garment and frameSelected() the selected pieces; a click picks a piece (Ctrl or Shift adds to
// the selection) through an id buffer, so what is picked is what is visible. A click on a body
// location marker chooses that location instead, and pieces dragged from the pattern view (
// piece_drag.h) onto a marker ask for the manual seed there.
//
// Diagnostics drawn over the garment, each an Overlay toggled on its own, with a legend in the
// corner for those that are on: the strain map, vertices inside the body and edges crossing it or
// other cloth, seams as lines between their two sides coloured by gap, folds, and the batch in
// progress set apart from the waiting pieces. All but the batch come from the quality checker
// (GarmentChecker's diagnostics), measured off the GUI thread for the latest positions while one of
// them is on. Display: wireframe, the body shown / see-through / hidden, markers shown or hidden
// (hidden behind the body, as if on its surface where they lie inside a limb).
//
// Threads (DESIGN.md): call everything on the GUI thread. setGarmentPositions() only keeps the
// latest snapshot; it is uploaded at the next paint, so a worker may deliver snapshots (through a
// queued signal) faster than frames are drawn without work piling up.

#include <QColor>
#include <QList>
#include <QMatrix4x4>
#include <QOpenGLBuffer>
#include <QOpenGLFunctions_3_3_Core>
#include <QOpenGLVertexArrayObject>
#include <QOpenGLWidget>
#include <QVector3D>
#include <memory>
#include <vector>

#include "engine/body/body_mesh.h"
#include "engine/pattern/garment_mesh.h"
#include "engine/quality/garment_metrics.h"
#include "ui/body_location_marker.h"
#include "ui/colour_legend.h"
#include "ui/piece_state.h"

class QMimeData;
class QOpenGLFramebufferObject;
class QOpenGLShaderProgram;

namespace garment::ui {

class GarmentDiagnosticsWorker;

class AvatarView : public QOpenGLWidget, protected QOpenGLFunctions_3_3_Core {
  Q_OBJECT
 public:
  struct Colours {
    QColor background{38, 41, 46};
    QColor body{206, 192, 178};
    QColor outside{70, 130, 225};    // the garment's outside: blue
    QColor inside{240, 130, 40};     // its inside: orange
    QColor highlight{255, 225, 40};  // outline of selected pieces, and a tint of their surface
    QColor marker{40, 210, 220};
    QColor highlighted_marker{255, 40, 150};
    QColor wire{25, 28, 34};
    QColor inside_body{255, 30, 30};      // vertices inside the body, edges crossing it
    QColor cloth_crossing{230, 60, 255};  // edges crossing other cloth
    QColor fold{255, 255, 255};           // fold creases
    QColor seam_closed{60, 220, 90};      // seam pairs within the verdict's gap limit
    QColor seam_open{255, 60, 40};        // seam pairs kSeamGapFullScale apart or more
  };

  enum class Overlay { Strain, Penetration, Seams, Folds, Batch };
  static constexpr int kOverlayCount = 5;
  enum class BodyDisplay { Shown, SeeThrough, Hidden };
  // The four horizontal views, as a camera yaw (setOrbit).
  enum class Side { Front = 0, Left = 90, Back = 180, Right = 270 };

  // The strain map's scale: from no stretch to the verdict's limit (QualityThresholds), and the
  // seam colours' scale: from the verdict's gap limit to kSeamGapFullScale.
  static constexpr double kStrainFullScale = 0.20;
  static constexpr double kSeamGapLimit = 0.005, kSeamGapFullScale = 0.05;
  // The strain map's colour for a strain: blue at 0, green at a third of the full scale, yellow at
  // two thirds, red at the full scale and beyond.
  static QColor strainColour(double strain);

  explicit AvatarView(QWidget* parent = nullptr);
  ~AvatarView() override;

  void setColours(const Colours& colours);
  const Colours& colours() const { return colours_; }

  // The body (nullptr hides it). A new body reframes the view.
  void setBody(std::shared_ptr<const BodyMesh> body);
  // The garment's topology and pieces. The garment stays hidden until positions arrive.
  void setGarment(std::shared_ptr<const Garment> garment);
  const std::shared_ptr<const Garment>& garment() const { return garment_; }
  // #V×3 positions of every garment vertex (metres). Only the latest is kept and drawn at the next
  // paint; nullptr, or a matrix whose row count is not the garment's vertex count, hides the
  // garment.
  void setGarmentPositions(std::shared_ptr<const Eigen::MatrixX3d> positions);
  std::shared_ptr<const Eigen::MatrixX3d> garmentPositions() const { return positions_; }
  bool garmentShown() const;
  // Per piece; pieces past the end of the list are visible. Hidden pieces cannot be picked.
  void setPieceVisibility(std::vector<bool> visible);
  // Per piece, for the Batch overlay; pieces past the end of the list are arranged.
  void setPieceStates(std::vector<PieceState> states);

  void setOverlay(Overlay overlay, bool on);
  bool overlay(Overlay overlay) const { return overlays_[static_cast<int>(overlay)]; }
  // The checker's diagnostics of the positions shown (the Strain, Penetration, Seams and Folds
  // overlays draw them); ignored when their sizes do not fit the garment. Set by the view's own
  // worker while one of those overlays is on; tests may set them directly.
  void setDiagnostics(std::shared_ptr<const GarmentDiagnostics> diagnostics);
  std::shared_ptr<const GarmentDiagnostics> diagnostics() const { return diagnostics_; }
  // The worker measuring positions for the overlays (for waiting on its diagnosticsReady).
  GarmentDiagnosticsWorker* diagnosticsWorker() const { return worker_; }
  // Explains the colours of the overlays that are on; hidden when none is.
  ColourLegend* legend() const { return legend_; }

  void setWireframe(bool on);
  bool wireframe() const { return wireframe_; }
  void setBodyDisplay(BodyDisplay display);
  BodyDisplay bodyDisplay() const { return body_display_; }
  void setMarkersShown(bool shown);
  bool markersShown() const { return markers_shown_; }

  // Selects without emitting pieceSelectionChanged (for mirroring another view's selection).
  void setSelectedPieces(const QList<int>& pieces);
  QList<int> selectedPieces() const { return selected_; }

  void setBodyLocations(std::vector<BodyLocationMarker> locations);
  const std::vector<BodyLocationMarker>& bodyLocations() const { return locations_; }
  void setHighlightedLocation(int location);  // -1: none
  int highlightedLocation() const { return highlighted_location_; }

  // Camera direction around the target: yaw 0 looks at the body's front (from +z), 90 at its left
  // side (from +x); pitch > 0 looks from above.
  void setOrbit(double yaw_degrees, double pitch_degrees);
  double orbitYaw() const { return yaw_degrees_; }
  double orbitPitch() const { return pitch_degrees_; }
  // Looks at the target horizontally from one side.
  void viewFrom(Side side) { setOrbit(static_cast<double>(side), 0.0); }
  // Moves the camera towards (factor < 1) or away from the point under a widget position (the
  // surface drawn there, or the target's depth over the background), which stays where it is.
  void zoomAt(const QPointF& position, double factor);
  // A point of the scene (metres) in widget coordinates (logical pixels).
  QPointF projectToView(const Eigen::Vector3d& point) const;
  // The piece visible at a widget position, -1 for the body or the background.
  int pieceAt(const QPoint& position);
  // The shown marker within kMarkerPickPixels of a widget position, the nearest the camera when
  // several are (a front marker over its back twin); -1 for none.
  int locationAt(const QPointF& position) const;
  static constexpr double kMarkerPickPixels = 12.0;
  // What a drop does: pieces (piece_drag.h) dropped on a marker emit piecesDroppedOnLocation; true
  // when they were. dropEvent calls it; tests may call it with the drop's data and position.
  bool dropPieces(const QMimeData* data, const QPointF& position);
  // How many garment states were drawn (one per paint that uploaded new positions): the live
  // frame rate's numerator.
  int garmentFrameCount() const { return garment_frames_; }
  // False when OpenGL 3.3 core or the shaders are not available; the view then stays blank.
  bool renderingAvailable() const { return rendering_available_; }

 public slots:
  void frameAll();
  // Frames the selected visible pieces from the current direction; nothing when none is shown.
  void frameSelected();

 signals:
  // The user changed the selection by picking; not emitted by setSelectedPieces.
  void pieceSelectionChanged(const QList<int>& pieces);
  // The user clicked a body location's marker.
  void locationClicked(int location);
  // The user dropped pieces dragged from the pattern view on a body location's marker.
  void piecesDroppedOnLocation(const QList<int>& pieces, int location);

 protected:
  void initializeGL() override;
  void resizeGL(int width, int height) override;
  void paintGL() override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dragMoveEvent(QDragMoveEvent* event) override;
  void dropEvent(QDropEvent* event) override;

 private:
  struct GpuMesh {
    QOpenGLVertexArrayObject vao;
    QOpenGLBuffer vertices{QOpenGLBuffer::VertexBuffer};
    QOpenGLBuffer indices{QOpenGLBuffer::IndexBuffer};
    int index_count = 0;
  };

  // What the id buffer holds at a widget position: the object id (0 nothing, 1 body, 2 + i piece
  // i) and the depth (0 to 1; 1 over the background).
  struct PickSample {
    int id = 0;
    float depth = 1.0f;
  };
  PickSample pickAt(const QPointF& position);

  void releaseGL();
  void uploadPending();
  void uploadMesh(GpuMesh& mesh, const Eigen::MatrixX3d& positions,
                  const Eigen::MatrixX3i& triangles, bool positions_only);
  void uploadOutlines();
  void uploadMarkers();
  // The diagnostics' #V strains (zeros when they do not fit) into the garment's attribute 2.
  void uploadDiagnostics();
  // The lines and points of the overlays that are on, over the positions shown.
  void uploadOverlayLines();
  // Whether the diagnostics' sizes and vertex ids fit the garment shown.
  bool diagnosticsFit() const;
  // Whether an overlay that draws the checker's diagnostics is on.
  bool diagnosticsWanted() const;
  // Asks the worker for the diagnostics of the positions shown, when they are wanted.
  void requestDiagnostics();
  // The legend's entries for the overlays that are on.
  void updateLegend();
  // Copies the cached body layer into the widget's framebuffer, drawing the layer first when the
  // body, the camera or the size changed; false when the driver cannot (the caller draws the body).
  bool copyBodyLayer(const QMatrix4x4& projection, const QMatrix4x4& view);
  void drawBody(const QMatrix4x4& projection, const QMatrix4x4& view, float opacity);
  void drawGarment(const QMatrix4x4& projection, const QMatrix4x4& view);
  // Every visible piece with the bound garment program (selected pieces tinted, waiting faded).
  void drawGarmentPieces();
  // Outlines of the selected and batch pieces, the diagnostics' lines and points, the markers.
  void drawOutlinesOverlaysAndMarkers(const QMatrix4x4& projection, const QMatrix4x4& view);
  // Aims at a box's centre from the distance that fits its bounding sphere in the view.
  void frameBox(const Eigen::Vector3d& lower, const Eigen::Vector3d& upper);
  void drawForPicking(const QMatrix4x4& projection, const QMatrix4x4& view);
  bool pieceVisible(int piece) const;
  QMatrix4x4 viewMatrix() const;
  QMatrix4x4 projectionMatrix() const;
  QVector3D eye() const;

  Colours colours_;
  std::shared_ptr<const BodyMesh> body_;
  std::shared_ptr<const Garment> garment_;
  std::shared_ptr<const Eigen::MatrixX3d> positions_;
  std::vector<bool> piece_visible_;
  std::vector<PieceState> piece_states_;
  std::shared_ptr<const GarmentDiagnostics> diagnostics_;
  bool overlays_[kOverlayCount] = {false, false, false, false, true};
  bool wireframe_ = false, markers_shown_ = true;
  BodyDisplay body_display_ = BodyDisplay::Shown;
  GarmentDiagnosticsWorker* worker_ = nullptr;
  ColourLegend* legend_ = nullptr;
  QList<int> selected_;
  std::vector<BodyLocationMarker> locations_;
  int highlighted_location_ = -1;

  // What paintGL must upload before drawing.
  bool body_dirty_ = true, garment_topology_dirty_ = true, positions_dirty_ = true,
       markers_dirty_ = true, diagnostics_dirty_ = true, overlay_lines_dirty_ = true;

  bool rendering_available_ = false;
  int garment_frames_ = 0;
  std::unique_ptr<QOpenGLShaderProgram> body_program_, garment_program_, marker_program_,
      pick_program_;
  GpuMesh body_mesh_, garment_mesh_;
  // The body does not move while the garment does: it is drawn once per camera into this layer
  // (colour and depth), and each frame starts from a copy of it. With a software rasteriser the
  // body's ~50k triangles were most of a live frame, all of it on the GUI thread.
  std::unique_ptr<QOpenGLFramebufferObject> body_layer_;
  QMatrix4x4 body_layer_view_, body_layer_projection_;
  bool body_layer_dirty_ = true, body_layer_supported_ = true;
  // Piece outlines as line loops over the garment's vertex buffer, drawn for selected pieces.
  QOpenGLVertexArrayObject outline_vao_;
  QOpenGLBuffer outline_indices_{QOpenGLBuffer::IndexBuffer};
  std::vector<int> outline_first_;  // per piece, first index into outline_indices_
  QOpenGLVertexArrayObject marker_vao_;
  QOpenGLBuffer marker_buffer_{QOpenGLBuffer::VertexBuffer};
  int marker_count_ = 0;
  // #V strains for the strain map: the garment's vertex attribute 2.
  QOpenGLBuffer strain_buffer_{QOpenGLBuffer::VertexBuffer};
  // The diagnostics' lines and points in the marker layout: first the lines and points drawn over
  // everything (penetrations: they lie inside the body or other cloth), then those depth-tested
  // like the surface they lie on (seams, folds).
  QOpenGLVertexArrayObject overlay_vao_;
  QOpenGLBuffer overlay_buffer_{QOpenGLBuffer::VertexBuffer};
  struct OverlayRanges {
    int xray_lines = 0, xray_points = 0, surface_lines = 0, surface_points = 0;  // vertex counts
  } overlay_ranges_;

  // Orbit camera.
  QVector3D target_{0.0f, 1.0f, 0.0f};
  float distance_ = 3.0f;
  float scene_radius_ = 1.0f;
  float yaw_degrees_ = 0.0f, pitch_degrees_ = 8.0f;
  static constexpr float kFieldOfViewDegrees = 35.0f;

  QPoint press_position_, last_position_;
  bool dragged_ = false;
};

}  // namespace garment::ui
