#pragma once
// The quality of one garment state as JSON: every metric of garment_metrics.h, the misplaced
// pieces, the failures of the verdict and `ok` (the `check` command's --json output).

#include <string>

#include "engine/pattern/garment_mesh.h"
#include "engine/quality/garment_metrics.h"
#include "engine/quality/verdict.h"

namespace garment {

// Pretty-printed JSON object. Pieces are named as in the pattern file.
std::string quality_json(const Garment& garment, const GarmentMetrics& metrics,
                         const QualityVerdict& verdict);

}  // namespace garment
