#pragma once
// The entry functions of the fuzz targets (fuzz_pattern.cpp, fuzz_obj.cpp), shared with the corpus
// replay test (test_corpus_replay.cpp) so that the regression corpus runs through exactly the code
// the fuzzer ran. An entry returns normally for every input: a valid input gives a result, an
// invalid one an InputError (BudgetError included). Anything else — another exception, a crash, a
// sanitizer report, a hang — is a finding.

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <string>

#include "engine/body/body_mesh.h"
#include "engine/core/error.h"
#include "engine/io/garment_obj.h"
#include "engine/pattern/garment_mesh.h"
#include "engine/pattern/pattern.h"

namespace garment::fuzz {

// Small enough that one input meshes in milliseconds, large enough for the real seed patterns at a
// coarse edge length.
inline MeshingOptions fuzz_meshing_options() {
  MeshingOptions options;
  options.target_edge_length = 0.05;
  options.vertex_budget = 5000;
  return options;
}

// Pattern importer: JSON text → parse_pattern → build_garment (small vertex budget).
inline void fuzz_pattern_input(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const Pattern pattern = parse_pattern(text, "fuzz.json");
    const Garment garment = build_garment(pattern, fuzz_meshing_options());
    // The mesh must index its own vertices.
    if (garment.triangle_count() > 0 && (garment.triangles.minCoeff() < 0 ||
                                         garment.triangles.maxCoeff() >= garment.vertex_count()))
      __builtin_trap();
  } catch (const InputError&) {
  }
}

// A garment to read garment OBJ files against: the two-rectangle pattern, meshed once.
inline const Garment& fuzz_reference_garment() {
  static const Garment garment = [] {
    const char* text = R"({"pattern": {"panels": {
      "a": {"vertices": [[0,0],[20,0],[20,30],[0,30]], "edges": [
        {"endpoints":[0,1]},{"endpoints":[1,2]},{"endpoints":[2,3]},{"endpoints":[3,0]}]},
      "b": {"vertices": [[0,0],[20,0],[20,30],[0,30]], "edges": [
        {"endpoints":[0,1]},{"endpoints":[1,2]},{"endpoints":[2,3]},{"endpoints":[3,0]}]}},
      "stitches": [[{"panel":"a","edge":1},{"panel":"b","edge":3}]]}})";
    return build_garment(parse_pattern(text, "reference.json"), fuzz_meshing_options());
  }();
  return garment;
}

// OBJ readers: the same text as a body (parse_body_obj) and as a garment export
// (parse_garment_obj, against fuzz_reference_garment()).
inline void fuzz_obj_input(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const BodyMesh body = parse_body_obj(text, "fuzz.obj");
    if (!body.vertices.allFinite() || body.triangles.rows() == 0) __builtin_trap();
  } catch (const InputError&) {
  }
  try {
    const Garment& garment = fuzz_reference_garment();
    const Eigen::MatrixX3d positions = parse_garment_obj(text, "fuzz.obj", garment);
    if (positions.rows() != garment.vertex_count()) __builtin_trap();
  } catch (const InputError&) {
  }
}

}  // namespace garment::fuzz
