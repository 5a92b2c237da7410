#include <cstdio>

#include "command_line.h"
#include "commands.h"
#include "engine/core/atomic_file.h"
#include "engine/pattern/quilting.h"
#include "output_plan.h"

namespace garment::cli {

int quilt_command(const std::vector<std::string>& args) {
  const CommandLine line(args, {}, {"-o", "--cell", "--keep"});
  const auto output = line.value("-o");
  if (!output) throw UsageError("-o OUT_specification.json is required");
  if (!line.value("--cell")) throw UsageError("--cell CM is required");
  QuiltOptions options;
  const double cell_cm = line.number("--cell", 0.0);
  if (!(cell_cm > 0.0)) throw UsageError("--cell must be a positive length in centimetres");
  options.cell = cell_cm / 100.0;
  options.keep = line.list("--keep");
  const std::string pattern_path = line.only_positional("pattern file");
  OutputPlan files;
  files.input("the pattern", pattern_path);
  files.output("-o", *output);
  files.check();
  const Pattern pattern = load_pattern(pattern_path);
  const QuiltResult result = quilt_pattern(pattern, options);
  write_file_atomically(*output, result.specification);
  std::printf(
      "%s: %d pieces (%zu panels, %d kept whole), %d stitches, cell %.4g cm, smallest "
      "cut piece %.4g cm²\n",
      output->c_str(), result.pieces, pattern.panels.size(), result.kept_panels, result.stitches,
      cell_cm, result.smallest_piece_area * 1e4);
  return kSuccess;
}

}  // namespace garment::cli
