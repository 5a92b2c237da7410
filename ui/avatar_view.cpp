#include "ui/avatar_view.h"

#include <QApplication>
#include <QDropEvent>
#include <QLineF>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <QOpenGLFunctions>
#include <QOpenGLShaderProgram>
#include <QWheelEvent>
#include <QtMath>
#include <cmath>
#include <limits>

#include "engine/core/mesh_geometry.h"
#include "ui/garment_diagnostics_worker.h"
#include "ui/opengl_format.h"
#include "ui/piece_drag.h"

namespace garment::ui {

namespace {

constexpr float kMarkerAxisLength = 0.12f;  // metres drawn along a location's axis
constexpr float kMarkerPointSize = 9.0f;
constexpr float kHighlightedMarkerPointSize = 18.0f;
constexpr float kMarkerLiftPerRadius = 1.2f;
constexpr float kSelectedPieceTint = 0.3f;
constexpr float kWaitingPieceFade = 0.65f;  // towards the background
constexpr float kSeeThroughOpacity = 0.3f;
constexpr float kOverlayPointSize = 7.0f;
// Seams and folds lie on the cloth: drawn this much (metres) towards the camera, they win the
// depth test against the surface they are on and lose it against what is in front of it.
constexpr float kSurfaceOverlayLift = 0.004f;
constexpr int kMarkerFloats = 7;  // per vertex: position, colour, lift towards the camera

// The strain map's colours at 0, 1/3, 2/3 and 1 of AvatarView::kStrainFullScale.
const QColor kStrainStops[4] = {QColor(40, 90, 230), QColor(40, 200, 90), QColor(245, 215, 40),
                                QColor(230, 30, 25)};

QColor mix_colours(const QColor& a, const QColor& b, double t) {
  return QColor::fromRgbF(static_cast<float>(a.redF() + t * (b.redF() - a.redF())),
                          static_cast<float>(a.greenF() + t * (b.greenF() - a.greenF())),
                          static_cast<float>(a.blueF() + t * (b.blueF() - a.blueF())));
}

// Whether every id of an #E by 2 matrix indexes one of `count` vertices.
bool ids_in_range(const Eigen::MatrixX2i& ids, int count) {
  return ids.size() == 0 || (ids.minCoeff() >= 0 && ids.maxCoeff() < count);
}

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

void append_marker_vertex(std::vector<float>& data, const Eigen::Vector3d& position,
                          const QColor& colour, float lift) {
  data.insert(data.end(),
              {static_cast<float>(position.x()), static_cast<float>(position.y()),
               static_cast<float>(position.z()), static_cast<float>(colour.redF()),
               static_cast<float>(colour.greenF()), static_cast<float>(colour.blueF()), lift});
}

// The attributes of marker.vert over the bound buffer of append_marker_vertex's vertices.
void set_marker_layout(QOpenGLFunctions_3_3_Core& gl) {
  const GLsizei stride = kMarkerFloats * sizeof(float);
  gl.glEnableVertexAttribArray(0);
  gl.glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
  gl.glEnableVertexAttribArray(1);
  gl.glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                           reinterpret_cast<const void*>(3 * sizeof(float)));
  gl.glEnableVertexAttribArray(2);
  gl.glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, stride,
                           reinterpret_cast<const void*>(6 * sizeof(float)));
}

}  // namespace

// Whether OpenGL is Mesa's software rasteriser (llvmpipe, softpipe: Xvfb, machines without a GPU
// driver), asked once of a throw-away context.
AvatarView::AvatarView(QWidget* parent) : QOpenGLWidget(parent) {
  QSurfaceFormat format = QSurfaceFormat::defaultFormat();
  format.setVersion(3, 3);
  format.setProfile(QSurfaceFormat::CoreProfile);
  format.setDepthBufferSize(24);
  // Multisampling costs a software rasteriser several times the frame time, and live updates
  // need the frames (an overriding GARMENT_STUDIO_SAMPLES is left alone).
  if (!qEnvironmentVariableIsSet("GARMENT_STUDIO_SAMPLES") && software_opengl())
    format.setSamples(0);
  setFormat(format);
  setMinimumSize(200, 200);
  worker_ = new GarmentDiagnosticsWorker(this);
  connect(worker_, &GarmentDiagnosticsWorker::diagnosticsReady, this,
          [this](std::shared_ptr<const GarmentDiagnostics> diagnostics) {
            setDiagnostics(std::move(diagnostics));
          });
  legend_ = new ColourLegend(this);
  // Hovering a marker shows that it can be clicked, and which location it is.
  setMouseTracking(true);
  setAcceptDrops(true);
}

QColor AvatarView::strainColour(double strain) {
  const double t = 3.0 * std::clamp(strain / kStrainFullScale, 0.0, 1.0);
  const int stop = std::min(static_cast<int>(t), 2);
  return mix_colours(kStrainStops[stop], kStrainStops[stop + 1], t - stop);
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
  strain_buffer_.destroy();
  overlay_vao_.destroy();
  overlay_buffer_.destroy();
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
  diagnostics_.reset();
  worker_->setScene(garment_, body_);
  requestDiagnostics();
  updateLegend();
  frameAll();
}

void AvatarView::setGarment(std::shared_ptr<const Garment> garment) {
  garment_ = std::move(garment);
  positions_.reset();
  piece_visible_.clear();
  piece_states_.clear();
  selected_.clear();
  diagnostics_.reset();
  worker_->setScene(garment_, body_);
  garment_topology_dirty_ = true;
  positions_dirty_ = true;
  updateLegend();
  update();
}

void AvatarView::setGarmentPositions(std::shared_ptr<const Eigen::MatrixX3d> positions) {
  positions_ = std::move(positions);
  positions_dirty_ = true;
  requestDiagnostics();
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

void AvatarView::setPieceStates(std::vector<PieceState> states) {
  piece_states_ = std::move(states);
  updateLegend();
  update();
}

void AvatarView::setOverlay(Overlay overlay, bool on) {
  overlays_[static_cast<int>(overlay)] = on;
  overlay_lines_dirty_ = true;
  requestDiagnostics();
  updateLegend();
  update();
}

void AvatarView::setDiagnostics(std::shared_ptr<const GarmentDiagnostics> diagnostics) {
  diagnostics_ = std::move(diagnostics);
  diagnostics_dirty_ = overlay_lines_dirty_ = true;
  update();
}

bool AvatarView::diagnosticsWanted() const {
  return overlay(Overlay::Strain) || overlay(Overlay::Penetration) || overlay(Overlay::Seams) ||
         overlay(Overlay::Folds);
}

void AvatarView::requestDiagnostics() {
  if (diagnosticsWanted() && garmentShown()) worker_->measure(positions_);
}

bool AvatarView::diagnosticsFit() const {
  if (!diagnostics_ || !garment_) return false;
  const GarmentDiagnostics& d = *diagnostics_;
  const int vertices = garment_->vertex_count();
  return d.vertex_strain.size() == vertices &&
         (d.vertex_inside_body.empty() ||
          d.vertex_inside_body.size() == static_cast<std::size_t>(vertices)) &&
         d.sewing_pair_gap_m.size() == garment_->sewing_pairs.rows() &&
         ids_in_range(d.body_crossing_edges, vertices) &&
         ids_in_range(d.self_crossing_edges, vertices) && ids_in_range(d.fold_edges, vertices);
}

void AvatarView::setWireframe(bool on) {
  wireframe_ = on;
  update();
}

void AvatarView::setBodyDisplay(BodyDisplay display) {
  body_display_ = display;
  update();
}

void AvatarView::setMarkersShown(bool shown) {
  markers_shown_ = shown;
  update();
}

void AvatarView::updateLegend() {
  QList<LegendEntry> entries;
  if (overlay(Overlay::Strain)) {
    const int full = qRound(100.0 * kStrainFullScale);
    for (int k = 0; k < 4; ++k)
      entries.append({strainColour(k * kStrainFullScale / 3.0),
                      k < 3 ? tr("strain %1 %").arg(qRound(k * full / 3.0))
                            : tr("strain %1 % or more (the verdict's limit)").arg(full)});
  }
  if (overlay(Overlay::Penetration)) {
    entries.append({colours_.inside_body, tr("inside the body, or crossing it")});
    entries.append({colours_.cloth_crossing, tr("crossing other cloth")});
  }
  if (overlay(Overlay::Seams)) {
    entries.append({colours_.seam_closed,
                    tr("seam closed (gap up to %1 mm)").arg(qRound(1000 * kSeamGapLimit))});
    entries.append({mix_colours(colours_.seam_closed, colours_.seam_open, 0.5),
                    tr("seam gap %1 cm").arg(50 * (kSeamGapLimit + kSeamGapFullScale), 0, 'f', 1)});
    entries.append(
        {colours_.seam_open, tr("seam gap %1 cm or more").arg(qRound(100 * kSeamGapFullScale))});
  }
  if (overlay(Overlay::Folds)) entries.append({colours_.fold, tr("fold")});
  const bool arranging = std::any_of(piece_states_.begin(), piece_states_.end(), [](PieceState s) {
    return s == PieceState::Waiting || s == PieceState::InBatch;
  });
  if (overlay(Overlay::Batch) && arranging) {
    entries.append(
        {piece_state_colour(PieceState::InBatch), tr("in the current batch (outlined)")});
    entries.append({mix_colours(colours_.outside, colours_.background, kWaitingPieceFade),
                    tr("waiting (faded)")});
  }
  legend_->setEntries(entries);
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
  strain_buffer_.create();
  overlay_vao_.create();
  overlay_buffer_.create();
  body_dirty_ = garment_topology_dirty_ = positions_dirty_ = markers_dirty_ = true;
  diagnostics_dirty_ = overlay_lines_dirty_ = true;
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
  // Lines along the axes first (2 vertices each), then the centre points. A marker inside a limb
  // is lifted towards the camera by a little more than the limb's radius (the surface is further
  // from the axis along a ray that meets the axis obliquely): it shows where the limb does and
  // hides behind the body where the limb does.
  std::vector<float> data;
  for (int i = 0; i < static_cast<int>(locations_.size()); ++i) {
    const QColor& colour =
        i == highlighted_location_ ? colours_.highlighted_marker : colours_.marker;
    const Eigen::Vector3d half = 0.5 * kMarkerAxisLength * locations_[i].axis.normalized();
    const float lift = kMarkerLiftPerRadius * static_cast<float>(locations_[i].radius);
    append_marker_vertex(data, locations_[i].centre - half, colour, lift);
    append_marker_vertex(data, locations_[i].centre + half, colour, lift);
  }
  for (int i = 0; i < static_cast<int>(locations_.size()); ++i)
    append_marker_vertex(data, locations_[i].centre,
                         i == highlighted_location_ ? colours_.highlighted_marker : colours_.marker,
                         kMarkerLiftPerRadius * static_cast<float>(locations_[i].radius));
  marker_vao_.bind();
  marker_buffer_.bind();
  marker_buffer_.allocate(data.data(), static_cast<int>(data.size() * sizeof(float)));
  set_marker_layout(*this);
  marker_vao_.release();
  marker_count_ = static_cast<int>(locations_.size());
}

void AvatarView::uploadDiagnostics() {
  // Zeros while there are no diagnostics, so that the attribute always covers every vertex.
  std::vector<float> strains(static_cast<std::size_t>(garment_->vertex_count()), 0.0f);
  if (diagnosticsFit())
    for (std::size_t v = 0; v < strains.size(); ++v)
      strains[v] = static_cast<float>(diagnostics_->vertex_strain(static_cast<Eigen::Index>(v)));
  garment_mesh_.vao.bind();
  strain_buffer_.bind();
  strain_buffer_.allocate(strains.data(), static_cast<int>(strains.size() * sizeof(float)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, sizeof(float), nullptr);
  garment_mesh_.vao.release();
}

void AvatarView::uploadOverlayLines() {
  std::vector<float> xray_lines, xray_points, surface_lines, surface_points;
  if (diagnosticsFit()) {
    const GarmentDiagnostics& d = *diagnostics_;
    const Eigen::MatrixX3d& p = *positions_;
    const auto add_edges = [&](std::vector<float>& data, const Eigen::MatrixX2i& edges,
                               const QColor& colour, float lift) {
      for (Eigen::Index e = 0; e < edges.rows(); ++e)
        for (int k = 0; k < 2; ++k)
          append_marker_vertex(data, p.row(edges(e, k)).transpose(), colour, lift);
    };
    if (overlay(Overlay::Penetration)) {
      add_edges(xray_lines, d.body_crossing_edges, colours_.inside_body, 0.0f);
      add_edges(xray_lines, d.self_crossing_edges, colours_.cloth_crossing, 0.0f);
      for (std::size_t v = 0; v < d.vertex_inside_body.size(); ++v)
        if (d.vertex_inside_body[v])
          append_marker_vertex(xray_points, p.row(static_cast<Eigen::Index>(v)).transpose(),
                               colours_.inside_body, 0.0f);
    }
    if (overlay(Overlay::Seams)) {
      // A line between the two sides of each sewing pair, and its ends as points, so that a
      // closed seam (a line of no length) shows too.
      const Eigen::MatrixX2i& pairs = garment_->sewing_pairs;
      for (Eigen::Index k = 0; k < pairs.rows(); ++k) {
        const double open =
            (d.sewing_pair_gap_m(k) - kSeamGapLimit) / (kSeamGapFullScale - kSeamGapLimit);
        const QColor colour =
            mix_colours(colours_.seam_closed, colours_.seam_open, std::clamp(open, 0.0, 1.0));
        for (int side = 0; side < 2; ++side) {
          const Eigen::Vector3d end = p.row(pairs(k, side)).transpose();
          append_marker_vertex(surface_lines, end, colour, kSurfaceOverlayLift);
          append_marker_vertex(surface_points, end, colour, kSurfaceOverlayLift);
        }
      }
    }
    if (overlay(Overlay::Folds)) {
      add_edges(surface_lines, d.fold_edges, colours_.fold, kSurfaceOverlayLift);
      for (Eigen::Index f = 0; f < d.fold_edges.rows(); ++f)
        for (int k = 0; k < 2; ++k)
          append_marker_vertex(surface_points, p.row(d.fold_edges(f, k)).transpose(), colours_.fold,
                               kSurfaceOverlayLift);
    }
  }
  overlay_ranges_ = {static_cast<int>(xray_lines.size()) / kMarkerFloats,
                     static_cast<int>(xray_points.size()) / kMarkerFloats,
                     static_cast<int>(surface_lines.size()) / kMarkerFloats,
                     static_cast<int>(surface_points.size()) / kMarkerFloats};
  std::vector<float> data = std::move(xray_lines);
  for (const std::vector<float>* part : {&xray_points, &surface_lines, &surface_points})
    data.insert(data.end(), part->begin(), part->end());
  overlay_vao_.bind();
  overlay_buffer_.bind();
  overlay_buffer_.allocate(data.data(), static_cast<int>(data.size() * sizeof(float)));
  set_marker_layout(*this);
  overlay_vao_.release();
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
      if (garment_topology_dirty_) {
        uploadOutlines();
        diagnostics_dirty_ = true;  // the strain attribute belongs to the garment's VAO
      }
      overlay_lines_dirty_ = true;
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
  if (!garmentShown()) return;
  if (diagnostics_dirty_) {
    uploadDiagnostics();
    diagnostics_dirty_ = false;
  }
  if (overlay_lines_dirty_) {
    uploadOverlayLines();
    overlay_lines_dirty_ = false;
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
  const bool opaque_body = body_display_ == BodyDisplay::Shown;
  if (!opaque_body || !copyBodyLayer(projection, view)) {
    glClearColor(background.x(), background.y(), background.z(), 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (opaque_body) drawBody(projection, view, 1.0f);
  }
  drawGarment(projection, view);
  // Blended over the garment drawn: what lies behind the body shows through it.
  if (body_display_ == BodyDisplay::SeeThrough) drawBody(projection, view, kSeeThroughOpacity);
  drawOutlinesOverlaysAndMarkers(projection, view);
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
    drawBody(projection, view, 1.0f);
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

void AvatarView::drawBody(const QMatrix4x4& projection, const QMatrix4x4& view, float opacity) {
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  if (!body_ || body_mesh_.index_count == 0) return;
  const bool translucent = opacity < 1.0f;
  if (translucent) {
    // Front faces only, blended, leaving the depth buffer to what is behind.
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
  }
  body_program_->bind();
  body_program_->setUniformValue("model_view", view);
  body_program_->setUniformValue("projection", projection);
  body_program_->setUniformValue("base_colour", colour_vector(colours_.body));
  body_program_->setUniformValue("opacity", opacity);
  body_mesh_.vao.bind();
  glDrawElements(GL_TRIANGLES, body_mesh_.index_count, GL_UNSIGNED_INT, nullptr);
  body_mesh_.vao.release();
  if (translucent) {
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
  }
}

void AvatarView::drawGarmentPieces() {
  const bool batch = overlay(Overlay::Batch);
  garment_mesh_.vao.bind();
  for (int p = 0; p < static_cast<int>(garment_->pieces.size()); ++p) {
    if (!pieceVisible(p)) continue;
    const Piece& piece = garment_->pieces[p];
    const bool waiting = batch && p < static_cast<int>(piece_states_.size()) &&
                         piece_states_[p] == PieceState::Waiting;
    garment_program_->setUniformValue("highlight",
                                      selected_.contains(p) ? kSelectedPieceTint : 0.0f);
    garment_program_->setUniformValue("fade", waiting ? kWaitingPieceFade : 0.0f);
    glDrawElements(GL_TRIANGLES, 3 * piece.triangle_count, GL_UNSIGNED_INT,
                   reinterpret_cast<const void*>(3 * sizeof(GLuint) * piece.first_triangle));
  }
  garment_mesh_.vao.release();
}

void AvatarView::drawGarment(const QMatrix4x4& projection, const QMatrix4x4& view) {
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  if (!garmentShown() || garment_mesh_.index_count == 0) return;
  garment_program_->bind();
  garment_program_->setUniformValue("model_view", view);
  garment_program_->setUniformValue("projection", projection);
  garment_program_->setUniformValue("outside_colour", colour_vector(colours_.outside));
  garment_program_->setUniformValue("inside_colour", colour_vector(colours_.inside));
  garment_program_->setUniformValue("highlight_colour", colour_vector(colours_.highlight));
  garment_program_->setUniformValue("fade_colour", colour_vector(colours_.background));
  garment_program_->setUniformValue("strain_map", overlay(Overlay::Strain) && diagnosticsFit());
  garment_program_->setUniformValue("strain_full_scale", static_cast<float>(kStrainFullScale));
  QVector3D stops[4];
  for (int k = 0; k < 4; ++k)
    stops[k] = colour_vector(kStrainStops[k]);
  garment_program_->setUniformValueArray("strain_stops", stops, 4);
  garment_program_->setUniformValue("wire", false);
  if (wireframe_) {
    // The surface pushed back a little, so that its edges drawn as lines win the depth test.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);
  }
  drawGarmentPieces();
  if (wireframe_) {
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDepthFunc(GL_LEQUAL);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    garment_program_->setUniformValue("wire", true);
    garment_program_->setUniformValue("wire_colour", colour_vector(colours_.wire));
    drawGarmentPieces();
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glDepthFunc(GL_LESS);
  }
}

void AvatarView::drawOutlinesOverlaysAndMarkers(const QMatrix4x4& projection,
                                                const QMatrix4x4& view) {
  marker_program_->bind();
  marker_program_->setUniformValue("model_view", view);
  marker_program_->setUniformValue("projection", projection);
  marker_program_->setUniformValue("round_points", false);
  marker_program_->setUniformValue("point_size", 1.0f);
  // Selected pieces and the batch in progress are outlined over everything, so that an outline
  // behind the body shows.
  glDisable(GL_DEPTH_TEST);
  if (garmentShown() && !outline_first_.empty()) {
    outline_vao_.bind();
    const auto draw_outline = [&](int p, const QColor& colour) {
      if (p < 0 || p + 1 >= static_cast<int>(outline_first_.size()) || !pieceVisible(p)) return;
      const QVector3D c = colour_vector(colour);
      context()->functions()->glVertexAttrib3f(1, c.x(), c.y(), c.z());
      glDrawElements(GL_LINE_LOOP, outline_first_[p + 1] - outline_first_[p], GL_UNSIGNED_INT,
                     reinterpret_cast<const void*>(sizeof(GLuint) * outline_first_[p]));
    };
    context()->functions()->glVertexAttrib1f(2, 0.0f);
    if (overlay(Overlay::Batch))
      for (int p = 0; p < static_cast<int>(piece_states_.size()); ++p)
        if (piece_states_[p] == PieceState::InBatch && !selected_.contains(p))
          draw_outline(p, piece_state_colour(PieceState::InBatch));
    for (int p : selected_)
      draw_outline(p, colours_.highlight);
    outline_vao_.release();
  }
  glEnable(GL_PROGRAM_POINT_SIZE);
  const OverlayRanges& r = overlay_ranges_;
  if (garmentShown() && r.xray_lines + r.xray_points + r.surface_lines + r.surface_points > 0) {
    overlay_vao_.bind();
    // Penetrations over everything: they lie inside the body or other cloth.
    glDrawArrays(GL_LINES, 0, r.xray_lines);
    marker_program_->setUniformValue("round_points", true);
    marker_program_->setUniformValue("point_size", kOverlayPointSize);
    glDrawArrays(GL_POINTS, r.xray_lines, r.xray_points);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    marker_program_->setUniformValue("round_points", false);
    marker_program_->setUniformValue("point_size", 1.0f);
    glDrawArrays(GL_LINES, r.xray_lines + r.xray_points, r.surface_lines);
    marker_program_->setUniformValue("round_points", true);
    marker_program_->setUniformValue("point_size", 0.6f * kOverlayPointSize);
    glDrawArrays(GL_POINTS, r.xray_lines + r.xray_points + r.surface_lines, r.surface_points);
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
    overlay_vao_.release();
  }
  if (marker_count_ > 0 && markers_shown_) {
    // Depth-tested: a marker behind the body (or the garment) is hidden by it. Less-or-equal, so
    // that the highlighted marker's larger point covers its own normal point.
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    marker_vao_.bind();
    marker_program_->setUniformValue("round_points", false);
    marker_program_->setUniformValue("point_size", 1.0f);
    glDrawArrays(GL_LINES, 0, 2 * marker_count_);
    marker_program_->setUniformValue("round_points", true);
    marker_program_->setUniformValue("point_size", kMarkerPointSize);
    glDrawArrays(GL_POINTS, 2 * marker_count_, marker_count_);
    if (highlighted_location_ >= 0) {
      marker_program_->setUniformValue("point_size", kHighlightedMarkerPointSize);
      glDrawArrays(GL_POINTS, 2 * marker_count_ + highlighted_location_, 1);
    }
    glDepthFunc(GL_LESS);
    marker_vao_.release();
  }
  glEnable(GL_DEPTH_TEST);
}

void AvatarView::drawForPicking(const QMatrix4x4& projection, const QMatrix4x4& view) {
  glEnable(GL_DEPTH_TEST);
  pick_program_->bind();
  pick_program_->setUniformValue("model_view", view);
  pick_program_->setUniformValue("projection", projection);
  // A body seen through or hidden does not stand in the way.
  if (body_ && body_mesh_.index_count > 0 && body_display_ == BodyDisplay::Shown) {
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

AvatarView::PickSample AvatarView::pickAt(const QPointF& position) {
  if (!rendering_available_ || !QRectF(rect()).contains(position)) return {};
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
  PickSample sample;
  const int x = std::clamp(static_cast<int>(position.x() * ratio), 0, pixels.width() - 1);
  const int y = std::clamp(pixels.height() - 1 - static_cast<int>(position.y() * ratio), 0,
                           pixels.height() - 1);
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
  glReadPixels(x, y, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &sample.depth);
  ids.release();
  doneCurrent();
  sample.id = pixel[0] | (pixel[1] << 8) | (pixel[2] << 16);
  return sample;
}

int AvatarView::pieceAt(const QPoint& position) {
  if (!garmentShown()) return -1;
  const int id = pickAt(QPointF(position) + QPointF(0.5, 0.5)).id;
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

int AvatarView::locationAt(const QPointF& position) const {
  if (!markers_shown_) return -1;
  const QMatrix4x4 transform = projectionMatrix() * viewMatrix();
  int best = -1;
  float best_depth = std::numeric_limits<float>::infinity();
  for (int i = 0; i < static_cast<int>(locations_.size()); ++i) {
    const Eigen::Vector3d& centre = locations_[i].centre;
    const QVector4D clip =
        transform * QVector4D(static_cast<float>(centre.x()), static_cast<float>(centre.y()),
                              static_cast<float>(centre.z()), 1.0f);
    if (clip.w() <= 0.0f) continue;  // behind the camera
    if (QLineF(projectToView(centre), position).length() > kMarkerPickPixels) continue;
    if (clip.z() / clip.w() < best_depth) {
      best_depth = clip.z() / clip.w();
      best = i;
    }
  }
  return best;
}

bool AvatarView::dropPieces(const QMimeData* data, const QPointF& position) {
  const QList<int> pieces = pieces_from_mime_data(data);
  const int location = locationAt(position);
  if (pieces.isEmpty() || location < 0) return false;
  Q_EMIT piecesDroppedOnLocation(pieces, location);
  return true;
}

void AvatarView::dragEnterEvent(QDragEnterEvent* event) {
  // Pieces are accepted anywhere in the view (the cursor says where a drop would seed); anything
  // else, such as files, is left to the main window.
  if (pieces_from_mime_data(event->mimeData()).isEmpty()) {
    event->ignore();
    return;
  }
  event->acceptProposedAction();
}

void AvatarView::dragMoveEvent(QDragMoveEvent* event) {
  if (locationAt(event->position()) >= 0 && !pieces_from_mime_data(event->mimeData()).isEmpty())
    event->acceptProposedAction();
  else
    event->ignore();
}

void AvatarView::dropEvent(QDropEvent* event) {
  if (dropPieces(event->mimeData(), event->position()))
    event->acceptProposedAction();
  else
    event->ignore();
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
  frameBox(lower, upper);
}

void AvatarView::frameSelected() {
  if (!garmentShown()) return;
  Eigen::Vector3d lower = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d upper = -lower;
  for (int p : selected_) {
    if (p < 0 || p >= static_cast<int>(garment_->pieces.size()) || !pieceVisible(p)) continue;
    const Piece& piece = garment_->pieces[p];
    if (piece.vertex_count == 0) continue;
    const auto rows = positions_->middleRows(piece.first_vertex, piece.vertex_count);
    lower = lower.cwiseMin(rows.colwise().minCoeff().transpose());
    upper = upper.cwiseMax(rows.colwise().maxCoeff().transpose());
  }
  frameBox(lower, upper);
}

void AvatarView::frameBox(const Eigen::Vector3d& lower, const Eigen::Vector3d& upper) {
  if (!(lower.array() <= upper.array()).all() || !lower.allFinite() || !upper.allFinite())
    return;  // nothing to frame
  const Eigen::Vector3d centre = 0.5 * (lower + upper);
  scene_radius_ = std::max(0.5f * static_cast<float>((upper - lower).norm()), 0.01f);
  target_ = QVector3D(centre.x(), centre.y(), centre.z());
  // The bounding sphere fits the narrower of the two fields of view.
  const float aspect = static_cast<float>(std::max(width(), 1)) / std::max(height(), 1);
  const float half_vertical = qDegreesToRadians(0.5f * kFieldOfViewDegrees);
  const float half_narrowest =
      aspect < 1.0f ? std::atan(aspect * std::tan(half_vertical)) : half_vertical;
  distance_ = 1.08f * scene_radius_ / std::sin(half_narrowest);
  update();
}

void AvatarView::zoomAt(const QPointF& position, double factor) {
  if (!(factor > 0.0) || !std::isfinite(factor)) return;
  const float new_distance = std::clamp(distance_ * static_cast<float>(factor), 0.05f, 50.0f);
  const float scale = new_distance / distance_;
  // The scene point under the cursor: unprojected from the depth drawn there, or from the
  // target's depth where nothing is drawn.
  const QMatrix4x4 projection = projectionMatrix(), view = viewMatrix();
  const PickSample sample = pickAt(position);
  float depth = sample.depth;
  if (sample.id == 0 || !(depth < 1.0f)) {
    const QVector4D target_clip = projection * view * QVector4D(target_, 1.0f);
    depth = 0.5f * (target_clip.z() / target_clip.w() + 1.0f);
  }
  const QVector4D ndc(static_cast<float>(2.0 * position.x() / std::max(width(), 1) - 1.0),
                      static_cast<float>(1.0 - 2.0 * position.y() / std::max(height(), 1)),
                      2.0f * depth - 1.0f, 1.0f);
  const QVector4D world = (projection * view).inverted() * ndc;
  if (world.w() == 0.0f) return;
  const QVector3D anchor = world.toVector3D() / world.w();
  // Camera and target move towards the anchor by the same ratio as the distance: the anchor keeps
  // its direction from the camera, whose orientation does not change.
  target_ = anchor + scale * (target_ - anchor);
  distance_ = new_distance;
  update();
}

void AvatarView::mousePressEvent(QMouseEvent* event) {
  press_position_ = last_position_ = event->position().toPoint();
  dragged_ = false;
}

void AvatarView::mouseMoveEvent(QMouseEvent* event) {
  const QPoint position = event->position().toPoint();
  if (event->buttons() == Qt::NoButton) {
    const int location = locationAt(event->position());
    setCursor(location >= 0 ? Qt::PointingHandCursor : Qt::ArrowCursor);
    setToolTip(location >= 0 ? QString::fromStdString(locations_[location].name) : QString());
    return;
  }
  const QPoint delta = position - last_position_;
  last_position_ = position;
  if ((position - press_position_).manhattanLength() >= QApplication::startDragDistance())
    dragged_ = true;
  const bool pan =
      (event->buttons() & (Qt::MiddleButton | Qt::RightButton)) ||
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
  // A marker is drawn over the body and the garment: clicking it chooses its location.
  if (const int location = locationAt(event->position()); location >= 0) {
    Q_EMIT locationClicked(location);
    return;
  }
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
  zoomAt(event->position(), std::pow(0.9985, event->angleDelta().y()));
  event->accept();
}

}  // namespace garment::ui
