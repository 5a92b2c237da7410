#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>

#include "command_line.h"
#include "commands.h"
#include "engine/core/mesh_topology.h"
#include "engine/pattern/garment_mesh.h"
#include "engine/quality/garment_metrics.h"
#include "engine/quality/opening_fit.h"

namespace garment::cli {
namespace {

nlohmann::json stitch_json(const Garment& garment, const StitchPairs& range) {
  const Stitch& stitch = garment.pattern.stitches[range.stitch];
  const auto side = [&](const EdgeRef& ref) {
    return nlohmann::json{{"panel", garment.pattern.panels[ref.panel].name}, {"edge", ref.edge}};
  };
  nlohmann::json json{{"a", side(stitch.a)}, {"b", side(stitch.b)}, {"pairs", range.pair_count}};
  if (stitch.right_wrong) json["right_wrong"] = true;
  return json;
}

}  // namespace

int inspect_command(const std::vector<std::string>& args) {
  const CommandLine line(args, {"--json"}, {"--edge-length"});
  MeshingOptions options;
  options.target_edge_length = line.number("--edge-length", options.target_edge_length);
  if (!(options.target_edge_length > 0.0))
    throw UsageError("--edge-length must be positive (metres)");
  const Garment garment =
      build_garment(load_pattern(line.only_positional("pattern file")), options);
  const std::vector<double> areas = piece_rest_areas(garment);

  nlohmann::json report;
  report["pieces"] = nlohmann::json::array();
  for (std::size_t p = 0; p < garment.pieces.size(); ++p) {
    const Piece& piece = garment.pieces[p];
    report["pieces"].push_back({{"name", piece.name},
                                {"vertices", piece.vertex_count},
                                {"triangles", piece.triangle_count},
                                {"area_m2", areas[p]}});
  }
  report["stitches"] = nlohmann::json::array();
  for (const StitchPairs& range : garment.stitches)
    report["stitches"].push_back(stitch_json(garment, range));
  report["darts"] = nlohmann::json::array();
  for (const StitchPairs& range : garment.darts)
    report["darts"].push_back(stitch_json(garment, range));
  // The openings of the sewn garment with their rest lengths: set against the body's girths
  // (`garment-init body`), they tell before any arrangement whether a band can go round it.
  report["openings"] = nlohmann::json::array();
  for (const Opening& opening :
       garment_openings(garment, build_mesh_edges(garment.triangles, garment.vertex_count()),
                        weld_seams_and_darts(garment))) {
    nlohmann::json pieces = nlohmann::json::array();
    for (int piece : opening.pieces)
      pieces.push_back(garment.pieces[piece].name);
    report["openings"].push_back(
        {{"pieces", pieces}, {"rest_length_m", opening.rest_length_m}, {"seam", opening.seam}});
  }
  report["vertices"] = garment.vertex_count();
  report["triangles"] = garment.triangle_count();
  if (line.has("--json")) {
    std::cout << report.dump(2) << "\n";
    return kSuccess;
  }

  std::printf("%s: %zu pieces, %zu stitches, %zu darts (units_in_meter %g)\n\n",
              garment.pattern.source.c_str(), garment.pieces.size(), garment.stitches.size(),
              garment.darts.size(), garment.pattern.units_in_meter);
  std::printf("%-28s %9s %10s %10s\n", "piece", "vertices", "triangles", "area_m2");
  for (const auto& piece : report["pieces"])
    std::printf("%-28s %9d %10d %10.4f\n", piece["name"].get<std::string>().c_str(),
                piece["vertices"].get<int>(), piece["triangles"].get<int>(),
                piece["area_m2"].get<double>());
  const auto print_stitches = [](const char* title, const nlohmann::json& list) {
    if (list.empty()) return;
    std::printf("\n%s\n", title);
    int index = 0;
    for (const auto& stitch : list) {
      const std::string a = stitch["a"]["panel"].get<std::string>() + ":" +
                            std::to_string(stitch["a"]["edge"].get<int>());
      const std::string b = stitch["b"]["panel"].get<std::string>() + ":" +
                            std::to_string(stitch["b"]["edge"].get<int>());
      std::printf("  %3d  %-30s <-> %-30s %4d pairs%s\n", index++, a.c_str(), b.c_str(),
                  stitch["pairs"].get<int>(),
                  stitch.contains("right_wrong") ? "  right_wrong" : "");
    }
  };
  print_stitches("stitches (panel:edge)", report["stitches"]);
  print_stitches("darts (panel:edge)", report["darts"]);
  if (!report["openings"].empty()) std::printf("\nopenings when sewn (rest length)\n");
  for (const auto& opening : report["openings"]) {
    std::string pieces;
    for (const auto& piece : opening["pieces"]) {
      if (!pieces.empty()) pieces += ' ';
      pieces += piece.get<std::string>();
    }
    std::printf("  %7.1f cm  %s\n", 100.0 * opening["rest_length_m"].get<double>(), pieces.c_str());
  }
  std::printf("\ntotal: %d vertices, %d triangles\n", garment.vertex_count(),
              garment.triangle_count());
  return kSuccess;
}

}  // namespace garment::cli
