#pragma once
// The report of one arrangement as JSON (garment-init run --report, the editor's export): the seed,
// the arrangement order, the batches with their revisits and checks, solver iterations and seconds
// per phase, the quality of the result, and the recovery's attempts.

#include <string>

#include "engine/quality/garment_metrics.h"
#include "engine/quality/verdict.h"
#include "engine/recovery/recovery.h"
#include "engine/session/session.h"

namespace garment {

// recovery: the attempts that led to `session` (recovery.h), listed under "recovery"; none: a
// session run once.
// regions: a quilt arranged as its regions (seeding/scene.h): `metrics` and `verdict` are of its
// pieces, as are "pieces", "vertices" and "quality"; "regions" lists the regions with their piece
// counts, and the seed, order and batches name the regions the session arranged.
std::string session_report_json(const Session& session, const GarmentMetrics& metrics,
                                const QualityVerdict& verdict,
                                const RecoveryResult* recovery = nullptr,
                                const RegionScene* regions = nullptr);

}  // namespace garment
