// A quilt placed from its regions (issue 43): the pieces take the regions' arranged surface.
// The regions' garment is meshed at another size than the pieces', so that no vertex is shared
// and every position is interpolated. Expected positions come from the maps applied to the
// pieces' own pattern coordinates, not from the code under test.

#include <QtTest>

#include "engine/pattern/flat_regions.h"
#include "engine/pattern/garment_mesh.h"
#include "engine/pattern/region_transfer.h"
#include "support/quilted_shirt.h"

using namespace garment;

namespace {

struct Quilt {
  Garment pieces, regions;
  RegionPattern region_pattern;
};

// gc_0022 (shirt front and back halves) quilted at 10 cm; pieces meshed at 20 mm, regions at 27.
Quilt quilt() {
  const Pattern quilted = test::quilted_shirt();
  Quilt result{build_garment(quilted), {}, *merge_flat_regions(quilted)};
  MeshingOptions coarser;
  coarser.target_edge_length = 0.027;
  result.regions = build_garment(result.region_pattern.pattern, coarser);
  return result;
}

// #V×3: `map` of each vertex's pattern position.
template <typename Map>
Eigen::MatrixX3d mapped(const Garment& garment, Map map) {
  Eigen::MatrixX3d positions(garment.vertex_count(), 3);
  for (int v = 0; v < garment.vertex_count(); ++v)
    positions.row(v) = map(garment.pattern_positions.row(v).transpose()).transpose();
  return positions;
}

}  // namespace

class RegionTransferTest : public QObject {
  Q_OBJECT
 private slots:
  // Linear interpolation reproduces an affine map exactly, inside a triangle or just outside it.
  void anAffinePlacementIsReproduced() {
    const Quilt q = quilt();
    Eigen::Matrix<double, 3, 2> linear;
    linear << 0.01, 0.002, -0.003, 0.008, 0.004, 0.005;
    const Eigen::Vector3d offset(0.1, 1.2, -0.3);
    auto affine = [&](const Eigen::Vector2d& x) -> Eigen::Vector3d { return linear * x + offset; };
    const Eigen::MatrixX3d placed = transfer_region_positions(
        q.pieces, q.regions, q.region_pattern.region_of_panel, mapped(q.regions, affine));
    const Eigen::MatrixX3d expected = mapped(q.pieces, affine);
    QVERIFY2((placed - expected).cwiseAbs().maxCoeff() < 1e-9,
             qPrintable(QString::number((placed - expected).cwiseAbs().maxCoeff())));
  }

  // The other way, from the pieces to the regions: the same affine map.
  void theRegionsArePlacedFromThePieces() {
    const Quilt q = quilt();
    Eigen::Matrix<double, 3, 2> linear;
    linear << -0.004, 0.01, 0.006, 0.001, 0.002, -0.007;
    const Eigen::Vector3d offset(-0.2, 0.9, 0.4);
    auto affine = [&](const Eigen::Vector2d& x) -> Eigen::Vector3d { return linear * x + offset; };
    const Eigen::MatrixX3d placed = region_positions_from_pieces(
        q.regions, q.pieces, q.region_pattern.region_of_panel, mapped(q.pieces, affine));
    const Eigen::MatrixX3d expected = mapped(q.regions, affine);
    QVERIFY2((placed - expected).cwiseAbs().maxCoeff() < 1e-9,
             qPrintable(QString::number((placed - expected).cwiseAbs().maxCoeff())));
  }

  // Wrapped round a cylinder (no affine map), the pieces follow within the chord error of the
  // regions' 27 mm mesh, and the two sides of every cut meet exactly.
  void aCurvedPlacementKeepsTheCutsClosed() {
    const Quilt q = quilt();
    const double radius = 15.0;  // pattern units (cm)
    auto wrap = [&](const Eigen::Vector2d& x) -> Eigen::Vector3d {
      return Eigen::Vector3d(radius * std::sin(x.x() / radius), x.y(),
                             radius * std::cos(x.x() / radius));
    };
    const Eigen::MatrixX3d placed = transfer_region_positions(
        q.pieces, q.regions, q.region_pattern.region_of_panel, mapped(q.regions, wrap));
    const Eigen::MatrixX3d expected = mapped(q.pieces, wrap);
    // A chord spanning w across the wrap lies within w² / (8 r) of the arc: w the widest span
    // of a regions' triangle.
    double widest = 0.0;
    for (int t = 0; t < q.regions.triangle_count(); ++t) {
      double low = std::numeric_limits<double>::infinity(), high = -low;
      for (int k = 0; k < 3; ++k) {
        low = std::min(low, q.regions.pattern_positions(q.regions.triangles(t, k), 0));
        high = std::max(high, q.regions.pattern_positions(q.regions.triangles(t, k), 0));
      }
      widest = std::max(widest, high - low);
    }
    const double chord_error = widest * widest / (8.0 * radius);
    const double error = (placed - expected).rowwise().norm().maxCoeff();
    QVERIFY2(error <= 1.01 * chord_error,
             qPrintable(QString("%1 cm, chords within %2 cm").arg(error).arg(chord_error)));
    const Pattern& pattern = q.pieces.pattern;
    const std::vector<bool> flat = stitches_sewn_flat(pattern);
    int cut_pairs = 0;
    for (const StitchPairs& stitch : q.pieces.stitches) {
      if (!flat[stitch.stitch]) continue;
      for (int row = stitch.first_pair; row < stitch.first_pair + stitch.pair_count; ++row) {
        ++cut_pairs;
        const double gap =
            (placed.row(q.pieces.sewing_pairs(row, 0)) - placed.row(q.pieces.sewing_pairs(row, 1)))
                .norm();
        QVERIFY2(gap < 1e-9, qPrintable(QString("pair %1: %2").arg(row).arg(gap)));
      }
    }
    QVERIFY(cut_pairs > 100);
  }
};

QTEST_APPLESS_MAIN(RegionTransferTest)
#include "test_region_transfer.moc"
