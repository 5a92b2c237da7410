#pragma once
// The 3D avatar view (OpenGL 3.3 core, shaders from shaders/): the shaded body, the garment with an
// outside and an inside colour (a flipped piece shows the inside colour among outside-coloured
// neighbours), and the body locations as markers. Left drag orbits, middle drag or Shift+left drag
// pans, the wheel zooms, frameAll() frames body and garment; a click picks a piece (Ctrl or Shift
// adds to the selection) through an id buffer, so what is picked is what is visible.
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
#include "ui/body_location_marker.h"

class QOpenGLFramebufferObject;
class QOpenGLShaderProgram;

namespace garment::ui {

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
  };

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
  // A point of the scene (metres) in widget coordinates (logical pixels).
  QPointF projectToView(const Eigen::Vector3d& point) const;
  // The piece visible at a widget position, -1 for the body or the background.
  int pieceAt(const QPoint& position);
  // How many garment states were drawn (one per paint that uploaded new positions): the live
  // frame rate's numerator.
  int garmentFrameCount() const { return garment_frames_; }
  // False when OpenGL 3.3 core or the shaders are not available; the view then stays blank.
  bool renderingAvailable() const { return rendering_available_; }

 public slots:
  void frameAll();

 signals:
  // The user changed the selection by picking; not emitted by setSelectedPieces.
  void pieceSelectionChanged(const QList<int>& pieces);

 protected:
  void initializeGL() override;
  void resizeGL(int width, int height) override;
  void paintGL() override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;

 private:
  struct GpuMesh {
    QOpenGLVertexArrayObject vao;
    QOpenGLBuffer vertices{QOpenGLBuffer::VertexBuffer};
    QOpenGLBuffer indices{QOpenGLBuffer::IndexBuffer};
    int index_count = 0;
  };

  void releaseGL();
  void uploadPending();
  void uploadMesh(GpuMesh& mesh, const Eigen::MatrixX3d& positions,
                  const Eigen::MatrixX3i& triangles, bool positions_only);
  void uploadOutlines();
  void uploadMarkers();
  // Copies the cached body layer into the widget's framebuffer, drawing the layer first when the
  // body, the camera or the size changed; false when the driver cannot (the caller draws the body).
  bool copyBodyLayer(const QMatrix4x4& projection, const QMatrix4x4& view);
  void drawBody(const QMatrix4x4& projection, const QMatrix4x4& view);
  void drawGarmentAndMarkers(const QMatrix4x4& projection, const QMatrix4x4& view);
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
  QList<int> selected_;
  std::vector<BodyLocationMarker> locations_;
  int highlighted_location_ = -1;

  // What paintGL must upload before drawing.
  bool body_dirty_ = true, garment_topology_dirty_ = true, positions_dirty_ = true,
       markers_dirty_ = true;

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
