#include "ui/avatar_view.h"

#include <QApplication>
#include <QMouseEvent>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <QOpenGLFunctions>
#include <QOpenGLShaderProgram>
#include <QWheelEvent>
#include <QtMath>
#include <cmath>

#include "engine/core/mesh_geometry.h"

namespace garment::ui {

namespace {

constexpr float kMarkerAxisLength = 0.12f;  // metres drawn along a location's axis
constexpr float kMarkerPointSize = 9.0f;
constexpr float kHighlightedMarkerPointSize = 18.0f;
constexpr float kSelectedPieceTint = 0.3f;

QVector3D colour_vector(const QColor& colour) {
  return QVector3D(colour.redF(), colour.greenF(), colour.blueF());
}

// Interleaved position and smooth normal per vertex.
std::vector<float> interleaved_positions_and_normals(const Eigen::MatrixX3d& positions,
                                                     const Eigen::MatrixX3i& triangles) {
  const Eigen::MatrixX3d normals = vertex_normals(positions, triangles);
  std::vector<float> data;
  data.reserve(positions.rows() * 6);
  for (Eigen::Index v = 0; v < positions.rows(); ++v) {
    for (int k = 0; k < 3; ++k)
      data.push_back(static_cast<float>(positions(v, k)));
    for (int k = 0; k < 3; ++k)
      data.push_back(static_cast<float>(normals(v, k)));
  }
  return data;
}

std::unique_ptr<QOpenGLShaderProgram> build_program(const QString& vertex,
                                                    const QString& fragment) {
  auto program = std::make_unique<QOpenGLShaderProgram>();
  if (!program->addShaderFromSourceFile(QOpenGLShader::Vertex, ":/shaders/" + vertex) ||
      !program->addShaderFromSourceFile(QOpenGLShader::Fragment, ":/shaders/" + fragment) ||
      !program->link()) {
    qWarning("avatar view: shader %s + %s: %s", qPrintable(vertex), qPrintable(fragment),
             qPrintable(program->log()));
    return nullptr;
  }
  return program;
}

}  // namespace

// Whether OpenGL is Mesa's software rasteriser (llvmpipe, softpipe: Xvfb, machines without a GPU
// driver), asked once of a throw-away context.
static bool software_renderer() {
  static const bool software = [] {
    QOpenGLContext context;
    context.setFormat(QSurfaceFormat::defaultFormat());
    QOffscreenSurface surface;
    surface.setFormat(context.format());
    surface.create();
    if (!context.create() || !context.makeCurrent(&surface)) return false;
    const auto* renderer =
        reinterpret_cast<const char*>(context.functions()->glGetString(GL_RENDERER));
    const QString name = renderer ? QString::fromLatin1(renderer) : QString();
    context.doneCurrent();
    return name.contains("llvmpipe") || name.contains("softpipe") || name.contains("Software");
  }();
  return software;
}

AvatarView::AvatarView(QWidget* parent) : QOpenGLWidget(parent) {
  QSurfaceFormat format = QSurfaceFormat::defaultFormat();
  format.setVersion(3, 3);
  format.setProfile(QSurfaceFormat::CoreProfile);
  format.setDepthBufferSize(24);
  // Multisampling costs a software rasteriser several times the frame time, and live updates
  // need the frames (an overriding GARMENT_STUDIO_SAMPLES is left alone).
  if (!qEnvironmentVariableIsSet("GARMENT_STUDIO_SAMPLES") && software_renderer())
    format.setSamples(0);
  setFormat(format);
  setMinimumSize(200, 200);
}

AvatarView::~AvatarView() {
  // The context outlives this part of the object: its aboutToBeDestroyed must not call back.
  if (context()) disconnect(context(), nullptr, this, nullptr);
  makeCurrent();
  releaseGL();
  doneCurrent();
}

void AvatarView::releaseGL() {
  body_program_.reset();
  garment_program_.reset();
  marker_program_.reset();
  pick_program_.reset();
  for (GpuMesh* mesh : {&body_mesh_, &garment_mesh_}) {
    mesh->vao.destroy();
    mesh->vertices.destroy();
    mesh->indices.destroy();
    mesh->index_count = 0;
  }
  outline_vao_.destroy();
  outline_indices_.destroy();
  outline_first_.clear();
  marker_vao_.destroy();
  marker_buffer_.destroy();
  body_layer_.reset();
  rendering_available_ = false;
}

void AvatarView::setColours(const Colours& colours) {
  colours_ = colours;
  body_layer_dirty_ = true;
  update();
}

void AvatarView::setBody(std::shared_ptr<const BodyMesh> body) {
  body_ = std::move(body);
  body_dirty_ = true;
  frameAll();
}

void AvatarView::setGarment(std::shared_ptr<const Garment> garment) {
  garment_ = std::move(garment);
  positions_.reset();
  piece_visible_.clear();
  selected_.clear();
  garment_topology_dirty_ = true;
  positions_dirty_ = true;
  update();
}

void AvatarView::setGarmentPositions(std::shared_ptr<const Eigen::MatrixX3d> positions) {
  positions_ = std::move(positions);
  positions_dirty_ = true;
  update();
}

bool AvatarView::garmentShown() const {
  return garment_ && positions_ && positions_->rows() == garment_->vertex_count() &&
         garment_->vertex_count() > 0;
}

void AvatarView::setPieceVisibility(std::vector<bool> visible) {
  piece_visible_ = std::move(visible);
  update();
}

bool AvatarView::pieceVisible(int piece) const {
  return piece >= static_cast<int>(piece_visible_.size()) || piece_visible_[piece];
}

void AvatarView::setSelectedPieces(const QList<int>& pieces) {
  selected_ = pieces;
  update();
}

void AvatarView::setBodyLocations(std::vector<BodyLocationMarker> locations) {
  locations_ = std::move(locations);
  if (highlighted_location_ >= static_cast<int>(locations_.size())) highlighted_location_ = -1;
  markers_dirty_ = true;
  update();
}

void AvatarView::setHighlightedLocation(int location) {
  highlighted_location_ =
      location >= 0 && location < static_cast<int>(locations_.size()) ? location : -1;
  markers_dirty_ = true;
  update();
}

void AvatarView::initializeGL() {
  rendering_available_ = false;
  connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, [this] {
    makeCurrent();
    releaseGL();
    doneCurrent();
  });
  if (!initializeOpenGLFunctions()) {
    qWarning("avatar view: OpenGL 3.3 core is not available; the 3D view stays blank");
    return;
  }
  body_program_ = build_program("surface.vert", "body.frag");
  garment_program_ = build_program("surface.vert", "garment.frag");
  marker_program_ = build_program("marker.vert", "marker.frag");
  pick_program_ = build_program("pick.vert", "pick.frag");
  if (!body_program_ || !garment_program_ || !marker_program_ || !pick_program_) return;
  for (GpuMesh* mesh : {&body_mesh_, &garment_mesh_}) {
    mesh->vao.create();
    mesh->vertices.create();
    mesh->indices.create();
  }
  garment_mesh_.vertices.setUsagePattern(QOpenGLBuffer::DynamicDraw);
  outline_vao_.create();
  outline_indices_.create();
  marker_vao_.create();
  marker_buffer_.create();
  body_dirty_ = garment_topology_dirty_ = positions_dirty_ = markers_dirty_ = true;
  rendering_available_ = true;
}

void AvatarView::resizeGL(int, int) {}

void AvatarView::uploadMesh(GpuMesh& mesh, const Eigen::MatrixX3d& positions,
                            const Eigen::MatrixX3i& triangles, bool positions_only) {
  const std::vector<float> vertex_data = interleaved_positions_and_normals(positions, triangles);
  mesh.vao.bind();
  mesh.vertices.bind();
  mesh.vertices.allocate(vertex_data.data(), static_cast<int>(vertex_data.size() * sizeof(float)));
  if (!positions_only) {
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float),
                          reinterpret_cast<const void*>(3 * sizeof(float)));
    std::vector<GLuint> index_data;
    index_data.reserve(triangles.size());
    for (Eigen::Index t = 0; t < triangles.rows(); ++t)
      for (int k = 0; k < 3; ++k)
        index_data.push_back(static_cast<GLuint>(triangles(t, k)));
    mesh.indices.bind();
    mesh.indices.allocate(index_data.data(), static_cast<int>(index_data.size() * sizeof(GLuint)));
    mesh.index_count = static_cast<int>(index_data.size());
  }
  mesh.vao.release();
}

void AvatarView::uploadOutlines() {
  std::vector<GLuint> indices;
  outline_first_.clear();
  for (const Piece& piece : garment_->pieces) {
    outline_first_.push_back(static_cast<int>(indices.size()));
    for (int vertex : piece.outline)
      indices.push_back(static_cast<GLuint>(vertex));
  }
  outline_first_.push_back(static_cast<int>(indices.size()));
  outline_vao_.bind();
  garment_mesh_.vertices.bind();
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
  // The colour attribute stays disabled: its constant value is set before drawing.
  glDisableVertexAttribArray(1);
  outline_indices_.bind();
  outline_indices_.allocate(indices.data(), static_cast<int>(indices.size() * sizeof(GLuint)));
  outline_vao_.release();
}

void AvatarView::uploadMarkers() {
  // Lines along the axes first (2 vertices each), then the centre points; 6 floats per vertex.
  std::vector<float> data;
  auto add = [&data](const Eigen::Vector3d& p, const QColor& colour) {
    for (int k = 0; k < 3; ++k)
      data.push_back(static_cast<float>(p(k)));
    const QVector3D c = colour_vector(colour);
    data.insert(data.end(), {c.x(), c.y(), c.z()});
  };
  for (int i = 0; i < static_cast<int>(locations_.size()); ++i) {
    const QColor& colour =
        i == highlighted_location_ ? colours_.highlighted_marker : colours_.marker;
    const Eigen::Vector3d half = 0.5 * kMarkerAxisLength * locations_[i].axis.normalized();
    add(locations_[i].centre - half, colour);
    add(locations_[i].centre + half, colour);
  }
  for (int i = 0; i < static_cast<int>(locations_.size()); ++i)
    add(locations_[i].centre,
        i == highlighted_location_ ? colours_.highlighted_marker : colours_.marker);
  marker_vao_.bind();
  marker_buffer_.bind();
  marker_buffer_.allocate(data.data(), static_cast<int>(data.size() * sizeof(float)));
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float),
                        reinterpret_cast<const void*>(3 * sizeof(float)));
  marker_vao_.release();
  marker_count_ = static_cast<int>(locations_.size());
}

void AvatarView::uploadPending() {
  if (body_dirty_) {
    if (body_) uploadMesh(body_mesh_, body_->vertices, body_->triangles, false);
    body_dirty_ = false;
    body_layer_dirty_ = true;
  }
  if (garment_topology_dirty_ || positions_dirty_) {
    if (garmentShown()) {
      uploadMesh(garment_mesh_, *positions_, garment_->triangles, !garment_topology_dirty_);
      if (garment_topology_dirty_) uploadOutlines();
      ++garment_frames_;
    }
    // Topology is uploaded together with the first positions that fit it.
    if (garmentShown() || !garment_) garment_topology_dirty_ = false;
    positions_dirty_ = false;
  }
  if (markers_dirty_) {
    uploadMarkers();
    markers_dirty_ = false;
  }
}

QVector3D AvatarView::eye() const {
  const float yaw = qDegreesToRadians(yaw_degrees_);
  const float pitch = qDegreesToRadians(pitch_degrees_);
  return target_ + distance_ * QVector3D(std::cos(pitch) * std::sin(yaw), std::sin(pitch),
                                         std::cos(pitch) * std::cos(yaw));
}

QMatrix4x4 AvatarView::viewMatrix() const {
  QMatrix4x4 view;
  view.lookAt(eye(), target_, QVector3D(0.0f, 1.0f, 0.0f));
  return view;
}

QMatrix4x4 AvatarView::projectionMatrix() const {
  QMatrix4x4 projection;
  const float aspect = static_cast<float>(std::max(width(), 1)) / std::max(height(), 1);
  const float near_plane = std::max(0.02f * distance_, 0.005f);
  projection.perspective(kFieldOfViewDegrees, aspect, near_plane,
                         distance_ + 10.0f * scene_radius_);
  return projection;
}

void AvatarView::paintGL() {
  const QVector3D background = colour_vector(colours_.background);
  if (!rendering_available_) {
    glClearColor(background.x(), background.y(), background.z(), 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    return;
  }
  uploadPending();
  const QMatrix4x4 projection = projectionMatrix(), view = viewMatrix();
  if (!copyBodyLayer(projection, view)) {
    glClearColor(background.x(), background.y(), background.z(), 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    drawBody(projection, view);
  }
  drawGarmentAndMarkers(projection, view);
}

bool AvatarView::copyBodyLayer(const QMatrix4x4& projection, const QMatrix4x4& view) {
  if (!body_layer_supported_) return false;
  while (glGetError() != GL_NO_ERROR) {
  }
  // Qt sets the viewport to the widget's framebuffer before paintGL.
  GLint viewport[4] = {0, 0, 0, 0};
  glGetIntegerv(GL_VIEWPORT, viewport);
  const QSize pixels(viewport[2], viewport[3]);
  if (!body_layer_ || body_layer_->size() != pixels) {
    QOpenGLFramebufferObjectFormat layer_format;
    layer_format.setAttachment(QOpenGLFramebufferObject::CombinedDepthStencil);
    // A blit into a multisampled framebuffer needs a source with the same sample count.
    layer_format.setSamples(format().samples());
    body_layer_ = std::make_unique<QOpenGLFramebufferObject>(pixels, layer_format);
    body_layer_dirty_ = true;
  }
  if (body_layer_dirty_ || body_layer_view_ != view || body_layer_projection_ != projection) {
    body_layer_->bind();
    const QVector3D background = colour_vector(colours_.background);
    glClearColor(background.x(), background.y(), background.z(), 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    drawBody(projection, view);
    body_layer_view_ = view;
    body_layer_projection_ = projection;
    body_layer_dirty_ = false;
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, body_layer_->handle());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, defaultFramebufferObject());
  glBlitFramebuffer(0, 0, pixels.width(), pixels.height(), 0, 0, pixels.width(), pixels.height(),
                    GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, defaultFramebufferObject());
  if (glGetError() == GL_NO_ERROR) return true;
  // A driver that cannot copy between the two framebuffers: the body is drawn every frame.
  qWarning("avatar view: cannot copy the cached body layer; drawing the body every frame");
  body_layer_supported_ = false;
  body_layer_.reset();
  return false;
}

void AvatarView::drawBody(const QMatrix4x4& projection, const QMatrix4x4& view) {
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  if (!body_ || body_mesh_.index_count == 0) return;
  body_program_->bind();
  body_program_->setUniformValue("model_view", view);
  body_program_->setUniformValue("projection", projection);
  body_program_->setUniformValue("base_colour", colour_vector(colours_.body));
  body_mesh_.vao.bind();
  glDrawElements(GL_TRIANGLES, body_mesh_.index_count, GL_UNSIGNED_INT, nullptr);
  body_mesh_.vao.release();
}

void AvatarView::drawGarmentAndMarkers(const QMatrix4x4& projection, const QMatrix4x4& view) {
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  if (garmentShown() && garment_mesh_.index_count > 0) {
    garment_program_->bind();
    garment_program_->setUniformValue("model_view", view);
    garment_program_->setUniformValue("projection", projection);
    garment_program_->setUniformValue("outside_colour", colour_vector(colours_.outside));
    garment_program_->setUniformValue("inside_colour", colour_vector(colours_.inside));
    garment_program_->setUniformValue("highlight_colour", colour_vector(colours_.highlight));
    garment_mesh_.vao.bind();
    for (int p = 0; p < static_cast<int>(garment_->pieces.size()); ++p) {
      if (!pieceVisible(p)) continue;
      const Piece& piece = garment_->pieces[p];
      garment_program_->setUniformValue("highlight",
                                        selected_.contains(p) ? kSelectedPieceTint : 0.0f);
      glDrawElements(GL_TRIANGLES, 3 * piece.triangle_count, GL_UNSIGNED_INT,
                     reinterpret_cast<const void*>(3 * sizeof(GLuint) * piece.first_triangle));
    }
    garment_mesh_.vao.release();
  }
  // Selected pieces are outlined over everything, so that a selection behind the body shows.
  glDisable(GL_DEPTH_TEST);
  marker_program_->bind();
  marker_program_->setUniformValue("model_view", view);
  marker_program_->setUniformValue("projection", projection);
  marker_program_->setUniformValue("round_points", false);
  marker_program_->setUniformValue("point_size", 1.0f);
  if (garmentShown() && !outline_first_.empty()) {
    outline_vao_.bind();
    const QVector3D highlight = colour_vector(colours_.highlight);
    context()->functions()->glVertexAttrib3f(1, highlight.x(), highlight.y(), highlight.z());
    for (int p : selected_) {
      if (p < 0 || p + 1 >= static_cast<int>(outline_first_.size()) || !pieceVisible(p)) continue;
      glDrawElements(GL_LINE_LOOP, outline_first_[p + 1] - outline_first_[p], GL_UNSIGNED_INT,
                     reinterpret_cast<const void*>(sizeof(GLuint) * outline_first_[p]));
    }
    outline_vao_.release();
  }
  if (marker_count_ > 0) {
    // Markers sit on or inside the body: drawn over everything so that all of them stay visible.
    glEnable(GL_PROGRAM_POINT_SIZE);
    marker_vao_.bind();
    glDrawArrays(GL_LINES, 0, 2 * marker_count_);
    marker_program_->setUniformValue("round_points", true);
    marker_program_->setUniformValue("point_size", kMarkerPointSize);
    glDrawArrays(GL_POINTS, 2 * marker_count_, marker_count_);
    if (highlighted_location_ >= 0) {
      marker_program_->setUniformValue("point_size", kHighlightedMarkerPointSize);
      glDrawArrays(GL_POINTS, 2 * marker_count_ + highlighted_location_, 1);
    }
    marker_vao_.release();
  }
  glEnable(GL_DEPTH_TEST);
}

void AvatarView::drawForPicking(const QMatrix4x4& projection, const QMatrix4x4& view) {
  glEnable(GL_DEPTH_TEST);
  pick_program_->bind();
  pick_program_->setUniformValue("model_view", view);
  pick_program_->setUniformValue("projection", projection);
  if (body_ && body_mesh_.index_count > 0) {
    pick_program_->setUniformValue("object_id", 1);
    body_mesh_.vao.bind();
    glDrawElements(GL_TRIANGLES, body_mesh_.index_count, GL_UNSIGNED_INT, nullptr);
    body_mesh_.vao.release();
  }
  if (garmentShown() && garment_mesh_.index_count > 0) {
    garment_mesh_.vao.bind();
    for (int p = 0; p < static_cast<int>(garment_->pieces.size()); ++p) {
      if (!pieceVisible(p)) continue;
      const Piece& piece = garment_->pieces[p];
      pick_program_->setUniformValue("object_id", 2 + p);
      glDrawElements(GL_TRIANGLES, 3 * piece.triangle_count, GL_UNSIGNED_INT,
                     reinterpret_cast<const void*>(3 * sizeof(GLuint) * piece.first_triangle));
    }
    garment_mesh_.vao.release();
  }
}

int AvatarView::pieceAt(const QPoint& position) {
  if (!rendering_available_ || !garmentShown() || !rect().contains(position)) return -1;
  makeCurrent();
  uploadPending();
  const qreal ratio = devicePixelRatioF();
  const QSize pixels(qRound(width() * ratio), qRound(height() * ratio));
  QOpenGLFramebufferObject ids(pixels, QOpenGLFramebufferObject::Depth);
  ids.bind();
  glViewport(0, 0, pixels.width(), pixels.height());
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  drawForPicking(projectionMatrix(), viewMatrix());
  GLubyte pixel[4] = {0, 0, 0, 0};
  const int x = std::clamp(qRound(position.x() * ratio), 0, pixels.width() - 1);
  const int y =
      std::clamp(pixels.height() - 1 - qRound(position.y() * ratio), 0, pixels.height() - 1);
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
  ids.release();
  doneCurrent();
  const int id = pixel[0] | (pixel[1] << 8) | (pixel[2] << 16);
  return id >= 2 ? id - 2 : -1;
}

QPointF AvatarView::projectToView(const Eigen::Vector3d& point) const {
  const QVector4D clip = projectionMatrix() * viewMatrix() *
                         QVector4D(static_cast<float>(point.x()), static_cast<float>(point.y()),
                                   static_cast<float>(point.z()), 1.0f);
  if (clip.w() <= 0.0f) return QPointF(-1.0, -1.0);
  const float x = clip.x() / clip.w(), y = clip.y() / clip.w();
  return QPointF((x + 1.0) * 0.5 * width(), (1.0 - y) * 0.5 * height());
}

void AvatarView::setOrbit(double yaw_degrees, double pitch_degrees) {
  yaw_degrees_ = static_cast<float>(yaw_degrees);
  pitch_degrees_ = std::clamp(static_cast<float>(pitch_degrees), -89.0f, 89.0f);
  update();
}

void AvatarView::frameAll() {
  Eigen::Vector3d lower = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d upper = -lower;
  auto include = [&](const Eigen::MatrixX3d& points) {
    if (points.rows() == 0) return;
    lower = lower.cwiseMin(points.colwise().minCoeff().transpose());
    upper = upper.cwiseMax(points.colwise().maxCoeff().transpose());
  };
  if (body_) include(body_->vertices);
  if (garmentShown()) include(*positions_);
  if (!(lower.array() <= upper.array()).all()) return;  // nothing to frame
  const Eigen::Vector3d centre = 0.5 * (lower + upper);
  scene_radius_ = std::max(0.5f * static_cast<float>((upper - lower).norm()), 0.01f);
  target_ = QVector3D(centre.x(), centre.y(), centre.z());
  distance_ = 1.08f * scene_radius_ / std::sin(qDegreesToRadians(0.5f * kFieldOfViewDegrees));
  update();
}

void AvatarView::mousePressEvent(QMouseEvent* event) {
  press_position_ = last_position_ = event->position().toPoint();
  dragged_ = false;
}

void AvatarView::mouseMoveEvent(QMouseEvent* event) {
  const QPoint position = event->position().toPoint();
  const QPoint delta = position - last_position_;
  last_position_ = position;
  if ((position - press_position_).manhattanLength() >= QApplication::startDragDistance())
    dragged_ = true;
  const bool pan =
      (event->buttons() & Qt::MiddleButton) ||
      ((event->buttons() & Qt::LeftButton) && (event->modifiers() & Qt::ShiftModifier));
  if (pan) {
    // One pixel moves the target by the size of a pixel at the target's depth.
    const float pixel = 2.0f * distance_ * std::tan(qDegreesToRadians(0.5f * kFieldOfViewDegrees)) /
                        std::max(height(), 1);
    const QMatrix4x4 view = viewMatrix();
    const QVector3D right(view(0, 0), view(0, 1), view(0, 2));
    const QVector3D up(view(1, 0), view(1, 1), view(1, 2));
    target_ += pixel * (-delta.x() * right + delta.y() * up);
    update();
  } else if (event->buttons() & Qt::LeftButton) {
    yaw_degrees_ -= 0.4f * delta.x();
    pitch_degrees_ = std::clamp(pitch_degrees_ + 0.4f * delta.y(), -89.0f, 89.0f);
    update();
  }
}

void AvatarView::mouseReleaseEvent(QMouseEvent* event) {
  if (event->button() != Qt::LeftButton || dragged_) return;
  const int piece = pieceAt(event->position().toPoint());
  QList<int> selection;
  if (event->modifiers() & (Qt::ControlModifier | Qt::ShiftModifier)) {
    selection = selected_;
    if (piece >= 0 && !selection.removeOne(piece)) selection << piece;
  } else if (piece >= 0) {
    selection << piece;
  }
  if (selection == selected_) return;
  setSelectedPieces(selection);
  Q_EMIT pieceSelectionChanged(selected_);
}

void AvatarView::wheelEvent(QWheelEvent* event) {
  distance_ = std::clamp(distance_ * std::pow(0.9985f, static_cast<float>(event->angleDelta().y())),
                         0.05f, 50.0f);
  update();
  event->accept();
}

}  // namespace garment::ui
