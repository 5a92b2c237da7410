#pragma once
// The body's signed distance field (negative inside) on a regular grid, built once per body and
// cached on disk.
//
// Method: samples within 1.5 spacings of the surface get the exact distance to their closest
// triangle (every triangle near them is tried). A marching front then carries each sample's
// closest triangle outward to its neighbours in order of distance (closest-point fast marching),
// so the samples up to 6 cm from the surface also hold the exact distance to a triangle that is
// closest or nearly so, with no first-order Eikonal error growing with distance. Farther samples
// take the exact distance to the closest triangle of the nearest sample of a 4× coarser grid
// marched the same way over the whole domain. The sign is the winding number counted by signed
// crossings along the grid rows: inside = winding ≥ 1, so where parts of a self-intersecting
// body overlap (all four bundled/shared bodies press thighs, armpits or lips into themselves a
// little) the overlap is inside, as the union of the parts.
//
// Interpolating the samples misses by up to half a spacing across the kinks of the distance
// (thin gaps between thighs, between arm and torso, inside hands) and can give the wrong sign in
// a gap narrower than the grid. The grid therefore carries its body's surface (body_surface.h):
// the cells within a spacing of the surface, and the farther cells where the samples bend
// sharply, answer with the exact signed distance of the closest feature (sign from its
// angle-weighted pseudo-normal). bench_body and test_distance measure both against CGAL.

#include <filesystem>

#include "engine/body/body_mesh.h"
#include "engine/body/distance_grid.h"

namespace garment {

struct SignedDistanceOptions {
  // Metres between samples. 6 mm: see bench_body and the report of issue 3 for the measured
  // accuracy / build time trade-off.
  double spacing = 0.006;
  // Metres of grid around the body's bounding box, so that a garment hanging away from the body
  // (skirts, sleeves) still gets a gradient that points away from the body, not from the grid.
  double margin = 0.3;
  bool use_cache = true;
  // Empty: default_sdf_cache_directory().
  std::filesystem::path cache_directory;
};

struct SignedDistanceField {
  DistanceGrid grid;
  double build_seconds = 0.0;        // wall time of this call (computation or cache read)
  bool from_cache = false;           // read from a valid cache file
  std::filesystem::path cache_file;  // the file used or written; empty when caching is off
};

// The cached field when a valid cache file for this mesh and these options exists, else the
// computed field (then written to the cache atomically; a cache that cannot be written is
// skipped, the field is still returned).
SignedDistanceField signed_distance_field(const BodyMesh& body,
                                          const SignedDistanceOptions& options = {});

// Computes the field without touching the cache. Parallel (TBB).
DistanceGrid compute_signed_distance_grid(const BodyMesh& body, double spacing, double margin);

// $GARMENT_CACHE_DIR if set (tests point it at a temporary folder), else
// $XDG_CACHE_HOME/garment-studio, else ~/.cache/garment-studio.
std::filesystem::path default_sdf_cache_directory();

}  // namespace garment
