#!/usr/bin/env python3
"""A field of N small spheres on the course's checker floor, for raytex and for POV-Ray 3.7.

Usage: bench/sphere_field.py N   (env: SEED, default 1; OUT_DIR, default the current directory)
Writes OUT_DIR/field-N.cfg (raytex) and OUT_DIR/field-N.pov (POV-Ray; render it with
+L<repository>/bench/povray, as bench/povray/compare.sh does).

The field: radii uniform in [0.1, 0.3], the eight course materials of
scenes/texture_include.cfg in turn, centres uniform over a square of side 2 sqrt(N) (one sphere
per 4 square units, so the area grows with N) that starts just in front of the camera and
reaches away from it, each sphere resting on the course's floor (y = -2, aChecker,
tex_scale 5). The camera stands at the near edge, looking over the field; the light is the
course scene's. The same seed gives the same scene.
"""
import argparse
import math
import os
import random

# In the order of bench/povray/compare.sh; each is a material of scenes/texture_include.cfg and a
# bench/povray/<name>.pov.
MATERIALS = ["aSolidChecker", "aNoise", "aMarble", "aWood", "anImage", "aTurbulence", "aDturbulence", "aChecker"]
FLOOR_Y = -2.0
EYE = (0.0, 1.0, 4.0)
LOOK_AT = (0.0, -1.5, -6.0)
FOV = 35.0  # vertical, degrees
LIGHT = (-6.0, 10.0, 6.0)
REPOSITORY = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def spheres(n, seed):
    """(centre, radius, material) for each sphere."""
    rng = random.Random(seed)
    side = 2.0 * math.sqrt(n)
    field = []
    for i in range(n):
        r = rng.uniform(0.1, 0.3)
        x = rng.uniform(-0.5 * side, 0.5 * side)
        z = -rng.uniform(0.0, side)
        field.append(((x, FLOOR_Y + r, z), r, MATERIALS[i % len(MATERIALS)]))
    return field


def vec(v):
    return "(%.6f, %.6f, %.6f)" % v


def raytex_scene(field):
    include = os.path.join(REPOSITORY, "scenes", "texture_include.cfg")
    lines = [
        "// %d spheres from bench/sphere_field.py" % len(field),
        '#include "%s"' % include,
        "camera { eye = %s; lookat = %s; up = (0, 1, 0); fov = %g; }" % (vec(EYE), vec(LOOK_AT), FOV),
        "light { position = %s; color = (1, 1, 1); }" % vec(LIGHT),
        "background = (0.05, 0.05, 0.08);",
        "ambient_light = (1, 1, 1);",
        "plane { normal = (0, 1, 0); distance = %g; tex_scale = 5.0; aChecker; }" % FLOOR_Y,
    ]
    for centre, r, material in field:
        lines.append("sphere { center = %s; radius = %.6f; %s; }" % (vec(centre), r, material))
    return "\n".join(lines) + "\n"


def povray_scene(field):
    # course.inc's sphere textures are made for its sphere (radius 2 at the origin); each field
    # sphere is that sphere scaled and moved, so its texture lands as raytex's does (raytex's
    # coordinates on a sphere follow its normal).
    lines = [
        "// %d spheres from bench/sphere_field.py" % len(field),
        "#version 3.7;",
        "#declare Course_Field = 1;",
        "#declare Course_Eye = <%.6f, %.6f, %.6f>;" % EYE,
        "#declare Course_Look_At = <%.6f, %.6f, %.6f>;" % LOOK_AT,
        '#include "course.inc"',
    ]
    for material in MATERIALS:
        lines.append('#include "%s.pov"' % material)
        lines.append("#declare Field_%s = Course_Texture;" % material)
    for (x, y, z), r, material in field:
        lines.append("sphere { <0, 0, 0>, 2 texture { Field_%s } scale %.6f translate <%.6f, %.6f, %.6f> }"
                     % (material, r / 2.0, x, y, z))
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0],
                                     epilog="env: SEED (default 1), OUT_DIR (default .)")
    parser.add_argument("n", type=int, help="number of spheres")
    args = parser.parse_args()
    if args.n < 1:
        parser.error("N must be at least 1")
    try:
        seed = int(os.environ.get("SEED", "1"))
    except ValueError:
        parser.error("SEED is an integer")
    out = os.environ.get("OUT_DIR", ".")
    field = spheres(args.n, seed)
    os.makedirs(out, exist_ok=True)
    base = os.path.join(out, "field-%d" % args.n)
    with open(base + ".cfg", "w") as f:
        f.write(raytex_scene(field))
    with open(base + ".pov", "w") as f:
        f.write(povray_scene(field))


if __name__ == "__main__":
    main()
