#pragma once
// Pieces sewn flat: two panels in one frame (the same rotation and translation) whose stitched
// edges lie on top of each other in that frame, each a mirror of the other (a.start at b.end), are
// one continuous cloth cut in two. A quilted panel (quilting.h) is many such pieces; GarmentCode's
// left and right torso halves are two. Their connected sets are regions: a region is arranged as
// the one panel it was cut from (region_transfer.h), since the classifier, the start shapes and
// the checks know panels, not the cells of a quilt (issue "Complex garments").

#include <optional>
#include <vector>

#include "engine/pattern/garment_mesh.h"
#include "engine/pattern/pattern.h"

namespace garment {

// #stitches: whether each stitch sews two panels flat (its two edges coincide in their shared
// frame, start to end and at the middle of the curve).
std::vector<bool> stitches_sewn_flat(const Pattern& pattern);

// The pattern with every region merged into one panel, and where each original panel went.
struct RegionPattern {
  Pattern pattern;                    // one panel per region, in the order of its first panel
  std::vector<int> region_of_panel;   // #original panels: index into pattern.panels
  std::vector<int> pieces_of_region;  // #regions: how many original panels each one holds
};

// The pattern as its regions, when one of them holds more than two panels (a quilt: the shared
// GarmentCode designs sew at most two flat, the torso halves the classifier was trained on);
// otherwise nullopt. A merged panel's outline is its pieces' edges that are not sewn flat,
// chained into one loop (curves kept as they are); its name is the words every piece's name
// shares (left_sleeve_f__r1c2, left_sleeve_f__r2c0 → left_sleeve_f), so that the name rules of
// the checks still read it; its frame and label are its first piece's. Stitches not sewn flat
// are kept, re-addressed to the merged edges (one joining a region to itself becomes a dart). A
// region whose edges do not close into one loop (a hole) keeps its pieces as they are; nullopt when
// no region is left to merge.
std::optional<RegionPattern> merge_flat_regions(const Pattern& pattern);

// The regions meshed: what a quilt is arranged as (seeding/scene.h) and judged by
// (quality/region_metrics.h).
struct MeshedRegions {
  Garment garment;                   // of RegionPattern::pattern
  std::vector<int> region_of_panel;  // as RegionPattern's
  std::vector<int> pieces_of_region;
};

// merge_flat_regions meshed with `options`, but no finer than MeshingOptions' default (20 mm,
// paper §4): the arrangement needs a region's shape, not the detail its cells are meshed to (a
// quilt of 17,000 vertices is arranged 2-5 times faster, clean as often). nullopt when there is
// nothing to merge or when the mesher refuses a merged outline (the pieces are then arranged and
// judged as they are). Throws BudgetError as build_garment.
std::optional<MeshedRegions> mesh_flat_regions(const Pattern& pattern,
                                               const MeshingOptions& options = {});

}  // namespace garment
