#include <cstdio>

#include "command_line.h"
#include "commands.h"
#include "engine/core/atomic_file.h"
#include "engine/io/garment_obj.h"
#include "engine/io/sewn_export.h"
#include "engine/pattern/garment_mesh.h"
#include "engine/quality/flat_placement.h"
#include "output_plan.h"

namespace garment::cli {

int flat_command(const std::vector<std::string>& args) {
  const CommandLine line(args, {}, {"-o", "--edge-length", "--export"});
  const auto output = line.value("-o");
  if (!output) throw UsageError("-o OUT.obj is required");
  MeshingOptions options;
  options.target_edge_length = line.number("--edge-length", options.target_edge_length);
  if (!(options.target_edge_length > 0.0))
    throw UsageError("--edge-length must be positive (metres)");
  std::vector<SewnExport> exports;
  if (const auto list = line.value("--export")) try {
      exports = parse_sewn_exports(*list);
    } catch (const std::invalid_argument& error) {
      throw UsageError(std::string("--export: ") + error.what());
    }
  const std::string pattern_path = line.only_positional("pattern file");
  OutputPlan files;
  files.input("the pattern", pattern_path);
  files.output("-o", *output);
  for (SewnExport kind : exports)
    files.output(std::string("--export ") + sewn_export_name(kind),
                 sewn_export_path(*output, kind));
  files.check();
  const Garment garment = build_garment(load_pattern(pattern_path), options);
  const Eigen::MatrixX3d positions = flat_placement(garment);
  // The same exports as `run`'s, so that a simulator can start from the flat placement too (the
  // comparison of issue 44; no body here, so the sewn GLB has the garment alone).
  AtomicFileSet outputs;
  outputs.stage(*output, format_garment_obj(garment, positions));
  for (SewnExport kind : exports) {
    const std::filesystem::path path = sewn_export_path(*output, kind);
    outputs.stage(path, format_sewn_export(kind, garment, positions, nullptr, path));
  }
  outputs.commit();
  const Eigen::RowVector3d lower = positions.colwise().minCoeff();
  const Eigen::RowVector3d upper = positions.colwise().maxCoeff();
  std::printf("%s: %zu pieces, %d vertices, %d triangles, flat as placed in %s\n", output->c_str(),
              garment.pieces.size(), garment.vertex_count(), garment.triangle_count(),
              garment.pattern.source.c_str());
  std::printf("bounds (m): x %.3f..%.3f  y %.3f..%.3f  z %.3f..%.3f\n", lower.x(), upper.x(),
              lower.y(), upper.y(), lower.z(), upper.z());
  return kSuccess;
}

}  // namespace garment::cli
