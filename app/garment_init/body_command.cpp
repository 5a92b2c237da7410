#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>

#include "command_line.h"
#include "commands.h"
#include "engine/body/body.h"
#include "engine/body/default_body.h"

namespace garment::cli {
namespace {

nlohmann::ordered_json vector_json(const Eigen::Vector3d& v) {
  return {v.x(), v.y(), v.z()};
}

nlohmann::ordered_json axis_json(const BodyAxis& axis) {
  return {{"origin", vector_json(axis.origin)},
          {"direction", vector_json(axis.direction)},
          {"length", axis.length}};
}

}  // namespace

int body_command(const std::vector<std::string>& args) {
  const CommandLine line(args, {"--json", "--no-cache"}, {"--spacing"});
  if (line.positional().size() > 1) throw UsageError("expected at most one body file");
  const std::filesystem::path path =
      line.positional().empty() ? default_body_path() : std::filesystem::path(line.positional()[0]);
  SignedDistanceOptions options;
  options.spacing = line.number("--spacing", options.spacing);
  if (!(options.spacing >= 0.001 && options.spacing <= 0.1))
    throw UsageError("--spacing must be between 0.001 and 0.1 (metres)");
  options.use_cache = !line.has("--no-cache");
  const Body body = load_body(path, options);
  // On stderr, with --json too: the report stays parseable and the warning is seen.
  for (const std::string& warning : body.warnings)
    std::fprintf(stderr, "warning: %s\n", warning.c_str());

  nlohmann::ordered_json report;
  report["source"] = body.mesh.source;
  report["vertices"] = body.mesh.vertices.rows();
  report["triangles"] = body.mesh.triangles.rows();
  report["height_m"] = body.mesh.height();
  report["unit_scale"] = body.mesh.unit_scale;
  const BodyLandmarks& marks = body.landmarks;
  report["landmarks"] = {{"floor", marks.floor}, {"crotch", marks.crotch},
                         {"hips", marks.hips},   {"waist", marks.waist},
                         {"bust", marks.bust},   {"armpits", marks.armpits},
                         {"neck", marks.neck},   {"top", marks.top}};
  // The tape round the torso at the three landmarks: what a band or a bodice must reach round.
  const BodySlicer slicer(body.mesh);
  const auto girth = [&](double height) { return torso_girth(slicer, marks.centre_x, height); };
  report["torso_girths_m"] = {
      {"hips", girth(marks.hips)}, {"waist", girth(marks.waist)}, {"bust", girth(marks.bust)}};
  report["axes"] = {{"torso", axis_json(marks.torso)},
                    {"left_arm", axis_json(marks.left_arm)},
                    {"right_arm", axis_json(marks.right_arm)},
                    {"left_leg", axis_json(marks.left_leg)},
                    {"right_leg", axis_json(marks.right_leg)}};
  report["locations"] = nlohmann::ordered_json::array();
  for (const BodyLocation& location : body.locations) {
    nlohmann::ordered_json entry{{"name", location.name},
                                 {"center", vector_json(location.center)},
                                 {"axis", vector_json(location.axis)},
                                 {"surface", surface_name(location.surface)},
                                 {"up", vector_json(location.up)},
                                 {"half_height", location.half_height}};
    if (location.surface == LocationSurface::cylinder)
      entry["radius"] = location.radius;
    else
      entry["half_width"] = location.half_width;
    report["locations"].push_back(entry);
  }
  if (!body.overrides_file.empty()) report["overrides"] = body.overrides_file.string();
  report["warnings"] = body.warnings;
  const DistanceGrid& grid = body.distance.grid;
  report["sdf"] = {
      {"spacing_m", grid.spacing},          {"size", {grid.size.x(), grid.size.y(), grid.size.z()}},
      {"origin", vector_json(grid.origin)}, {"build_seconds", body.distance.build_seconds},
      {"cached", body.distance.from_cache}, {"cache_file", body.distance.cache_file.string()}};
  if (line.has("--json")) {
    std::cout << report.dump(2) << "\n";
    return kSuccess;
  }

  std::printf("%s: %ld vertices, %ld triangles, height %.3f m%s\n", body.mesh.source.c_str(),
              static_cast<long>(body.mesh.vertices.rows()),
              static_cast<long>(body.mesh.triangles.rows()), body.mesh.height(),
              body.mesh.unit_scale != 1.0 ? " (scaled from the file's unit)" : "");
  std::printf(
      "\nlandmark heights (m): crotch %.3f  hips %.3f  waist %.3f  bust %.3f  armpits %.3f"
      "  neck %.3f\n",
      marks.crotch, marks.hips, marks.waist, marks.bust, marks.armpits, marks.neck);
  const nlohmann::ordered_json& girths = report["torso_girths_m"];
  std::printf("torso girths (cm, a tape round the torso): hips %.1f  waist %.1f  bust %.1f\n",
              100.0 * girths["hips"].get<double>(), 100.0 * girths["waist"].get<double>(),
              100.0 * girths["bust"].get<double>());
  std::printf("\naxes                origin                     direction               length\n");
  for (const auto& [name, axis] : report["axes"].items())
    std::printf("  %-10s (%6.3f %6.3f %6.3f)   (%6.3f %6.3f %6.3f)   %6.3f\n", name.c_str(),
                axis["origin"][0].get<double>(), axis["origin"][1].get<double>(),
                axis["origin"][2].get<double>(), axis["direction"][0].get<double>(),
                axis["direction"][1].get<double>(), axis["direction"][2].get<double>(),
                axis["length"].get<double>());
  std::printf("\n%-18s %-9s %-24s %-24s %s\n", "location", "surface", "center (m)", "axis / normal",
              "size (m)");
  for (const BodyLocation& location : body.locations) {
    char size[64];
    if (location.surface == LocationSurface::cylinder)
      std::snprintf(size, sizeof size, "radius %.3f, half height %.3f", location.radius,
                    location.half_height);
    else
      std::snprintf(size, sizeof size, "half %.3f × %.3f", location.half_width,
                    location.half_height);
    std::printf("%-18s %-9s (%6.3f %6.3f %6.3f)   (%6.3f %6.3f %6.3f)   %s\n",
                location.name.c_str(), std::string(surface_name(location.surface)).c_str(),
                location.center.x(), location.center.y(), location.center.z(), location.axis.x(),
                location.axis.y(), location.axis.z(), size);
  }
  if (!body.overrides_file.empty())
    std::printf("\noverrides applied from %s\n", body.overrides_file.c_str());
  std::printf("\nsigned distance field: spacing %.1f mm, %d×%d×%d samples, %.3f s (%s)\n",
              1000.0 * grid.spacing, grid.size.x(), grid.size.y(), grid.size.z(),
              body.distance.build_seconds,
              body.distance.from_cache ? "read from cache"
                                       : (options.use_cache ? "built and cached" : "built"));
  return kSuccess;
}

}  // namespace garment::cli
