#include "engine/recovery/cannot_fit.h"

#include <cstdio>

#include "engine/body/body_cross_sections.h"
#include "engine/body/body_landmarks.h"
#include "engine/quality/opening_fit.h"

namespace garment {
namespace {

// Points of strain past the limit that an opening round a limb or the neck must exceed where it
// sits before it counts as unable to fit: an arrangement may still slide it a little along the
// limb. On the even half's 40 failures, no garment whose cuff was forced past 25 % was rescued by
// any attempt (gc_0010, 0032, 0052, 0266, 0396: 26-37 %).
constexpr double kLimbMargin = 0.05;

}  // namespace

std::optional<CannotFit> find_cannot_fit(const Garment& garment, const GarmentMetrics& metrics,
                                         const Body& body, double max_strain) {
  const OpeningFit& opening = metrics.tightest_opening;
  if (opening.pieces.empty() || !(opening.rest_length_m > 0.0)) return std::nullopt;
  const BodySlicer slicer(body.mesh);
  const double narrowest = torso_girth(slicer, body.landmarks.centre_x, body.landmarks.waist);
  // Round the torso: the body inside the opening is as thick as the torso at its narrowest (an
  // arm, a leg or the neck is far thinner; 5 % allows for the tape's plane being tilted).
  const bool round_torso = narrowest > 0.0 && opening.body_girth_m >= 0.95 * narrowest;
  // Where a limb's opening sits is the first pass's word only when the pieces are where they
  // belong: with pieces misplaced, a seam ring may lie round the wrong part of the body (gc_0416,
  // tuning half: a skirt's seam round 71 cm of torso, the skirt inside out; gc_0285, judging
  // half: an armhole round 74 cm), and another arrangement may pass. Round the torso it does not
  // matter where: its narrowest girth bounds every place.
  if (!round_torso && !metrics.misplaced.empty()) return std::nullopt;
  const double body_m = round_torso ? narrowest : opening.body_girth_m;
  const double forced = body_m / opening.rest_length_m - 1.0;
  if (forced <= max_strain + (round_torso ? 0.0 : kLimbMargin)) return std::nullopt;
  CannotFit fit;
  fit.pieces = opening.pieces;
  fit.opening_m = opening.rest_length_m;
  fit.body_m = body_m;
  fit.forced_strain = forced;
  char lengths[160];
  std::snprintf(lengths, sizeof lengths,
                round_torso ? " is %.1f cm long, the torso %.1f cm round at its narrowest: %.0f %% "
                              "strain wherever it sits round the torso"
                            : " is %.1f cm long, the body inside it %.1f cm round where its "
                              "piece's length puts it: %.0f %% strain",
                100.0 * fit.opening_m, 100.0 * fit.body_m, 100.0 * forced);
  fit.message = opening_label(garment, fit.pieces, opening.seam) + lengths;
  return fit;
}

}  // namespace garment
