#include <cstdio>

#include "command_line.h"
#include "commands.h"
#include "engine/io/garment_obj.h"
#include "engine/pattern/garment_mesh.h"
#include "engine/quality/flat_placement.h"
#include "output_plan.h"

namespace garment::cli {

int flat_command(const std::vector<std::string>& args) {
  const CommandLine line(args, {}, {"-o", "--edge-length"});
  const auto output = line.value("-o");
  if (!output) throw UsageError("-o OUT.obj is required");
  MeshingOptions options;
  options.target_edge_length = line.number("--edge-length", options.target_edge_length);
  if (!(options.target_edge_length > 0.0))
    throw UsageError("--edge-length must be positive (metres)");
  const std::string pattern_path = line.only_positional("pattern file");
  OutputPlan files;
  files.input("the pattern", pattern_path);
  files.output("-o", *output);
  files.check();
  const Garment garment = build_garment(load_pattern(pattern_path), options);
  const Eigen::MatrixX3d positions = flat_placement(garment);
  write_garment_obj(*output, garment, positions);
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
