#pragma once
// Designs that cannot fit the body (issue "Self-correcting arrangement", item 3), judged on the
// first pass's tightest opening (garment_metrics.h), before any attempt:
// - an opening round the torso (a waistband, a top's hem band; the body inside it at least as
//   thick as the torso at its narrowest) shorter than that narrowest girth (the waist landmark's,
//   body_landmarks.h) by more than the strain limit must stretch past it wherever it sits round
//   the torso;
// - an opening round a limb or the neck (a cuff, a trouser leg's end, a neckline) sits where the
//   length of its piece puts it (a cuff at the end of its sleeve): shorter than the body inside
//   it there by more than the strain limit and a margin (cannot_fit.cpp), no arrangement of the
//   same pieces moves it to a thinner place.
// A limb's opening is judged only when no piece is misplaced: otherwise the first pass does not
// say where the design puts it. The recovery spends no attempt on such a design.

#include <optional>
#include <string>
#include <vector>

#include "engine/body/body.h"
#include "engine/pattern/garment_mesh.h"
#include "engine/quality/garment_metrics.h"

namespace garment {

struct CannotFit {
  std::vector<int> pieces;     // the opening runs along them
  double opening_m = 0.0;      // its rest length
  double body_m = 0.0;         // the torso's narrowest girth
  double forced_strain = 0.0;  // body_m / opening_m − 1, the least strain anywhere round the torso
  std::string message;         // one line with the lengths and piece names
};

std::optional<CannotFit> find_cannot_fit(const Garment& garment, const GarmentMetrics& metrics,
                                         const Body& body, double max_strain);

}  // namespace garment
