#include "ui/pattern_layout.h"

#include <algorithm>

namespace garment::ui {

namespace {

constexpr double kGap = 0.06;         // metres between pieces and rows
constexpr double kMinRowWidth = 1.6;  // metres before a row wraps

struct PieceBox {
  int piece = 0;
  Eigen::Vector2d lower, upper;  // rest-frame bounding box
  bool back = false;
  double across = 0.0;  // left-right position on the body, from the file's placement
};

PieceBox piece_box(const Garment& garment, int piece_index) {
  const Piece& piece = garment.pieces[piece_index];
  PieceBox box;
  box.piece = piece_index;
  const auto rest = garment.rest_positions.middleRows(piece.first_vertex, piece.vertex_count);
  box.lower = rest.colwise().minCoeff().transpose();
  box.upper = rest.colwise().maxCoeff().transpose();
  const Panel& panel = garment.pattern.panels[piece.panel];
  box.back = panel.translation.z() < 0.0;
  // The file's translation places the panel's own origin; adding the panel's horizontal centre
  // separates a left and a right piece that share an origin on the centre line.
  const auto local = garment.pattern_positions.middleRows(piece.first_vertex, piece.vertex_count);
  const double centre_x = local.col(0).mean() / garment.pattern.units_in_meter;
  box.across = panel.translation.x() + centre_x;
  return box;
}

}  // namespace

std::vector<Eigen::Vector2d> pattern_layout_offsets(const Garment& garment) {
  const int piece_count = static_cast<int>(garment.pieces.size());
  std::vector<PieceBox> boxes;
  double widest = 0.0;
  for (int p = 0; p < piece_count; ++p) {
    if (garment.pieces[p].vertex_count == 0) continue;
    boxes.push_back(piece_box(garment, p));
    widest = std::max(widest, boxes.back().upper.x() - boxes.back().lower.x());
  }
  // Seen from the front the body's right (−x) is on the viewer's left; seen from behind, its left.
  std::stable_sort(boxes.begin(), boxes.end(), [](const PieceBox& a, const PieceBox& b) {
    if (a.back != b.back) return !a.back;
    return a.back ? a.across > b.across : a.across < b.across;
  });

  std::vector<Eigen::Vector2d> offsets(piece_count, Eigen::Vector2d::Zero());
  const double row_width = std::max(kMinRowWidth, widest);
  double row_top = 0.0;
  std::size_t row_begin = 0;
  while (row_begin < boxes.size()) {
    // Fill one row, then centre its pieces vertically on the row's middle line.
    std::size_t row_end = row_begin;
    double x = 0.0, row_height = 0.0;
    const bool back_row = boxes[row_begin].back;
    while (row_end < boxes.size() && boxes[row_end].back == back_row) {
      const double width = boxes[row_end].upper.x() - boxes[row_end].lower.x();
      if (row_end > row_begin && x + width > row_width) break;
      x += width + kGap;
      row_height = std::max(row_height, boxes[row_end].upper.y() - boxes[row_end].lower.y());
      ++row_end;
    }
    const double middle = row_top - 0.5 * row_height;
    x = 0.0;
    for (std::size_t i = row_begin; i < row_end; ++i) {
      const PieceBox& box = boxes[i];
      const Eigen::Vector2d box_centre = 0.5 * (box.lower + box.upper);
      offsets[box.piece] = Eigen::Vector2d(x - box.lower.x(), middle - box_centre.y());
      x += box.upper.x() - box.lower.x() + kGap;
    }
    row_top -= row_height + kGap;
    row_begin = row_end;
  }
  return offsets;
}

}  // namespace garment::ui
