#include "engine/io/sewn_export.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "engine/core/text.h"
#include "engine/io/garment_obj.h"
#include "engine/quality/garment_metrics.h"

namespace garment {

SewnMesh sew_garment(const Garment& garment, const Eigen::MatrixX3d& positions) {
  if (positions.rows() != garment.vertex_count())
    throw std::invalid_argument("sew_garment: positions must have one row per vertex");
  const Eigen::VectorXi welded = weld_seams_and_darts(garment);
  SewnMesh sewn;
  sewn.sewn_vertex.resize(garment.vertex_count());
  Eigen::VectorXi id_of_class = Eigen::VectorXi::Constant(garment.vertex_count(), -1);
  int count = 0;
  for (int v = 0; v < garment.vertex_count(); ++v) {
    int& id = id_of_class(welded(v));
    if (id < 0) id = count++;
    sewn.sewn_vertex(v) = id;
  }
  sewn.positions = Eigen::MatrixX3d::Zero(count, 3);
  Eigen::VectorXd members = Eigen::VectorXd::Zero(count);
  for (int v = 0; v < garment.vertex_count(); ++v) {
    sewn.positions.row(sewn.sewn_vertex(v)) += positions.row(v);
    members(sewn.sewn_vertex(v)) += 1.0;
  }
  sewn.positions.array().colwise() /= members.array();
  sewn.triangles.resize(garment.triangle_count(), 3);
  for (int t = 0; t < garment.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k)
      sewn.triangles(t, k) = sewn.sewn_vertex(garment.triangles(t, k));
  return sewn;
}

std::string format_sewn_obj(const Garment& garment, const Eigen::MatrixX3d& positions) {
  const SewnMesh sewn = sew_garment(garment, positions);
  // A line break in a name would start a line of its own: refused as format_garment_obj does.
  for (const Piece& piece : garment.pieces)
    if (const std::string fault = name_fault(piece.name); !fault.empty())
      throw std::invalid_argument("format_sewn_obj: piece '" + printable(piece.name) +
                                  "': " + fault);
  std::string out;
  out.reserve(static_cast<std::size_t>(garment.vertex_count()) * 80);
  out += "# garment-studio sewn garment from " + printable(garment.pattern.source) + "\n";
  out +=
      "# v: metres, sewn (seam and dart pairs merged); vt: the pattern file's panel "
      "coordinates, one per unwelded vertex; f v/vt.\n";
  out += "# " + std::to_string(sewn.positions.rows()) + " vertices (" +
         std::to_string(garment.vertex_count()) + " unwelded), " +
         std::to_string(garment.triangle_count()) + " triangles\n";
  char line[128];
  for (Eigen::Index v = 0; v < sewn.positions.rows(); ++v)
    out.append(line, static_cast<std::size_t>(std::snprintf(
                         line, sizeof line, "v %.9g %.9g %.9g\n", sewn.positions(v, 0),
                         sewn.positions(v, 1), sewn.positions(v, 2))));
  for (int v = 0; v < garment.vertex_count(); ++v)
    out.append(line, static_cast<std::size_t>(std::snprintf(line, sizeof line, "vt %.9g %.9g\n",
                                                            garment.pattern_positions(v, 0),
                                                            garment.pattern_positions(v, 1))));
  for (const Piece& piece : garment.pieces) {
    out += "g " + piece.name + "\n";
    for (int t = piece.first_triangle; t < piece.first_triangle + piece.triangle_count; ++t) {
      out += 'f';
      for (int k = 0; k < 3; ++k) {
        const int v = garment.triangles(t, k);
        out.append(line, static_cast<std::size_t>(std::snprintf(line, sizeof line, " %d/%d",
                                                                sewn.sewn_vertex(v) + 1, v + 1)));
      }
      out += '\n';
    }
  }
  return out;
}

std::string format_sewing_lines_obj(const Garment& garment, const Eigen::MatrixX3d& positions) {
  // The unwelded OBJ lists the pieces in order, so file index = global vertex id + 1.
  std::string out = format_garment_obj(garment, positions);
  out += "# sewing: " + std::to_string(garment.sewing_pairs.rows()) + " stitch pairs and " +
         std::to_string(garment.dart_pairs.rows()) + " dart pairs as loose edges\n";
  char line[64];
  for (const Eigen::MatrixX2i* pairs : {&garment.sewing_pairs, &garment.dart_pairs})
    for (Eigen::Index k = 0; k < pairs->rows(); ++k)
      out.append(line,
                 static_cast<std::size_t>(std::snprintf(line, sizeof line, "l %d %d\n",
                                                        (*pairs)(k, 0) + 1, (*pairs)(k, 1) + 1)));
  return out;
}

std::vector<GlbMesh> sewn_glb_meshes(const Garment& garment, const Eigen::MatrixX3d& positions,
                                     const Body* body) {
  std::vector<GlbMesh> meshes = garment_glb_meshes(garment, positions, body);
  SewnMesh sewn = sew_garment(garment, positions);
  meshes.front().positions = std::move(sewn.positions);
  meshes.front().triangles = std::move(sewn.triangles);
  return meshes;
}

const char* sewn_export_name(SewnExport kind) {
  switch (kind) {
    case SewnExport::kSewnObj:
      return "sewn-obj";
    case SewnExport::kSewnGlb:
      return "sewn-glb";
    case SewnExport::kSewingObj:
      return "sewing-obj";
  }
  return "";
}

std::filesystem::path sewn_export_path(const std::filesystem::path& obj, SewnExport kind) {
  std::filesystem::path path = obj;
  switch (kind) {
    case SewnExport::kSewnObj:
      return path.replace_extension(".sewn.obj");
    case SewnExport::kSewnGlb:
      return path.replace_extension(".sewn.glb");
    case SewnExport::kSewingObj:
      return path.replace_extension(".sewing.obj");
  }
  return path;
}

std::vector<SewnExport> parse_sewn_exports(const std::string& list) {
  std::vector<SewnExport> kinds;
  std::size_t start = 0;
  while (start <= list.size()) {
    const std::size_t end = std::min(list.find(',', start), list.size());
    const std::string word = list.substr(start, end - start);
    start = end + 1;
    bool known = false;
    for (SewnExport kind : {SewnExport::kSewnObj, SewnExport::kSewnGlb, SewnExport::kSewingObj})
      if (word == sewn_export_name(kind)) {
        for (SewnExport earlier : kinds)
          if (earlier == kind) throw std::invalid_argument("'" + word + "' is listed twice");
        kinds.push_back(kind);
        known = true;
      }
    if (!known)
      throw std::invalid_argument("unknown export '" + word +
                                  "' (expected sewn-obj, sewn-glb or sewing-obj, comma-separated)");
  }
  return kinds;
}

std::string format_sewn_export(SewnExport kind, const Garment& garment,
                               const Eigen::MatrixX3d& positions, const Body* body,
                               const std::filesystem::path& path) {
  switch (kind) {
    case SewnExport::kSewnObj:
      return format_sewn_obj(garment, positions);
    case SewnExport::kSewnGlb:
      return format_glb(sewn_glb_meshes(garment, positions, body), path.string());
    case SewnExport::kSewingObj:
      return format_sewing_lines_obj(garment, positions);
  }
  return {};
}

}  // namespace garment
