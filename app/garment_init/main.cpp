// garment-init: the headless face of garment-studio. Wiring only: each command lives in its own
// file.

#include <cstdio>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "command_line.h"
#include "commands.h"
#include "engine/core/error.h"

namespace {

using garment::cli::Command;

const Command kCommands[] = {
    {"inspect", "inspect PATTERN.json [--json] [--edge-length M]",
     "Imports and meshes a GarmentCode pattern. Prints per piece its name, vertices, triangles "
     "and\n"
     "area (m²); per stitch its two sides and number of vertex pairs; darts; the openings of the "
     "sewn\n"
     "garment (waistbands, cuffs, necklines, hems) with their rest lengths; totals. --json prints "
     "one\n"
     "object {pieces, stitches, darts, openings, vertices, triangles}.",
     garment::cli::inspect_command},
    {"run",
     "run PATTERN.json [MORE.json ...] [--body BODY.obj] -o OUT.obj [--glb OUT.glb] [--export "
     "KINDS] [--report "
     "R.json] "
     "[--seed-pieces a,b "
     "--seed-location NAME] "
     "[--order p1,p2,...] [--threads N] [--edge-length M] [--parameters P.json] [--snapshots DIR] "
     "[--attempts N] [--clearance MM] [--quiet]",
     "Arranges the pattern on the body (default: the bundled mean body) and writes the garment "
     "OBJ\n"
     "(one group per panel, vt = pattern coordinates). Several patterns are an outfit, the first\n"
     "innermost: each garment arranged outside the ones before it (a shirt tucked in: shirt then\n"
     "skirt; worn over: skirt then shirt), one post-process over all, groups named GARMENT:PANEL\n"
     "(GARMENT: the file name without _specification.json or .json), crossings between garments\n"
     "printed and reported per pair; --glb also writes the garment and the body\n"
     "as glTF 2.0 binary for viewers. --export sewn-obj,sewn-glb,sewing-obj (any of them) also\n"
     "writes files for cloth simulators next to OUT.obj: OUT.sewn.obj (seam and dart pairs merged\n"
     "into one mesh, pattern UVs per corner), OUT.sewn.glb (the same mesh and the body, no UVs) "
     "and\n"
     "OUT.sewing.obj (the unwelded pieces plus one `l i j` line per sewing pair: Blender's cloth\n"
     "sewing springs); scripts/validate_glb.sh checks a GLB with the Khronos glTF validator.\n"
     "Seeds with the classifier unless --seed-pieces and --seed-location (one of the 15 body\n"
     "locations, see `body`) are given; --order fixes the arrangement order of the named pieces.\n"
     "--report writes the order, batches, revisits, "
     "per-phase\n"
     "iterations and times and the quality metrics as JSON. --snapshots writes the garment after "
     "every\n"
     "phase (NNN_batchB_PHASE.obj), to step through the arrangement. --parameters overrides "
     "stiffnesses,\n"
     "budgets and thresholds (keys as in the report's \"parameters\"). A garment that fails the "
     "quality\n"
     "check is diagnosed and arranged again (on a finer or coarser mesh, reordered, from another\n"
     "seed, with a longer settle), up to --attempts sessions in all (default 8; 1: a single pass), "
     "the\n"
     "best kept; the report lists every attempt, and a design that cannot fit the body is said so\n"
     "(cannot_fit) with no attempt, or none further once an attempt shows it. --clearance MM:\n"
     "the post-process repels the cloth from the body within MM millimetres instead of its 3 mm\n"
     "(the cloth ends up to 0.3 mm nearer), for a simulator whose collision distance is larger\n"
     "(scripts/blender-drape). Exit 0 when the garment passes the quality check, 3 when it was\n"
     "written but fails it.",
     garment::cli::run_command},
    {"batch",
     "batch DIR|--outfits LIST -o OUTDIR [--jobs N] [--body BODY.obj] [--bodies DIR] [--time-limit "
     "S] [--limit N] "
     "[--parameters P.json] [--attempts N] [--export KINDS] [--clearance MM] [--shard K/N]",
     "Runs `run` on every pattern in DIR, each in its own process with one thread and a time "
     "limit\n"
     "(default 300 s), --jobs at a time (default: the number of cores). Each pattern goes on its "
     "own\n"
     "body when DIR has a GarmentCode index.json (body_obj, looked up in --bodies, default\n"
     "DIR/../../bodies), else on --body (default: the bundled body). Writes per pattern "
     "OUTDIR/NAME.obj,\n"
     ".report.json, .log and .outcome.json (with --export, as in `run`: NAME.sewn.obj, ...);\n"
     "patterns with an outcome are skipped, so an interrupted batch resumes. OUTDIR may not be\n"
     "DIR or lie inside it; jobs die with the batch. Prints a progress bar on a terminal and\n"
     "writes summary.md and summary.json: success\n"
     "rate (clean at the first pass, recovered, failed, designs that cannot fit), failures by\n"
     "class, time per garment (median, p95, max). --clearance as in `run`.\n"
     "--shard K/N (K 1-based, 1 <= K <= N) runs one part of the batch, for N machines: of the\n"
     "name-sorted patterns (the first --limit of them), those at 0-based positions i with\n"
     "i % N == K - 1; its summary says which shard it is. `summary` merges the shards' OUTDIRs.\n"
     "--outfits LIST instead of DIR: an outfit per line of LIST, its pattern files separated by\n"
     "spaces, the first innermost (as `run` takes them), and optionally its body (a .obj; else\n"
     "--body); paths relative to LIST's folder, # starts a comment line; NAME is the garments'\n"
     "names joined by '+'.",
     garment::cli::batch_command},
    {"summary", "summary OUTDIR... [-o MERGED_DIR]",
     "Merges the summaries of the shards of a batch (batch --shard K/N, each OUTDIR one shard):\n"
     "writes MERGED_DIR/summary.md and summary.json as `batch` over all the patterns writes them\n"
     "(same results in the same order, same counts), and prints its totals; without -o only\n"
     "prints them. Timing differs as between any two runs: each garment's seconds come from its\n"
     "shard, and the wall time is the slowest shard's (shards run side by side). Every shard\n"
     "1..N must be given once, each pattern in one shard only; MERGED_DIR may not be an OUTDIR.\n"
     "An OUTDIR of a batch without --shard counts as shard 1/1.",
     garment::cli::summary_command},
    {"body", "body [BODY.obj] [--json] [--spacing M] [--no-cache]",
     "Loads a body (default: the bundled resources/bodies/mean_all.obj): OBJ with triangles or\n"
     "polygons, metres or centimetres (detected); closed, manifold surface required. Prints its\n"
     "size, landmark heights (crotch, hips, waist, bust, armpits, neck), the torso's girths at\n"
     "hips, waist (its narrowest) and bust, torso/arm/leg axes, the 15\n"
     "seed locations (name, surface cylinder|plane, centre, axis or normal, size) and the signed\n"
     "distance field (spacing, default 0.006 m; build time; whether it came from the cache in\n"
     "$XDG_CACHE_HOME/garment-studio). BODY.locations.json beside the OBJ overrides landmarks, "
     "axes\n"
     "and locations. --json prints {vertices, triangles, height_m, landmarks, torso_girths_m, "
     "axes,\n"
     "locations:[{name, center, axis, surface, ...}], sdf:{spacing_m, build_seconds, cached}}.",
     garment::cli::body_command},
    {"check",
     "check GARMENT.obj --pattern PATTERN.json[,MORE.json...] [--body BODY.obj] [--json] "
     "[--edge-length M]",
     "Measures a garment OBJ (as exported: one group per panel, vt = pattern coordinates)\n"
     "made from PATTERN.json (several, comma-separated: an outfit of `run`, groups GARMENT:PANEL) "
     "(meshed at --edge-length, default 0.02 m) on BODY.obj (default:\n"
     "the bundled body, resources/bodies/mean_all.obj) and prints every metric:\n"
     "body_inside_vertices (and max depth), body_crossing_edges, self_crossing_edges (cloth\n"
     "edges through cloth triangles, seams welded, with the pairs of pieces), folds\n"
     "(neighbour triangles with normal dot < -0.5; theta_in/theta_out), max_strain (and how\n"
     "far its edge is from the body), p99_strain, max_seam_gap_m, misplaced (pieces on the\n"
     "wrong side of the body; expected\n"
     "sides from the panel names), fails and ok. ok = nothing inside or crossing the body, no\n"
     "cloth crossing, no fold, strain <= 20 %, seam gap <= 5 mm, nothing misplaced. Exit 0\n"
     "when ok, 3 when not. --json prints one object.",
     garment::cli::check_command},
    {"flat", "flat PATTERN.json -o OUT.obj [--edge-length M] [--export KINDS]",
     "Writes the pieces flat where the pattern file places them (world = R(x, y, 0) +\n"
     "translation, R = Rz.Ry.Rx of the panel rotation), unsimulated: the state GarmentCode's\n"
     "simulator starts from, the reference to compare with. OBJ as exported (one group per\n"
     "panel, vt = pattern coordinates, metres). --export as in `run` (sewing-obj: the start\n"
     "for scripts/blender-drape).",
     garment::cli::flat_command},
    {"quilt", "quilt PATTERN.json --cell CM [--keep NAMES] -o OUT_specification.json",
     "Cuts every panel into cells of a grid CM centimetres apart (in the panel's own plane, each\n"
     "line moved by up to 0.3 cell to avoid slivers), sews neighbouring cells along every cut and\n"
     "splits the pattern's stitches and darts to match, so that each edge stays in one stitch:\n"
     "a GarmentCode specification with many pieces, for benchmarks and tests. A cell of panel\n"
     "NAME is NAME__rRcC and sits where its part of the panel sat. --keep a,b leaves whole the\n"
     "panels whose name contains a or b (trims: waistband,collar,cuff). Prints the piece count.",
     garment::cli::quilt_command},
    {"seed",
     "seed PATTERN.json [--body BODY.obj] [--json] [-o SEED.obj] [--seed-pieces a,b "
     "--seed-location NAME] [--weights FILE] [--edge-length M] [--parameters P.json]",
     "Classifies the pattern's pieces for seeding (paper §5.1): strips sewn side to side are\n"
     "merged into one seed piece (waist merge), then graph attention networks over the sewing\n"
     "graph (an ensemble of 3, probabilities averaged) give each piece a class (neck, waist,\n"
     "front_chest, back_chest, front_pelvis, back_pelvis, other) and its probabilities from\n"
     "shapes and seams. Then chooses the seed (§5): the waist piece (unless its chest pieces\n"
     "reach more than twice the body's waist-to-neck height from it: a long top's hem band),\n"
     "else the front and back chest pieces, else the neck piece (a collar), else the pelvis\n"
     "pieces, else the piece with the most garment below it (a waist or collar counts when its\n"
     "pieces close into a ring); a chest or pelvis piece named front or back goes to that side\n"
     "whatever its class says, and an open front's two halves (named left and right) go together\n"
     "as one part; --seed-pieces with --seed-location (one of the 15 body locations, see `body`)\n"
     "overrides it. The body (default: the bundled mean body) is the one the automatic seed is\n"
     "measured against; -o shapes the seed on it as the arrangement does (§5.2, the seed solve\n"
     "of `run`) and writes only the seed pieces as a garment OBJ (one group per seed panel,\n"
     "vt = pattern coordinates). --json prints\n"
     "{pieces:[{name, class, probabilities:{class: p}}], waist_merge:[[names]],\n"
     "seed:{pieces:[names], location, parts:[{pieces, location}], manual, reason}}; location\n"
     "joins the parts' locations with '+' (chest_front+chest_back). --weights defaults to\n"
     "resources/classifier/gat_weights.json.",
     garment::cli::seed_command},
    {"train-classifier",
     "train-classifier DATA_DIR -o WEIGHTS.json [--regions FILE] [--epochs N] [--ensemble N] "
     "[--seed N]",
     "Trains the seeding classifier on the GarmentCode patterns in DATA_DIR (labels from panel\n"
     "names by --regions, default DATA_DIR/../panel_regions.json; used for training only). Split:\n"
     "the file at position i of the name-sorted list is held out when i % 5 == 0, the other 80 %\n"
     "train. --ensemble networks (default 3) from seeds --seed, --seed+1, ...; their "
     "probabilities\n"
     "are averaged. Deterministic: same data and options, same weights. Prints the training time\n"
     "and the held-out report (as classify-eval).",
     garment::cli::train_classifier_command},
    {"classify-eval",
     "classify-eval DATA_DIR [--split held-out|training|all] [--weights FILE] [--regions FILE] "
     "[--json]",
     "Evaluates the seeding classifier on labelled patterns (default split: held-out; use --split\n"
     "all for pattern_generator_templates). Prints per-class precision/recall, the confusion\n"
     "matrix over seed pieces and the detection rates: neck-or-waist found = the pattern has a\n"
     "neck or waist piece and the piece ranked highest by p(neck)+p(waist) is one and is\n"
     "classified neck or waist; chest found = likewise with front/back chest; both chests = the\n"
     "top front-chest and top back-chest pieces are both right; false alarms on patterns without\n"
     "neck or waist.",
     garment::cli::classify_eval_command},
};

void print_help(std::ostream& out) {
  out << "usage: garment-init COMMAND [ARGS]\n\n"
         "Arranges the pieces of a sewing pattern around a body (Liu et al., SIGGRAPH 2024).\n\n"
         "Commands:\n";
  for (const Command& command : kCommands) {
    out << "  garment-init " << command.synopsis << "\n";
    std::string help = command.help;
    std::string line;
    for (char c : help + "\n") {
      if (c == '\n') {
        out << "      " << line << "\n";
        line.clear();
      } else {
        line += c;
      }
    }
    out << "\n";
  }
  out << "Exit status: 0 success, 1 bad input (the message names file and place), 2 bad usage\n"
         "(also an output that is an input, two outputs on one file, or an output that cannot be\n"
         "written: all checked before any work), 3 a garment was written but fails the quality\n"
         "check.\n";
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) {
    print_help(std::cerr);
    return garment::cli::kUsage;
  }
  if (args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    print_help(std::cout);
    return garment::cli::kSuccess;
  }
  for (const Command& command : kCommands) {
    if (args[0] != command.name) continue;
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    for (const std::string& word : rest) {
      if (word == "--help" || word == "-h") {
        std::cout << "usage: garment-init " << command.synopsis << "\n\n" << command.help << "\n";
        return garment::cli::kSuccess;
      }
    }
    try {
      return command.run(rest);
    } catch (const garment::cli::UsageError& error) {
      std::cerr << "garment-init " << command.name << ": " << error.what() << "\n"
                << "usage: garment-init " << command.synopsis << "\n";
      return garment::cli::kUsage;
    } catch (const garment::InputError& error) {
      std::cerr << "error: " << error.what() << "\n";
      return garment::cli::kBadInput;
    } catch (const std::bad_alloc&) {
      std::cerr << "error: out of memory\n";
      return garment::cli::kBadInput;
    } catch (const std::exception& error) {
      std::cerr << "error: " << error.what() << "\n";
      return garment::cli::kBadInput;
    }
  }
  std::cerr << "garment-init: unknown command '" << args[0] << "' (see garment-init --help)\n";
  return garment::cli::kUsage;
}
