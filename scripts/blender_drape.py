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
                        help="tension and compression stiffness (Blender's default 15)")
    parser.add_argument("--bending", type=float, default=0.5,
                        help="bending stiffness (Blender's default 0.5)")
    # Blender's default 0.3 kg a vertex makes a garment of 2,000 vertices weigh 600 kg: the
    # springs give way and the cloth sinks into the body. 1 g a vertex (about 3 kg/m² at the
    # 2 cm mesh) kept the garments tried clean; 10 g did not (gc_0000: 460 vertices inside).
    parser.add_argument("--mass", type=float, default=0.001,
                        help="vertex mass, kg (default 0.001; Blender's 0.3)")
    parser.add_argument("--self-collision", action="store_true",
                        help="cloth collides with itself (off in Blender's default)")
    return parser.parse_args(argv)


def read_obj(path):
    """Vertices, triangles (and polygons), sewing lines, and the text's lines."""
    with open(path, encoding="utf-8") as file:
        lines = file.read().splitlines()
    vertices, faces, edges = [], [], []
    for line in lines:
        words = line.split()
        if not words:
            continue
        if words[0] == "v":
            vertices.append(tuple(float(w) for w in words[1:4]))
        elif words[0] == "f":
            faces.append([int(w.split("/")[0]) - 1 for w in words[1:]])
        elif words[0] == "l":
            ids = [int(w.split("/")[0]) - 1 for w in words[1:]]
            edges.extend(zip(ids, ids[1:]))
    return vertices, faces, edges, lines


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

    vertices, faces, sewing, lines = read_obj(args.garment)
    body_vertices, body_faces, _, _ = read_obj(args.body)
    garment = add_object("garment", vertices, faces, sewing)
    body = add_object("body", body_vertices, body_faces)

    body.modifiers.new("Collision", "COLLISION")
    body.collision.thickness_outer = args.collision_distance
    # A cloth vertex found this deep inside the body is pushed out of it; Blender's default 0.2 m
    # is more than an arm is thick.
    body.collision.thickness_inner = 0.02
    body.collision.damping = 0.1

    cloth = garment.modifiers.new("Cloth", "CLOTH")
    settings = cloth.settings
    settings.quality = args.quality
    settings.mass = args.mass
    settings.tension_stiffness = settings.compression_stiffness = args.stiffness
    settings.bending_stiffness = args.bending
    settings.use_sewing_springs = True
    settings.sewing_force_max = 0.0  # unlimited: the springs pull each seam shut
    collision = cloth.collision_settings
    collision.use_collision = True
    collision.distance_min = args.collision_distance
    collision.use_self_collision = args.self_collision
    collision.self_distance_min = args.collision_distance
    cloth.point_cache.frame_start, cloth.point_cache.frame_end = 1, args.frames

    for frame in range(1, args.frames + 1):
        scene.frame_set(frame)
    depsgraph = bpy.context.evaluated_depsgraph_get()
    evaluated = garment.evaluated_get(depsgraph)
    mesh = evaluated.to_mesh()
    if len(mesh.vertices) != len(vertices):
        raise SystemExit("the cloth's evaluated mesh lost vertices")
    draped = [tuple(v.co) for v in mesh.vertices]
    evaluated.to_mesh_clear()

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
          f" {args.frames} frames in {time.time() - start:.1f} s")


main()
