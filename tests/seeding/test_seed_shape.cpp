// The seed shape (paper §5.2, issue 6 item 8): the automatic seed of a skirt waistband, a trouser
// waistband and a shirt's chest pieces, shaped on each of the three body shapes (the bundled
// mean_all and the SMPL female and male averages, tests/data/bodies). Each body gets patterns that
// GarmentCode made for it (DESIGN.md: a pattern is evaluated on its own body), so a waistband is
// cut for the waist it goes around. Checks, each measured independently of the solver:
//   outside   every seed vertex outside the body: exact signed distance (ExactBodyDistance, not the
//             grid the solver uses) > 0
//   centred   the centroid of each seed part within 3 cm of its location's centre. The centroid is
//             area-weighted (triangle centroids × rest area). For a cylinder location (waist) the
//             part is a ring around the axis: its centroid is the ring's centre on the axis, so the
//             offset splits into a height (along the axis) and a horizontal part (off the axis),
//             both reported. For a plane location (chest front/back) the offset is taken in the
//             plane (across and up): a part that wraps round the torso, as a bodice front does to
//             its side seams, has its centroid some centimetres behind the plane (the depth, also
//             reported, is the body's business: see `outside`).
//   upright   each seed piece's up (its frame's upright direction, panel-local → rest frame) mapped
//             through every triangle's deformation gradient, against world up as seen in that
//             triangle's plane (cloth lying on a sloping chest or back cannot point straight up):
//             the angle between the two area-weighted sums within 20°. The angle to world up in
//             space, the surface's slope included, is reported as the tilt
//   no folds  smallest dot of the normals of neighbour triangles inside a seed piece > −0.5 (the
//             quality report's folds); across the seams among the seed pieces (seams welded, Eq.
//             13's theta_out) it is reported, not checked: a seam still open over a shoulder
//             makes its two sides "neighbours" facing opposite ways
// The figures are printed (qInfo) for the report.

#include <QtTest>

#include <Eigen/Geometry>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "engine/arrange/arrangement_parameters.h"
#include "engine/body/default_body.h"
#include "engine/body/exact_body_distance.h"
#include "engine/core/mesh_topology.h"
#include "engine/io/garment_obj.h"
#include "engine/pattern/garment_mesh.h"
#include "engine/quality/exact_intersections.h"
#include "engine/quality/piece_placement.h"
#include "engine/seeding/scene.h"
#include "engine/seeding/seed_choice.h"
#include "engine/seeding/seed_shape.h"
#include "support/test_paths.h"

using namespace garment;

namespace {

struct Figures {
  double min_distance = 1e30;        // m, exact signed distance of the seed's vertices
  double centroid_offset = 0.0;      // m, the largest over the parts
  double height_offset = 0.0;        // m, cylinder parts: along the axis (signed, largest |.|)
  double radial_offset = 0.0;        // m, cylinder parts: off the axis
  double depth_offset = 0.0;         // m, plane parts: along the normal (signed, largest |.|)
  double min_seam_normal_dot = 1.0;  // across the seams among the seed pieces (theta_out)
  double upright_degrees = 0.0;      // the largest over the seed pieces, in the surface
  double tilt_degrees = 0.0;         // the same in space, the surface's own slope included
  double min_normal_dot = 1.0;
  double seconds = 0.0;
  int iterations = 0;
};

Eigen::Vector3d triangle_normal(const Eigen::MatrixX3d& x, const Eigen::Vector3i& t) {
  return (x.row(t[1]) - x.row(t[0])).transpose().cross((x.row(t[2]) - x.row(t[0])).transpose());
}

double rest_area(const Garment& garment, const Eigen::Vector3i& t) {
  const Eigen::Vector2d a = garment.rest_positions.row(t[1]) - garment.rest_positions.row(t[0]);
  const Eigen::Vector2d b = garment.rest_positions.row(t[2]) - garment.rest_positions.row(t[0]);
  return 0.5 * std::abs(a.x() * b.y() - a.y() * b.x());
}

Figures measure_seed(const Scene& scene, const SeedPlan& plan, const Eigen::MatrixX3d& x) {
  const Garment& garment = *scene.garment;
  Figures figures;

  // Outside: exact signed distance of every seed vertex.
  const ExactBodyDistance exact(scene.body->mesh);
  for (int piece : plan.pieces()) {
    const Piece& info = garment.pieces[piece];
    for (int v = info.first_vertex; v < info.first_vertex + info.vertex_count; ++v)
      figures.min_distance =
          std::min(figures.min_distance, exact.signed_distance(x.row(v).transpose()));
  }

  // Centred: area-weighted centroid of each part against its location's centre.
  for (const SeedPart& part : plan.parts) {
    const BodyLocation& location = scene.body->location(part.location);
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    double area = 0.0;
    for (int piece : part.pieces) {
      const Piece& info = garment.pieces[piece];
      for (int t = info.first_triangle; t < info.first_triangle + info.triangle_count; ++t) {
        const Eigen::Vector3i tri = garment.triangles.row(t);
        const double a = rest_area(garment, tri);
        sum += a * (x.row(tri[0]) + x.row(tri[1]) + x.row(tri[2])).transpose() / 3.0;
        area += a;
      }
    }
    const Eigen::Vector3d offset = sum / area - location.center;
    const Eigen::Vector3d axis = location.axis.normalized();
    const double along = offset.dot(axis);
    if (location.surface == LocationSurface::cylinder) {
      figures.centroid_offset = std::max(figures.centroid_offset, offset.norm());
      if (std::abs(along) > std::abs(figures.height_offset)) figures.height_offset = along;
      figures.radial_offset = std::max(figures.radial_offset, (offset - along * axis).norm());
    } else {
      figures.centroid_offset = std::max(figures.centroid_offset, (offset - along * axis).norm());
      if (std::abs(along) > std::abs(figures.depth_offset)) figures.depth_offset = along;
      const double up = offset.dot(location.up.normalized());
      if (std::abs(up) > std::abs(figures.height_offset)) figures.height_offset = up;
      figures.radial_offset =
          std::max(figures.radial_offset,
                   std::sqrt(std::max(0.0, (offset - along * axis).squaredNorm() - up * up)));
    }
  }

  // Upright: the piece's up through each triangle's map rest → world, area-weighted.
  for (int piece : plan.pieces()) {
    const Piece& info = garment.pieces[piece];
    const Eigen::Vector2d up_rest =
        (info.frame.local_to_rest * info.frame.upright_local).normalized();
    Eigen::Vector3d mapped = Eigen::Vector3d::Zero();
    Eigen::Vector3d up_on_surface = Eigen::Vector3d::Zero();
    for (int t = info.first_triangle; t < info.first_triangle + info.triangle_count; ++t) {
      const Eigen::Vector3i tri = garment.triangles.row(t);
      Eigen::Matrix2d rest;
      rest.col(0) =
          (garment.rest_positions.row(tri[1]) - garment.rest_positions.row(tri[0])).transpose();
      rest.col(1) =
          (garment.rest_positions.row(tri[2]) - garment.rest_positions.row(tri[0])).transpose();
      Eigen::Matrix<double, 3, 2> world;
      world.col(0) = (x.row(tri[1]) - x.row(tri[0])).transpose();
      world.col(1) = (x.row(tri[2]) - x.row(tri[0])).transpose();
      const double area = 0.5 * std::abs(rest.determinant());
      if (area <= 0.0) continue;
      const Eigen::Vector3d up_world = world * rest.inverse() * up_rest;
      mapped += area * up_world;
      // World up as seen in the triangle's plane: what the piece's up can point to while it lies
      // on a sloping surface (a bust, the small of the back, a shoulder).
      const Eigen::Vector3d normal = world.col(0).cross(world.col(1)).normalized();
      const Eigen::Vector3d up_in_plane =
          Eigen::Vector3d::UnitY() - Eigen::Vector3d::UnitY().dot(normal) * normal;
      if (up_in_plane.norm() < 1e-6 || up_world.norm() < 1e-12) continue;
      up_on_surface += area * up_in_plane.normalized();
    }
    const double cosine = std::clamp(mapped.normalized().y(), -1.0, 1.0);
    figures.tilt_degrees =
        std::max(figures.tilt_degrees, std::acos(cosine) * 180.0 / std::numbers::pi);
    const double in_surface_cosine =
        std::clamp(mapped.normalized().dot(up_on_surface.normalized()), -1.0, 1.0);
    figures.upright_degrees =
        std::max(figures.upright_degrees, std::acos(in_surface_cosine) * 180.0 / std::numbers::pi);
  }

  // No folds: neighbour triangles inside the seed's pieces (the quality report's folds); the same
  // across the seams among the seed pieces (seams welded; Eq. 13's theta_out), reported.
  const Eigen::VectorXi welded = welded_vertices(garment);
  std::vector<int> seed_triangles;
  for (int piece : plan.pieces()) {
    const Piece& info = garment.pieces[piece];
    for (int t = info.first_triangle; t < info.first_triangle + info.triangle_count; ++t)
      seed_triangles.push_back(t);
  }
  Eigen::MatrixX3i joined(static_cast<Eigen::Index>(seed_triangles.size()), 3);
  for (std::size_t i = 0; i < seed_triangles.size(); ++i)
    for (int k = 0; k < 3; ++k)
      joined(static_cast<Eigen::Index>(i), k) = welded[garment.triangles(seed_triangles[i], k)];
  const MeshEdges edges = build_mesh_edges(joined, garment.vertex_count());
  for (Eigen::Index e = 0; e < edges.edges.rows(); ++e) {
    const int a = edges.edge_triangles(e, 0), b = edges.edge_triangles(e, 1);
    if (a < 0 || b < 0) continue;
    const int ta = seed_triangles[a], tb = seed_triangles[b];
    const double dot = triangle_normal(x, garment.triangles.row(ta))
                           .normalized()
                           .dot(triangle_normal(x, garment.triangles.row(tb)).normalized());
    double& smallest = garment.triangle_piece[ta] == garment.triangle_piece[tb]
                           ? figures.min_normal_dot
                           : figures.min_seam_normal_dot;
    smallest = std::min(smallest, dot);
  }
  return figures;
}

std::string part_list(const Garment& garment, const SeedPlan& plan) {
  std::string text;
  for (const SeedPart& part : plan.parts) {
    std::string names;
    for (int piece : part.pieces)
      names += (names.empty() ? "" : "+") + garment.pieces[piece].name;
    text += (text.empty() ? "" : ", ") + names + " -> " + part.location;
  }
  return text;
}

}  // namespace

class SeedShapeTest : public QObject {
  Q_OBJECT

  std::map<std::string, std::shared_ptr<const Body>> bodies;

  std::shared_ptr<const Body> load(const std::string& name) {
    auto& loaded = bodies[name];
    if (!loaded) {
      const std::filesystem::path path =
          name == "mean_all" ? default_body_path() : test::test_data("bodies/" + name + ".obj");
      loaded = std::make_shared<const Body>(load_body(path));
    }
    return loaded;
  }

  // The pattern `pattern` (under tests/data) meshed, its scene on the body `body` and the seed
  // chosen for it automatically.
  struct Seeded {
    std::shared_ptr<const Garment> garment;
    std::shared_ptr<const Scene> scene;
    SeedPlan plan;
  };
  Seeded seeded(const std::string& body, const std::string& pattern) {
    auto garment =
        std::make_shared<const Garment>(build_garment(load_pattern(test::test_data(pattern))));
    std::shared_ptr<const Scene> scene = make_scene(garment, load(body));
    const BodyLandmarks& landmarks = scene->body->landmarks;
    SeedPlan plan = choose_seed(*garment, scene->classification, landmarks.neck - landmarks.waist);
    return {std::move(garment), std::move(scene), std::move(plan)};
  }

 private slots:
  void shape_data() {
    QTest::addColumn<QString>("body_name");
    QTest::addColumn<QString>("pattern_file");   // under tests/data
    QTest::addColumn<QStringList>("locations");  // the automatic seed's parts
    struct Row {
      const char *body, *kind, *pattern;
      QStringList locations;
    };
    const QStringList waist{"waist"}, chest{"chest_front", "chest_back"};
    const Row rows[] = {
        {"mean_all", "skirt waistband", "seeding/garmentcode_random/gc_0130_specification.json",
         waist},
        {"mean_all", "trouser waistband", "seeding/garmentcode_random/gc_0115_specification.json",
         waist},
        {"mean_all", "shirt chest", "seeding/garmentcode_random/gc_0225_specification.json", chest},
        {"f_smpl_average_A40", "skirt waistband",
         "seeding/garmentcode_random/gc_0080_specification.json", waist},
        {"f_smpl_average_A40", "trouser waistband",
         "seeding/garmentcode_random/gc_0240_specification.json", waist},
        {"f_smpl_average_A40", "shirt chest", "patterns/gc_0022_specification.json", chest},
        {"m_smpl_average_A40", "skirt waistband",
         "seeding/garmentcode_random/gc_0195_specification.json", waist},
        {"m_smpl_average_A40", "trouser waistband", "patterns/gc_0473_specification.json", waist},
        {"m_smpl_average_A40", "shirt chest", "patterns/gc_0037_specification.json", chest},
    };
    for (const Row& row : rows)
      QTest::newRow((std::string(row.body) + " / " + row.kind).c_str())
          << QString(row.body) << QString(row.pattern) << row.locations;
  }

  void shape() {
    QFETCH(QString, body_name);
    QFETCH(QString, pattern_file);
    QFETCH(QStringList, locations);
    const std::string body = body_name.toStdString(), pattern = pattern_file.toStdString();
    const auto [garment, scene, plan] = seeded(body, pattern);
    QStringList chosen;
    for (const SeedPart& part : plan.parts)
      chosen << QString::fromStdString(part.location);
    QVERIFY2(chosen == locations, part_list(*garment, plan).c_str());

    const ArrangementParameters parameters;
    SeedShapeOptions options;
    options.iterations = parameters.seed_iterations;
    Eigen::MatrixX3d positions = scene->initial_positions;
    // SEED_SHAPE_DUMP=DIR writes the seed every 50 iterations, to look at a failure.
    const QByteArray dump = qgetenv("SEED_SHAPE_DUMP");
    int iteration = 0;
    std::string stem = body + "_" + std::filesystem::path(pattern).stem().string();
    const auto on_iterate = [&](const Eigen::MatrixX3d& x) {
      if (iteration++ % 50 == 0)
        write_garment_obj(std::filesystem::path(dump.toStdString()) /
                              (stem + "_" + std::to_string(iteration - 1) + ".obj"),
                          *garment, x, plan.pieces());
    };
    const SeedShapeReport report = shape_seed(
        *scene, plan, parameters.energy, positions, nullptr,
        dump.isEmpty() ? std::function<void(const Eigen::MatrixX3d&)>() : on_iterate, options);
    if (!dump.isEmpty())
      write_garment_obj(std::filesystem::path(dump.toStdString()) / (stem + "_final.obj"), *garment,
                        positions, plan.pieces());
    const Figures f = measure_seed(*scene, plan, positions);
    const bool ring =
        scene->body->location(plan.parts.front().location).surface == LocationSurface::cylinder;
    const QString centroid = ring ? QString("height %1, off axis %2")
                                        .arg(1000.0 * f.height_offset, 0, 'f', 1)
                                        .arg(1000.0 * f.radial_offset, 0, 'f', 1)
                                  : QString("in the plane: up %1, across %2; depth %3")
                                        .arg(1000.0 * f.height_offset, 0, 'f', 1)
                                        .arg(1000.0 * f.radial_offset, 0, 'f', 1)
                                        .arg(1000.0 * f.depth_offset, 0, 'f', 1);
    qInfo(
        "%s | %s: %s | min distance %.1f mm, centroid offset %.1f mm (%s), upright %.1f deg (tilt "
        "%.1f deg), "
        "min normal dot %.3f (across seams %.3f) | %d iterations, %.2f s",
        body.c_str(), pattern.c_str(), part_list(*garment, plan).c_str(), 1000.0 * f.min_distance,
        1000.0 * f.centroid_offset, qPrintable(centroid), f.upright_degrees, f.tilt_degrees,
        f.min_normal_dot, f.min_seam_normal_dot, report.iterations, report.seconds);
    QStringList failed;
    if (!(f.min_distance > 0.0)) failed << "a seed vertex is inside the body";
    if (!(f.centroid_offset <= 0.03)) failed << "the centroid is more than 3 cm from the location";
    if (!(f.upright_degrees <= 20.0)) failed << "a piece is more than 20 degrees off upright";
    if (!(f.min_normal_dot > -0.5)) failed << "a piece folds";
    QVERIFY2(failed.isEmpty(), qPrintable(failed.join("; ")));
  }

  // gc_0339's "collar" is a lapel (two strips down the front, two flat bands on the shoulders),
  // which the classifier takes for neck pieces; it does not close round the neck, so the chest
  // pieces are the seed.
  void lapel_collar_is_not_the_seed() {
    const auto [garment, scene, plan] = seeded("mean_all", "patterns/gc_0339_specification.json");
    const int collar = garment->pattern.panel_index("left_collar_front");
    QCOMPARE(scene->classification.group_class(scene->classification.piece_group[collar]),
             SeedClass::Neck);
    QStringList chosen;
    for (const SeedPart& part : plan.parts)
      chosen << QString::fromStdString(part.location);
    QCOMPARE(chosen, (QStringList{"chest_front", "chest_back"}));
  }

  // A collar in four pieces (left and right, front and back, sewn end to end into a ring) starts
  // wrapped round the neck with the seam between its two front pieces in front: each piece on
  // its side of the body, front or back and left or right as its name says (the body faces +z,
  // its left is +x), measured at the piece's area centroid against the neck location's centre.
  void collar_ring_starts_facing_front_data() {
    QTest::addColumn<QString>("body_name");
    QTest::addColumn<QString>("pattern_file");
    QTest::newRow("mean_all") << "mean_all"
                              << "seeding/garmentcode_random/gc_0405_specification.json";
    QTest::newRow("m_smpl_average_A40") << "m_smpl_average_A40"
                                        << "seeding/garmentcode_random/gc_0410_specification.json";
  }

  void collar_ring_starts_facing_front() {
    QFETCH(QString, body_name);
    QFETCH(QString, pattern_file);
    const auto [garment, scene, automatic] =
        seeded(body_name.toStdString(), pattern_file.toStdString());
    // The automatic seed of both is another part (gc_0405's waistband, gc_0410's chest pieces,
    // which come before a collar): the collar is seeded here as the classifier's neck pieces, as
    // a user's manual seed would.
    SeedPlan plan;
    plan.parts.push_back({{}, "neck"});
    for (int piece = 0; piece < static_cast<int>(garment->pieces.size()); ++piece)
      if (scene->classification.group_class(scene->classification.piece_group[piece]) ==
          SeedClass::Neck)
        plan.parts.front().pieces.push_back(piece);
    QCOMPARE(plan.parts.front().pieces.size(), std::size_t(4));
    QVERIFY(automatic.parts.front().location != "neck");
    Eigen::MatrixX3d positions = scene->initial_positions;
    place_seed_on_surfaces(*scene, plan, ArrangementParameters().energy.body_distance, positions);
    const Eigen::MatrixX3d centroids = piece_centroids(*garment, positions);
    const Eigen::Vector3d neck = scene->body->location("neck").center;
    for (int piece : plan.parts.front().pieces) {
      const std::string& name = garment->pieces[piece].name;
      const Eigen::Vector3d offset = centroids.row(piece).transpose() - neck;
      qInfo("%s: %s at x %+.1f cm, z %+.1f cm from the neck's centre", qPrintable(body_name),
            name.c_str(), 100.0 * offset.x(), 100.0 * offset.z());
      const bool front = name.find("front") != std::string::npos;
      const bool left = name.find("left") != std::string::npos;
      QVERIFY2(front == (offset.z() > 0.0), name.c_str());
      QVERIFY2(left == (offset.x() > 0.0), name.c_str());
    }
  }

  // gc_0432 (a skirt of 13 panels named skirt_panel_<N> under a waistband of wb_front and
  // wb_back, made for mean_all): its automatic seed is the waistband, and the classifier takes
  // the unnamed panels sewn to it for front and back alike. The band starts wrapped round the
  // waist with wb_front in front of the body (+z) and wb_back behind, measured at each piece's
  // area centroid against the waist location's centre. It started turned round (both pieces
  // misplaced in the quality report) while the neighbours alone decided.
  void named_waistband_starts_facing_its_sides() {
    const auto [garment, scene, plan] =
        seeded("mean_all", "patterns/named_waistband/gc_0432_specification.json");
    QCOMPARE(plan.parts.size(), std::size_t(1));
    QCOMPARE(plan.parts.front().location, std::string("waist"));
    Eigen::MatrixX3d positions = scene->initial_positions;
    place_seed_on_surfaces(*scene, plan, ArrangementParameters().energy.body_distance, positions);
    const Eigen::MatrixX3d centroids = piece_centroids(*garment, positions);
    const Eigen::Vector3d waist = scene->body->location("waist").center;
    QStringList placed;
    for (int piece : plan.parts.front().pieces) {
      const std::string& name = garment->pieces[piece].name;
      const double depth = centroids(piece, 2) - waist.z();
      qInfo("%s at z %+.1f cm from the waist's centre", name.c_str(), 100.0 * depth);
      placed << QString::fromStdString(name);
      QVERIFY2((name == "wb_front") == (depth > 0.0), name.c_str());
    }
    placed.sort();
    QCOMPARE(placed, (QStringList{"wb_back", "wb_front"}));
  }

  // gc_0276 (a sleeveless top with a straight waistband, made for m_smpl_average_A40) is a long
  // top: its torso pieces are 1.06 m tall, the band sewn to their hem. The classifier takes the
  // band for a waist piece, but on the body it cannot be at the waist, 0.365 m below the neck:
  // the chest pieces are the seed. Without a body to measure against, the band would be. gc_0299
  // (the same kind of top, 0.49 m tall, made for mean_all) keeps its band at the waist.
  void long_tops_hem_band_is_no_waist_seed() {
    const auto [garment, scene, plan] =
        seeded("m_smpl_average_A40", "patterns/hem_band/gc_0276_specification.json");
    QCOMPARE(part_list(*garment, plan), std::string("right_ftorso+left_ftorso -> chest_front, "
                                                    "right_btorso+left_btorso -> chest_back"));
    QCOMPARE(part_list(*garment, choose_seed(*garment, scene->classification)),
             std::string("wb_back+wb_front -> waist"));
    const auto [short_top, short_scene, short_plan] =
        seeded("mean_all", "patterns/hem_band/gc_0299_specification.json");
    QCOMPARE(part_list(*short_top, short_plan), std::string("wb_back+wb_front -> waist"));
  }

  // gc_0109 (a skirt whose front and back each hold two godets, made for mean_all) is seeded as
  // its front and back at the pelvis, pieces not named for a side of the body (no trouser legs).
  // Below the crotch no body lies between the legs: drawn to the body there, the two met in the
  // gap and crossed, 25 to 33 cm below the crotch (42 edges
  // of one through triangles of the other). Shaped, the seed pieces have no cloth-cloth contact
  // below the crotch (exact edge-triangle tests, seams welded).
  void skirt_seed_stays_out_of_the_gap_between_the_legs() {
    const auto [garment, scene, plan] =
        seeded("mean_all", "patterns/godet_skirt/gc_0109_specification.json");
    QStringList locations;
    for (const SeedPart& part : plan.parts)
      locations << QString::fromStdString(part.location);
    QCOMPARE(locations, (QStringList{"pelvis_front", "pelvis_back"}));
    const ArrangementParameters parameters;
    SeedShapeOptions options;
    options.iterations = parameters.seed_iterations;
    Eigen::MatrixX3d positions = scene->initial_positions;
    shape_seed(*scene, plan, parameters.energy, positions, nullptr, {}, options);

    std::vector<bool> in_seed(garment->pieces.size(), false);
    for (int piece : plan.pieces())
      in_seed[piece] = true;
    const MeshEdges mesh = build_mesh_edges(garment->triangles, garment->vertex_count());
    const double crotch = scene->body->landmarks.crotch;
    int below = 0, crossing = 0;
    for (int v = 0; v < garment->vertex_count(); ++v)
      below += in_seed[garment->vertex_piece(v)] && positions(v, 1) < crotch;
    for (const Eigen::Vector2i& contact : edge_triangle_contacts(
             positions, mesh.edges, garment->triangles, welded_vertices(*garment))) {
      const int a = mesh.edges(contact.x(), 0), b = mesh.edges(contact.x(), 1);
      crossing += in_seed[garment->vertex_piece(a)] &&
                  in_seed[garment->triangle_piece(contact.y())] &&
                  std::min(positions(a, 1), positions(b, 1)) < crotch;
    }
    qInfo("%d seed vertices below the crotch, %d seed edges through seed cloth there", below,
          crossing);
    QVERIFY(below > 100);
    QCOMPARE(crossing, 0);
  }

  // gc_0097's bodice wrapped round mean_all starts with an armhole corner in the arm and ends
  // stretched round it (about 190 %, measured before the fallback existed): the seed is shaped
  // again from the next start, and what is kept stretches no edge by more than half its rest
  // length (edge strain computed here from the rest positions).
  void caught_seed_is_shaped_again() {
    const auto [garment, scene, plan] =
        seeded("mean_all", "patterns/caught_seed/gc_0097_specification.json");
    QCOMPARE(plan.parts.size(), std::size_t{2});
    const ArrangementParameters parameters;
    SeedShapeOptions options;
    options.iterations = parameters.seed_iterations;
    Eigen::MatrixX3d positions = scene->initial_positions;
    const SeedShapeReport report =
        shape_seed(*scene, plan, parameters.energy, positions, nullptr, {}, options);
    double worst = 0.0;
    for (int piece : plan.pieces())
      for (int t = 0; t < garment->triangle_count(); ++t) {
        if (garment->triangle_piece(t) != piece) continue;
        for (int k = 0; k < 3; ++k) {
          const int a = garment->triangles(t, k), b = garment->triangles(t, (k + 1) % 3);
          const double rest =
              (garment->rest_positions.row(a) - garment->rest_positions.row(b)).norm();
          worst = std::max(worst, (positions.row(a) - positions.row(b)).norm() / rest - 1.0);
        }
      }
    qInfo("%d starts, max edge strain %.1f %% (report %.1f %%)", report.attempts, 100.0 * worst,
          100.0 * report.max_strain);
    QVERIFY(report.attempts >= 2);
    QVERIFY2(worst <= options.broken_strain, qPrintable(QString::number(worst)));
    QVERIFY(std::abs(worst - report.max_strain) < 1e-9);
  }

  // Front and back chest parts start wrapped round the torso, so that both side seams start
  // closed under the arms; on the two chest planes they would start a torso's depth apart and pull
  // the armpit corners through the arms.
  void chest_side_seams_start_together_data() {
    QTest::addColumn<QString>("body_name");
    QTest::addColumn<QString>("pattern_file");
    QTest::newRow("mean_all") << "mean_all"
                              << "seeding/garmentcode_random/gc_0225_specification.json";
    QTest::newRow("f_smpl_average_A40") << "f_smpl_average_A40"
                                        << "patterns/gc_0022_specification.json";
    QTest::newRow("m_smpl_average_A40") << "m_smpl_average_A40"
                                        << "patterns/gc_0037_specification.json";
  }

  void chest_side_seams_start_together() {
    QFETCH(QString, body_name);
    QFETCH(QString, pattern_file);
    const auto [garment, scene, plan] = seeded(body_name.toStdString(), pattern_file.toStdString());
    QCOMPARE(plan.parts.size(), std::size_t(2));
    Eigen::MatrixX3d positions = scene->initial_positions;
    place_seed_on_surfaces(*scene, plan, ArrangementParameters().energy.body_distance, positions);
    const auto in = [](const std::vector<int>& pieces, int piece) {
      return std::find(pieces.begin(), pieces.end(), piece) != pieces.end();
    };
    // The seams between the two parts, as the mean distance of their sewing pairs, and whether
    // they run up (side seams) or across (shoulder seams) in the pattern.
    std::vector<double> side_gaps;
    for (const StitchPairs& stitch : garment->stitches) {
      if (stitch.pair_count < 2) continue;
      const int a = garment->sewing_pairs(stitch.first_pair, 0);
      const int b = garment->sewing_pairs(stitch.first_pair, 1);
      const int piece_a = garment->vertex_piece(a), piece_b = garment->vertex_piece(b);
      const bool across_parts =
          (in(plan.parts[0].pieces, piece_a) && in(plan.parts[1].pieces, piece_b)) ||
          (in(plan.parts[1].pieces, piece_a) && in(plan.parts[0].pieces, piece_b));
      if (!across_parts) continue;
      const int last = garment->sewing_pairs(stitch.first_pair + stitch.pair_count - 1, 0);
      const Eigen::Vector2d run =
          garment->rest_positions.row(last) - garment->rest_positions.row(a);
      if (std::abs(run.y()) < std::abs(run.x())) continue;  // a shoulder seam
      double gap = 0.0;
      for (int k = stitch.first_pair; k < stitch.first_pair + stitch.pair_count; ++k)
        gap += (positions.row(garment->sewing_pairs(k, 0)) -
                positions.row(garment->sewing_pairs(k, 1)))
                   .norm();
      side_gaps.push_back(gap / stitch.pair_count);
    }
    QString gaps;
    for (double gap : side_gaps)
      gaps += QString(" %1").arg(1000.0 * gap, 0, 'f', 1);
    qInfo("%s: side seam gaps at the start (mm):%s", qPrintable(body_name), qPrintable(gaps));
    QCOMPARE(side_gaps.size(), std::size_t(2));
    for (double gap : side_gaps)
      QVERIFY2(gap < 0.05, qPrintable(gaps));
  }
};

QTEST_APPLESS_MAIN(SeedShapeTest)
#include "test_seed_shape.moc"
