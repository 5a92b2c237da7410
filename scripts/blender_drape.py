"""Drapes a garment on a body with Blender's cloth (run by scripts/blender-drape, which documents
the arguments). Runs inside Blender: blender -b --factory-startup --python blender_drape.py -- ARGS.

The garment OBJ is the one `garment-init run --export sewing-obj` (or `flat --export sewing-obj`)
writes: unwelded pieces, one group per panel, `vt` = pattern coordinates, and `l i j` lines that
sew vertex i to vertex j. The OBJ is parsed here rather than through Blender's importer, which
splits objects by group and may reorder vertices: `garment-init check` matches the draped OBJ to
the pattern by groups and `vt`, so the output is the input text with only the `v` lines replaced,
in the input's vertex order. The `l` lines are kept (check ignores them), so a draped garment can
be draped again.

Coordinates stay as the files have them (metres, y up); gravity points down y.
"""

import argparse
import sys
import time

import bpy


def parse_arguments():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    parser = argparse.ArgumentParser(prog="blender-drape")
    parser.add_argument("garment", help="garment OBJ with sewing lines (metres)")
    parser.add_argument("body", help="body OBJ (metres)")
    parser.add_argument("output", help="draped garment OBJ")
    parser.add_argument("--frames", type=int, default=120)
    # Blender's defaults (cloth 15 mm, body 20 mm) push cloth that lies 3 mm from the body out
    # at the first frame, and it comes back tangled and through the body. The two distances seem
    # to add up: at 5 mm each, gc_0004's top kept 6 mm from the body (run --clearance 6) came out
    # tangled, kept 12 mm it stayed clean; gc_0002's trousers came out through the body at 6 mm
    # and with only the strain they had before at 12 mm. So both added must stay under the
    # clearance the garment keeps from the body (3 mm by default).
    parser.add_argument("--collision-distance", type=float, default=0.001,
                        help="the cloth's and the body's collision distance, m (default 0.001)")
    parser.add_argument("--quality", type=int, default=5, help="cloth quality steps per frame")
    parser.add_argument("--stiffness", type=float, default=15.0,
                        help="tension stiffness, and compression's unless --compression"
                             " (Blender's default 15)")
    parser.add_argument("--bending", type=float, default=0.5,
                        help="bending stiffness (Blender's default 0.5)")
    # Blender's default 0.3 kg a vertex makes a garment of 2,000 vertices weigh 600 kg: the
    # springs give way and the cloth sinks into the body; 10 g did not do either (gc_0000: 460
    # vertices inside). 1 g (3.2 to 3.8 kg/m² at the 2 cm mesh) kept 10 of the 15 shared garments
    # clean before Blender clean. 0.1 g, 320 to 380 g/m² (a denim), sags and slides less:
    # gc_0006, gc_0016 and gc_0024 stayed clean too (docs/blender-drape.md).
    parser.add_argument("--mass", type=float, default=0.0001,
                        help="vertex mass, kg (default 0.0001; Blender's 0.3)")
    # Off in Blender's default; without it, at 0.1 g a vertex, gc_0044's two flared trouser hems
    # passed through each other between the legs (32 edges).
    parser.add_argument("--self-collision", action=argparse.BooleanOptionalAction, default=True,
                        help="cloth collides with itself (default on; off in Blender's default)")
    # Options tried for issue 44 that are not defaults (docs/blender-drape.md has the figures).
    # Cloth buckles rather than resists being shortened: a lower compression stiffness should let
    # the longer side of a gathered seam gather instead of stretching the shorter one.
    parser.add_argument("--compression", type=float, default=None,
                        help="compression stiffness (default: --stiffness)")
    # Collision iterations a step (Blender's "Collisions > Quality").
    parser.add_argument("--collision-quality", type=int, default=2,
                        help="collision iterations a step (Blender's default 2)")
    # Blender's "Single Sided": the body pushes cloth out along its normals (the bodies are closed
    # meshes with outward normals).
    parser.add_argument("--single-sided", action="store_true",
                        help="body collision along the body's normals (Blender's Single Sided)")
    # The cloth's collision friction and the body's cloth friction (Blender's defaults 5 and 5).
    parser.add_argument("--friction", type=float, default=5.0,
                        help="cloth-body friction, the cloth's and the body's (Blender's 5)")
    # Blender takes the springs' rest lengths from the mesh it is given, here the arranged
    # garment, whose edges may already be stretched (up to the 20 % `check` allows). "pattern"
    # rests them at the pattern's lengths instead (the OBJ's `vt`, 100 units a metre), the
    # lengths `check` measures strain against; the cloth then contracts hard onto the body.
    parser.add_argument("--rest", choices=("arranged", "pattern"), default="arranged",
                        help="rest lengths of the springs: the input's shape or the pattern's")
    return parser.parse_args(argv)


def read_obj(path):
    """Vertices, triangles (and polygons), sewing lines, the text's lines, and each vertex's
    texture coordinates (the pattern's, for the garment)."""
    with open(path, encoding="utf-8") as file:
        lines = file.read().splitlines()
    vertices, faces, edges, uvs, vertex_uv = [], [], [], [], {}
    for line in lines:
        words = line.split()
        if not words:
            continue
        if words[0] == "v":
            vertices.append(tuple(float(w) for w in words[1:4]))
        elif words[0] == "vt":
            uvs.append((float(words[1]), float(words[2])))
        elif words[0] == "f":
            faces.append([int(w.split("/")[0]) - 1 for w in words[1:]])
            for w in words[1:]:
                ids = w.split("/")
                if len(ids) > 1 and ids[1]:
                    vertex_uv[int(ids[0]) - 1] = uvs[int(ids[1]) - 1]
        elif words[0] == "l":
            ids = [int(w.split("/")[0]) - 1 for w in words[1:]]
            edges.extend(zip(ids, ids[1:]))
    return vertices, faces, edges, lines, vertex_uv


def add_object(name, vertices, faces, edges=()):
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(vertices, list(edges), faces)
    mesh.validate()
    if len(mesh.vertices) != len(vertices):
        raise SystemExit(f"{name}: Blender changed the vertex count")
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(obj)
    return obj


def main():
    args = parse_arguments()
    start = time.time()
    for obj in list(bpy.data.objects):  # the factory scene's cube, camera and light
        bpy.data.objects.remove(obj)
    scene = bpy.context.scene
    scene.gravity = (0.0, -9.81, 0.0)  # the OBJs are y up
    scene.frame_start, scene.frame_end = 1, args.frames

    vertices, faces, sewing, lines, vertex_uv = read_obj(args.garment)
    body_vertices, body_faces, _, _, _ = read_obj(args.body)
    garment = add_object("garment", vertices, faces, sewing)
    body = add_object("body", body_vertices, body_faces)

    body.modifiers.new("Collision", "COLLISION")
    body.collision.thickness_outer = args.collision_distance
    # Blender documents the inner thickness as used by soft bodies only; kept at 2 cm rather
    # than the default 0.2 m (more than an arm is thick) in case it is not.
    body.collision.thickness_inner = 0.02
    body.collision.damping = 0.1
    body.collision.use_culling = args.single_sided
    body.collision.cloth_friction = args.friction

    cloth = garment.modifiers.new("Cloth", "CLOTH")
    settings = cloth.settings
    if args.rest == "pattern":
        if len(vertex_uv) != len(vertices):
            raise SystemExit("--rest pattern: a vertex has no texture coordinates")
        garment.shape_key_add(name="arranged")
        rest = garment.shape_key_add(name="pattern", from_mix=False)
        for i, point in enumerate(rest.data):
            u, v = vertex_uv[i]
            point.co = (u / 100.0, v / 100.0, 0.0)
        settings.rest_shape_key = rest
    settings.quality = args.quality
    settings.mass = args.mass
    settings.tension_stiffness = args.stiffness
    settings.compression_stiffness = (args.stiffness if args.compression is None
                                      else args.compression)
    settings.bending_stiffness = args.bending
    settings.use_sewing_springs = True
    settings.sewing_force_max = 0.0  # unlimited: the springs pull each seam shut
    collision = cloth.collision_settings
    collision.use_collision = True
    collision.collision_quality = args.collision_quality
    collision.friction = args.friction
    collision.distance_min = args.collision_distance
    collision.use_self_collision = args.self_collision
    collision.self_distance_min = args.collision_distance
    cloth.point_cache.frame_start, cloth.point_cache.frame_end = 1, args.frames

    def positions():
        evaluated = garment.evaluated_get(bpy.context.evaluated_depsgraph_get())
        mesh = evaluated.to_mesh()
        if len(mesh.vertices) != len(vertices):
            raise SystemExit("the cloth's evaluated mesh lost vertices")
        result = [tuple(v.co) for v in mesh.vertices]
        evaluated.to_mesh_clear()
        return result

    for frame in range(1, args.frames + 1):
        scene.frame_set(frame)
        if frame == args.frames - 1:
            before_last = positions()
    draped = positions()
    # How far the cloth still moves in the last frame: near 0 when it has settled, so that
    # fewer frames are not mistaken for a better drape.
    last_move = max((sum((a - b) ** 2 for a, b in zip(p, q)) ** 0.5
                     for p, q in zip(draped, before_last)), default=0.0) if args.frames > 1 else 0.0

    out, index = [], 0
    for line in lines:
        if line.startswith("v "):
            x, y, z = draped[index]
            out.append(f"v {x:.6f} {y:.6f} {z:.6f}")
            index += 1
        else:
            out.append(line)
    with open(args.output, "w", encoding="utf-8") as file:
        file.write("\n".join(out) + "\n")
    print(f"blender-drape: {args.output}: {len(vertices)} vertices, {len(sewing)} sewing springs,"
          f" {args.frames} frames in {time.time() - start:.1f} s, the last frame moved a vertex"
          f" {1000 * last_move:.2f} mm at most")


main()
