#pragma once
// The report of one arrangement as JSON (garment-init run --report, the editor's export): the seed,
// the arrangement order, the batches with their revisits and checks, solver iterations and seconds
// per phase, and the quality of the result.

#include <string>

#include "engine/arrange/session.h"
#include "engine/quality/garment_metrics.h"
#include "engine/quality/verdict.h"

namespace garment {

std::string session_report_json(const Session& session, const GarmentMetrics& metrics,
                                const QualityVerdict& verdict);

}  // namespace garment
