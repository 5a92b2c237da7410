#pragma once
// The seed (paper §5): the piece(s) arranged first and the body location each goes to. Automatic:
// the waist piece (with the pieces of its kind sewn to it: a waistband in two) when some of these
// close into a ring round the body and it is no long top's hem band (its chest pieces are measured
// against the body), else the chest pieces (front and back), else the neck piece (a collar ring,
// likewise), else the pelvis pieces (front and back, for skirts and trousers without a waistband;
// when the classifier finds one side only, the other is the piece sewn to it that is named for
// that side or that it ranks highest for it), else a rule: the piece with the most garment
// hanging below its seams (Eq. 1), as the neck or waist seed would have. The paper puts the neck
// piece with the waist piece, before the chests; collars come after the chests here
// (seed_choice.cpp gives the figures). Panels named front or back go to that side whatever the
// classifier says of their side (seed_choice.cpp says why). Manual (§5.1.2): any set of pieces
// and one of the 15 body locations.

#include <string>
#include <vector>

#include "engine/pattern/garment_mesh.h"
#include "engine/seeding/piece_classifier.h"

namespace garment {

// Pieces that go together to one body location.
struct SeedPart {
  std::vector<int> pieces;
  std::string location;  // a body location name (body_locations.h)
};

struct SeedPlan {
  std::vector<SeedPart> parts;
  bool manual = false;
  std::string reason;  // how it was chosen, for the report

  std::vector<int> pieces() const;  // of all parts, in order
};

// waist_to_neck: the body's height from waist to neck base (BodyLandmarks), in metres, to tell a
// long top's hem band from a waistband; 0 when there is no body to tell by.
SeedPlan choose_seed(const Garment& garment, const PieceClassification& classification,
                     double waist_to_neck = 0.0);

// Every seed the rules above find, in their order, each once: choose_seed's first, then the ones
// a later rule gives (the classifier's next seeds, which the recovery tries), the last always
// the rule of Eq. 1.
std::vector<SeedPlan> seed_candidates(const Garment& garment,
                                      const PieceClassification& classification,
                                      double waist_to_neck = 0.0);

// A manual seed from piece names and a location name; throws InputError naming the unknown piece
// or location (known_locations lists the valid names).
SeedPlan manual_seed(const Garment& garment, const std::vector<std::string>& piece_names,
                     const std::string& location, const std::vector<std::string>& known_locations);

}  // namespace garment
