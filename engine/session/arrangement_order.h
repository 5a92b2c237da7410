#pragma once
// What an explicit arrangement order can be (SessionOptions::order, Session::reorder): the seed is
// arranged first, and after it a piece can only be arranged once a piece it is sewn to is, since
// the align step pulls it to that piece's seams (§6). The session skips a requested piece that is
// not yet sewn to anything arranged and takes it as soon as it is; this file says, before a run,
// where that puts each piece, so that an editor can show and explain it.

#include <string>
#include <vector>

#include "engine/pattern/garment_mesh.h"

namespace garment {

// Whether `piece` is sewn to a piece marked in `arranged` (a mask over pieces).
bool sewn_to_arranged(const Garment& garment, int piece, const std::vector<bool>& arranged);

// The pieces `piece` is sewn to (not itself), ascending.
std::vector<int> sewing_partners(const Garment& garment, int piece);

struct OrderPlan {
  // The order the session arranges `requested` in: the seed first, then the requested pieces as
  // they become sewn to what is arranged, then those never sewn to it (left to the selection).
  std::vector<int> order;
  // Requested pieces not where they were asked to be, each with why (positions in `order` and in
  // the requested list without its invalid entries; they agree when the list starts with the seed).
  struct Moved {
    int piece = -1;
    int requested_position = -1;
    int position = -1;
    bool seed = false;           // the seed went ahead of it, or it is a seed piece asked later
    std::vector<int> waits_for;  // its sewing partners, when it waited for one of them
  };
  std::vector<Moved> moved;
};

// Where `requested` (piece indices, no repeats; may leave pieces out, or hold the seed anywhere)
// puts each piece when the seed is `seed`. Out-of-range or repeated pieces are left out.
OrderPlan plan_order(const Garment& garment, const std::vector<int>& seed,
                     const std::vector<int>& requested);

}  // namespace garment
