#include "engine/session/arrangement_order.h"

#include <algorithm>

namespace garment {

bool sewn_to_arranged(const Garment& garment, int piece, const std::vector<bool>& arranged) {
  for (Eigen::Index k = 0; k < garment.sewing_pairs.rows(); ++k) {
    const int a = garment.vertex_piece(garment.sewing_pairs(k, 0));
    const int b = garment.vertex_piece(garment.sewing_pairs(k, 1));
    if ((a == piece && arranged[b]) || (b == piece && arranged[a])) return true;
  }
  return false;
}

std::vector<int> sewing_partners(const Garment& garment, int piece) {
  std::vector<int> partners;
  for (Eigen::Index k = 0; k < garment.sewing_pairs.rows(); ++k) {
    const int a = garment.vertex_piece(garment.sewing_pairs(k, 0));
    const int b = garment.vertex_piece(garment.sewing_pairs(k, 1));
    const int other = a == piece ? b : b == piece ? a : -1;
    if (other >= 0 && other != piece) partners.push_back(other);
  }
  std::sort(partners.begin(), partners.end());
  partners.erase(std::unique(partners.begin(), partners.end()), partners.end());
  return partners;
}

OrderPlan plan_order(const Garment& garment, const std::vector<int>& seed,
                     const std::vector<int>& requested) {
  const int piece_count = static_cast<int>(garment.pieces.size());
  std::vector<bool> arranged(piece_count, false), in_seed(piece_count, false);
  for (int piece : seed)
    if (piece >= 0 && piece < piece_count) in_seed[piece] = true;
  // The requested pieces, valid and first occurrences only, with their positions.
  std::vector<int> asked;
  std::vector<int> asked_position(piece_count, -1);
  for (int piece : requested) {
    if (piece < 0 || piece >= piece_count || asked_position[piece] >= 0) continue;
    asked_position[piece] = static_cast<int>(asked.size());
    asked.push_back(piece);
  }
  // A seed piece asked after another piece, or another piece asked before a seed piece: the seed
  // goes first whatever the order says.
  std::vector<bool> seed_moves(piece_count, false);
  for (std::size_t i = 0; i < asked.size(); ++i)
    for (std::size_t j = i + 1; j < asked.size(); ++j)
      if (!in_seed[asked[i]] && in_seed[asked[j]])
        seed_moves[asked[i]] = seed_moves[asked[j]] = true;

  OrderPlan plan;
  for (int piece : seed) {
    if (piece < 0 || piece >= piece_count || arranged[piece]) continue;
    arranged[piece] = true;
    plan.order.push_back(piece);
  }
  std::vector<int> waiting;  // asked, not in the seed, in the asked order
  for (int piece : asked)
    if (!in_seed[piece]) waiting.push_back(piece);
  // As Session::next_explicit_batch does: the first waiting piece sewn to the arranged set goes
  // next; the ones before it in the list wait for a partner.
  std::vector<bool> waited(piece_count, false);
  for (;;) {
    const auto next = std::find_if(waiting.begin(), waiting.end(), [&](int piece) {
      return sewn_to_arranged(garment, piece, arranged);
    });
    if (next == waiting.end()) break;
    for (auto skipped = waiting.begin(); skipped != next; ++skipped)
      waited[*skipped] = true;
    arranged[*next] = true;
    plan.order.push_back(*next);
    waiting.erase(next);
  }
  for (int piece : waiting)
    waited[piece] = true;
  plan.order.insert(plan.order.end(), waiting.begin(), waiting.end());

  for (std::size_t position = 0; position < plan.order.size(); ++position) {
    const int piece = plan.order[position];
    if (asked_position[piece] < 0 || asked_position[piece] == static_cast<int>(position)) continue;
    if (!seed_moves[piece] && !waited[piece]) continue;
    OrderPlan::Moved moved;
    moved.piece = piece;
    moved.requested_position = asked_position[piece];
    moved.position = static_cast<int>(position);
    moved.seed = seed_moves[piece];
    if (waited[piece]) moved.waits_for = sewing_partners(garment, piece);
    plan.moved.push_back(std::move(moved));
  }
  return plan;
}

}  // namespace garment
