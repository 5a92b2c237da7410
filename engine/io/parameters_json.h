#pragma once
// The arrangement's parameters as JSON, for `garment-init run/batch --parameters FILE`
// (experiments, per-studio defaults) and for the report. Every key is optional; unknown keys are
// errors, so that a misspelt parameter is not silently ignored, and so is a value outside its key's
// range (a stiffness of -1000, gravity 1e308, iterations -1 or 2.5), which the arrangement would
// otherwise meet only deep inside a solver, with neither the file nor the key named.

#include <filesystem>
#include <string>

#include "engine/arrange/arrangement_parameters.h"

namespace garment {

// Applies the keys of `json_text` over `parameters`. Throws InputError "<source>: <key>: <value> is
// out of range: must be between <low> and <high> (<unit>)" and the like, naming `source` and the
// key.
void apply_parameters_json(const std::string& json_text, const std::string& source,
                           ArrangementParameters& parameters);
ArrangementParameters load_parameters(const std::filesystem::path& path);

std::string parameters_json(const ArrangementParameters& parameters);

}  // namespace garment
