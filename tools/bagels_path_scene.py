#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Writes scenes/bagels-path.yaml, the path tracer's hero scene.

The scene is a breakfast table by a window: a plate with a sesame bagel and
two glazed doughnuts, a bitten bagel beside it. The sesame seeds and the
sprinkles sit on the tori's surfaces; this script places them (a fixed seed,
so the file is the same on every run) and writes the YAML.

    tools/bagels_path_scene.py > scenes/bagels-path.yaml
"""

import math
import random

HALF_PI = math.pi / 2


def fmt(x):
    return f"{x:.4f}".rstrip("0").rstrip(".") if abs(x) > 5e-5 else "0"


def surface_item(kind, material, scale, centre, major, minor, theta, phi, spin, lift=0.0):
    """A small shape lying on a flat torus (axis +y) at `centre`: `theta`
    around the axis, `phi` around the tube (0 outside, pi/2 on top), its own
    y axis along the surface normal, turned by `spin` about that normal."""
    ring = major + (minor + lift) * math.cos(phi)
    x = centre[0] + ring * math.cos(theta)
    y = centre[1] + (minor + lift) * math.sin(phi)
    z = centre[2] + ring * math.sin(theta)
    lines = [
        f"- add: {kind}",
        f"  material: {material}",
        "  shadow: false",
        "  transform:",
        f"    - [scale, {fmt(scale[0])}, {fmt(scale[1])}, {fmt(scale[2])}]",
        f"    - [rotate-y, {fmt(spin)}]",
        # rotate-z(phi - pi/2) takes +y to (cos phi, sin phi, 0), the normal
        # at theta = 0; rotate-y(-theta) carries it round to theta.
        f"    - [rotate-z, {fmt(phi - HALF_PI)}]",
        f"    - [rotate-y, {fmt(-theta)}]",
        f"    - [translate, {fmt(x)}, {fmt(y)}, {fmt(z)}]",
    ]
    return "\n".join(lines)


def torus(major, minor, material, centre, extra=(), turn=0.0):
    lines = [
        "- add: torus",
        f"  major: {fmt(major)}",
        f"  minor: {fmt(minor)}",
    ]
    lines += [f"  {e}" for e in extra]
    lines += [
        f"  material: {material}",
        "  transform:",
        "    - lie-flat",
    ]
    if turn:
        lines.append(f"    - [rotate-y, {fmt(turn)}]")
    lines.append(f"    - [translate, {fmt(centre[0])}, {fmt(centre[1])}, {fmt(centre[2])}]")
    return "\n".join(lines)


def seeds(rng, count, centre, major, minor, theta_range=(0, 2 * math.pi)):
    out = []
    for _ in range(count):
        theta = rng.uniform(*theta_range)
        phi = rng.uniform(0.35, 2.8)
        out.append(
            surface_item("sphere", "sesame", (0.045, 0.014, 0.024), centre, major, minor, theta, phi,
                         rng.uniform(0, math.pi), lift=0.004))
    return out


def sprinkles(rng, count, centre, major, minor, materials):
    out = []
    for _ in range(count):
        theta = rng.uniform(0, 2 * math.pi)
        phi = rng.uniform(0.6, 2.5)
        material = rng.choice(materials)
        # a unit cylinder (axis y, y in [-1, 1] once min/max are set) laid on
        # its side: its length along the surface, its radius across
        item = surface_item("cylinder", material, (0.014, 0.05, 0.014), centre, major, minor + 0.02, theta, phi,
                            rng.uniform(0, math.pi), lift=0.012)
        item = item.replace("- add: cylinder\n", "- add: cylinder\n  min: -1\n  max: 1\n  closed: true\n", 1)
        # lay the stick down: turn its axis from the normal into the surface
        item = item.replace("    - [rotate-y,", "    - [rotate-x, 1.5708]\n    - [rotate-y,", 1)
        out.append(item)
    return out


HEADER = """\
# SPDX-License-Identifier: Apache-2.0
# bagels-path.yaml: breakfast by the window, the path tracer's hero scene. A
# plate with a sesame bagel and two glazed doughnuts on a red-checked cloth,
# a bitten bagel beside it; daylight through a window on the left (an area
# light), a blue sky all round (the environment), a warm wall on the right
# whose light bleeds onto the plate.
#
# Written by tools/bagels_path_scene.py (it places the seeds and sprinkles).
# Render: build/toroid render scenes/bagels-path.yaml -o bagels-path.png --samples 256

- add: integrator
  type: path

- add: environment
  color: [0.12, 0.16, 0.23]
  zenith: [0.2, 0.3, 0.5]

- add: camera
  width: 960
  height: 600
  field-of-view: 0.72
  from: [1.2, 5.4, -8.2]
  to: [0.3, 0.1, 0.1]
  up: [0, 1, 0]

# the window: daylight from the upper left (intensity / area = its radiance)
- add: light
  corner: [-6, 2.5, -2.5]
  uvec: [0, 0, 4]
  usteps: 4
  vvec: [0, 3.5, 0]
  vsteps: 4
  jitter: true
  intensity: [300, 280, 240]

- define: lie-flat
  value:
    - [rotate-x, -1.5708]

- define: crust
  value:
    color: [0.74, 0.42, 0.16]
    diffuse: 0.9
    specular: 0.1
    shininess: 40

- define: dough
  value:
    color: [0.88, 0.6, 0.32]
    diffuse: 0.9
    specular: 0.05
    shininess: 5

- define: crumb
  value:
    color: [0.96, 0.88, 0.7]
    diffuse: 0.9
    specular: 0

- define: pink-glaze
  value:
    color: [0.95, 0.5, 0.66]
    diffuse: 0.85
    specular: 0.1
    shininess: 300

- define: chocolate
  value:
    color: [0.3, 0.15, 0.08]
    diffuse: 0.85
    specular: 0.12
    shininess: 300

- define: sesame
  value:
    color: [0.97, 0.9, 0.72]
    diffuse: 0.9
    specular: 0.1
    shininess: 20

- define: sprinkle-white
  value: {color: [0.97, 0.97, 0.95], diffuse: 0.9, specular: 0.2, shininess: 60}
- define: sprinkle-blue
  value: {color: [0.2, 0.45, 0.9], diffuse: 0.9, specular: 0.2, shininess: 60}
- define: sprinkle-yellow
  value: {color: [0.98, 0.82, 0.2], diffuse: 0.9, specular: 0.2, shininess: 60}
- define: sprinkle-green
  value: {color: [0.35, 0.8, 0.35], diffuse: 0.9, specular: 0.2, shininess: 60}

# the table cloth
- add: plane
  material:
    pattern:
      type: checkers
      colors:
        - [0.8, 0.12, 0.1]
        - [0.92, 0.9, 0.85]
      transform:
        - [scale, 0.7, 0.7, 0.7]
        - [rotate-y, 0.3]
    diffuse: 0.9
    specular: 0

# the wall behind, with the window's wall on the left
- add: plane
  transform:
    - [rotate-x, 1.5708]
    - [translate, 0, 0, 6]
  material:
    color: [0.9, 0.88, 0.82]
    diffuse: 0.9
    specular: 0

# a warm yellow wall on the right
- add: plane
  transform:
    - [rotate-z, 1.5708]
    - [translate, 5.5, 0, 0]
  material:
    color: [0.95, 0.75, 0.3]
    diffuse: 0.9
    specular: 0

# the plate: a squashed closed cylinder, its top at y = 0.08
- add: cylinder
  min: 0
  max: 1
  closed: true
  transform:
    - [scale, 2.5, 0.08, 2.5]
  material:
    color: [0.96, 0.96, 0.95]
    diffuse: 0.85
    specular: 0.08
    shininess: 1000
"""


def main():
    rng = random.Random(19)
    plate_top = 0.08
    parts = [HEADER]

    # the sesame bagel, at the back of the plate
    bagel = (0.15, plate_top + 0.31, 1.15)
    parts.append("# the sesame bagel")
    parts.append(torus(0.6, 0.31, "crust", bagel))
    parts += seeds(rng, 90, bagel, 0.6, 0.31)

    # a pink doughnut with sprinkles, front left
    pink = (-1.05, plate_top + 0.26, -0.45)
    parts.append("# a pink glazed doughnut with sprinkles")
    parts.append(torus(0.55, 0.26, "dough", pink))
    parts.append(torus(0.55, 0.272, "pink-glaze", pink, extra=["phi-min: 0.3", "phi-max: 2.85"]))
    parts += sprinkles(rng, 70, pink, 0.55, 0.26,
                       ["sprinkle-white", "sprinkle-blue", "sprinkle-yellow", "sprinkle-green"])

    # a chocolate doughnut, front right
    choc = (1.1, plate_top + 0.26, -0.35)
    parts.append("# a chocolate glazed doughnut")
    parts.append(torus(0.55, 0.26, "dough", choc))
    parts.append(torus(0.55, 0.272, "chocolate", choc, extra=["phi-min: 0.25", "phi-max: 2.9"]))

    # a bitten bagel on the cloth, in front of the plate. The torus's own
    # theta runs from +x towards -z once laid flat (the other way round from
    # surface_item's), so theta-max: 5.2 keeps surface_item's [-5.2, 0].
    parts.append("# a bitten bagel on the cloth, its cut closed by caps")
    children = [
        "\n".join([
            "- add: torus",
            "  major: 0.6",
            "  minor: 0.31",
            "  theta-max: 5.2",
            "  caps: true",
            "  material: crust",
            "  transform: [lie-flat]",
        ])
    ]
    children += seeds(rng, 70, (0, 0, 0), 0.6, 0.31, theta_range=(-5.1, -0.1))
    indented = "\n".join("    " + line for child in children for line in child.split("\n"))
    parts.append("\n".join(["- add: group", "  transform:", "    - [rotate-y, 0.9]",
                             "    - [translate, 2.85, 0.31, -2.25]", "  children:", indented]))

    print("\n\n".join(parts))


if __name__ == "__main__":
    main()
