# SPDX-License-Identifier: Apache-2.0
#
# A bonus chapter for the book's renderer: the torus, written in the style
# of the book's feature files so that a renderer in any language can add a
# torus and check it against these numbers. Every scenario here is run by
# toroid's test of the same name (tests/torus_feature_test.cpp; see
# features/README.md for how the names map).
#
# The shape
#   torus(R, r) is a ring centred at the origin whose axis is the z axis:
#   R (the major radius) is the distance from the axis to the centre circle
#   of the tube, r (the minor radius) the radius of the tube. Its points
#   satisfy
#       (sqrt(x² + y²) − R)² + z² = r²
#   and squaring away the root gives the quartic surface
#       (x² + y² + z² + R² − r²)² = 4R²(x² + y²)
#   whose real roots along a ray are the intersections. torus() is
#   torus(1, 0.25).
#
#   The axis is z, not y as for the book's cylinders and cones: the ring
#   lies in the xy-plane as in the course paper "Torus Primitive" that this
#   torus starts from (and RenderMan's RiTorus, whose partial tori are used
#   below). To give a torus the book's y axis, as its cylinders and cones
#   have (a doughnut lying flat on a y-up floor), give it rotation_x(π / 2)
#   (see the last scenarios).
#
# Tolerances
#   A t value is equal to the one expected when they differ by less than
#   EPSILON_T = 0.000000001 (1e-9), unless the scenario gives its own
#   tolerance. Points, vectors and (u, v) pairs use the book's
#   EPSILON = 0.00001, component by component.
#
# Counting
#   local_intersect returns every real root of the quartic, those behind
#   the ray's origin (negative t) too, in ascending order. A tangent point
#   is a double root and is listed twice, so on a whole torus xs.count is
#   0, 2 or 4 even when the ray meets the surface at one or three distinct
#   points.
#
# Where a value is not exact it is given to more digits than its tolerance
# needs. These were worked out from the quartic formed exactly from the
# inputs (read as the nearest doubles) in 600-bit arithmetic; the roots of
# the simpler cases can be checked by hand from the equation above.

Feature: Tori

Scenario: The default torus
  Given t ← torus()
  Then t.major = 1
    And t.minor = 0.25

Scenario: A torus is whole by default
  Given t ← torus()
  Then t.theta_max = 2π
    And t.phi_min = -π
    And t.phi_max = π
    And t.spindle = whole

# ---------------------------------------------------------------------------
# Intersections

Scenario Outline: A ray misses a torus
  Given t ← torus(1, 0.25)
    And r ← ray(<origin>, <direction>)
  When xs ← local_intersect(t, r)
  Then xs.count = 0

  Examples:
    | case                         | origin                  | direction       |
    | over the top                 | point(-5, 0, 1)         | vector(1, 0, 0) |
    | a hair above the top         | point(-5, 0, 0.2500001) | vector(1, 0, 0) |
    | beyond the outer equator     | point(-5, 1.5, 0)       | vector(1, 0, 0) |
    | down the axis                | point(0, 0, -5)         | vector(0, 0, 1) |
    | up the axis from the centre  | point(0, 0, 0)          | vector(0, 0, 1) |
    | parallel to the axis, hole   | point(0.5, 0, -5)       | vector(0, 0, 1) |
    | parallel to the axis, beyond | point(2, 0, -5)         | vector(0, 0, 1) |

Scenario Outline: A ray strikes a torus four times
  Given t ← torus(1, 0.25)
    And direction ← normalize(<direction>)
    And r ← ray(<origin>, direction)
  When xs ← local_intersect(t, r)
  Then xs.count = 4
    And xs[0].t = <t0>
    And xs[1].t = <t1>
    And xs[2].t = <t2>
    And xs[3].t = <t3>

  Examples:
    | origin              | direction               | t0               | t1               | t2               | t3               |
    | point(-5, 0, 0)     | vector(1, 0, 0)         | 3.75             | 4.25             | 5.75             | 6.25             |
    | point(-5, 0.5, 0)   | vector(1, 0, 0)         | 3.85435607626104 | 4.44098300562505 | 5.55901699437495 | 6.14564392373896 |
    | point(-5, 0, 0.15)  | vector(1, 0, 0)         | 3.8              | 4.2              | 5.8              | 6.2              |
    | point(-5, 0.3, 0.1) | vector(1, -0.06, -0.02) | 3.76098732961585 | 4.25939115634874 | 5.76058888355153 | 6.25899271028443 |

Scenario Outline: A ray crosses the tube twice
  Given t ← torus(1, 0.25)
    And r ← ray(<origin>, <direction>)
  When xs ← local_intersect(t, r)
  Then xs.count = 2
    And xs[0].t = <t0>
    And xs[1].t = <t1>

  Examples:
    | case                     | origin          | direction       | t0   | t1   |
    | parallel to the axis     | point(1, 0, -5) | vector(0, 0, 1) | 4.75 | 5.25 |
    | across the tube at y = 1 | point(-5, 1, 0) | vector(1, 0, 0) | 4.25 | 5.75 |

Scenario Outline: Intersections behind the origin of the ray have a negative t
  Given t ← torus(1, 0.25)
    And r ← ray(<origin>, vector(1, 0, 0))
  When xs ← local_intersect(t, r)
  Then xs.count = 4
    And xs[0].t = <t0>
    And xs[1].t = <t1>
    And xs[2].t = <t2>
    And xs[3].t = <t3>

  Examples:
    | case             | origin         | t0    | t1    | t2    | t3    |
    | beyond the torus | point(5, 0, 0) | -6.25 | -5.75 | -4.25 | -3.75 |
    | from the centre  | point(0, 0, 0) | -1.25 | -0.75 | 0.75  | 1.25  |

Scenario: A ray from inside the tube meets it once behind and once ahead
  Given t ← torus(1, 0.25)
    And r ← ray(point(1, 0, 0), vector(0, 0, 1))
  When xs ← local_intersect(t, r)
  Then xs.count = 2
    And xs[0].t = -0.25
    And xs[1].t = 0.25

# The quartic does not need a unit direction: t is measured in lengths of
# the direction, as for the book's other shapes.
Scenario Outline: The direction of the ray need not be a unit vector
  Given t ← torus(1, 0.25)
    And r ← ray(point(-5, 0, 0), <direction>)
  When xs ← local_intersect(t, r)
  Then xs.count = 4
    And xs[0].t = <t0>
    And xs[1].t = <t1>
    And xs[2].t = <t2>
    And xs[3].t = <t3>

  Examples:
    | direction         | t0    | t1    | t2    | t3    |
    | vector(2, 0, 0)   | 1.875 | 2.125 | 2.875 | 3.125 |
    | vector(0.5, 0, 0) | 7.5   | 8.5   | 11.5  | 12.5  |

# Tangent rays. A solver that decides from the sign of a discriminant often
# loses these: rounding can push a double root just off the real line.
Scenario: A ray tangent to the outer equator touches the torus at one point, counted twice
  Given t ← torus(1, 0.25)
    And r ← ray(point(1.25, -5, 0), vector(0, 1, 0))
  When xs ← local_intersect(t, r)
  Then xs.count = 2
    And xs[0].t = 5
    And xs[1].t = 5

Scenario: A ray tangent to the top of the tube touches it twice, each touch counted twice
  Given t ← torus(1, 0.25)
    And r ← ray(point(-5, 0, 0.25), vector(1, 0, 0))
  When xs ← local_intersect(t, r)
  Then xs.count = 4
    And xs[0].t = 4
    And xs[1].t = 4
    And xs[2].t = 6
    And xs[3].t = 6

Scenario: A ray tangent to the inner equator meets the torus at three points
  Given t ← torus(1, 0.25)
    And r ← ray(point(-5, 0.75, 0), vector(1, 0, 0))
  When xs ← local_intersect(t, r)
  Then xs.count = 4
    And xs[0].t = 4
    And xs[1].t = 5
    And xs[2].t = 5
    And xs[3].t = 6

# ---------------------------------------------------------------------------
# The cases that break naive solvers
#
# Expanding the quartic into its five coefficients and handing them to a
# textbook closed form (Ferrari's method, or the paper's formula) works for
# the rays above, but not for the rays below. With a far origin, a thin
# tube or a large torus, the large terms of the coefficients cancel and take
# the digits that decide the roots with them; near a tangent, or near the
# axis of a spindle, two roots are so close that the rounding of the
# coefficients moves them apart or makes them complex. Each scenario gives
# a tolerance: a double-precision Ferrari misses a root, or is off by more
# than it, on every row (toroid's test TorusFeatureHardCases checks that),
# and a solver that keeps full precision meets it.

Scenario Outline: A distant camera still sees all four walls of the tube
  Given t ← torus(1, 0.25)
    And r ← ray(<origin>, vector(1, 0, 0))
  When xs ← local_intersect(t, r)
  Then xs.count = 4
    And xs[0].t = <t0> ± <tolerance>
    And xs[1].t = <t1> ± <tolerance>
    And xs[2].t = <t2> ± <tolerance>
    And xs[3].t = <t3> ± <tolerance>

  Examples:
    | origin                  | t0          | t1          | t2           | t3           | tolerance    |
    | point(-10000, 0, 0)     | 9998.75     | 9999.25     | 10000.75     | 10001.25     | 0.0000000001 |
    | point(-1000000, 0, 0)   | 999998.75   | 999999.25   | 1000000.75   | 1000001.25   | 0.00000001   |
    | point(-100000000, 0, 0) | 99999998.75 | 99999999.25 | 100000000.75 | 100000001.25 | 0.000001     |

# The ray passes through the centre of the tube, (1, 0, 0), at t = distance.
Scenario Outline: A distant camera looking down at the tube at a slant
  Given t ← torus(1, 0.25)
    And r ← ray(<origin>, vector(0, 0.6, -0.8))
  When xs ← local_intersect(t, r)
  Then xs.count = 2
    And xs[0].t = <t0> ± <tolerance>
    And xs[1].t = <t1> ± <tolerance>

  Examples:
    | origin                        | t0                   | t1                    | tolerance  |
    | point(1, -600000, 800000)     | 999999.6882528678598 | 1000000.3117471320310 | 0.00000001 |
    | point(1, -60000000, 80000000) | 99999999.68825286245 | 100000000.31174712662 | 0.000001   |

Scenario Outline: A ray across a thin torus meets all four walls
  Given t ← torus(1, <minor>)
    And r ← ray(point(-5, 0, 0), vector(1, 0, 0))
  When xs ← local_intersect(t, r)
  Then xs.count = 4
    And xs[0].t = <t0> ± 0.000000000001
    And xs[1].t = <t1> ± 0.000000000001
    And xs[2].t = <t2> ± 0.000000000001
    And xs[3].t = <t3> ± 0.000000000001

  Examples:
    | minor    | t0       | t1       | t2       | t3       |
    | 0.0001   | 3.9999   | 4.0001   | 5.9999   | 6.0001   |
    | 0.000001 | 3.999999 | 4.000001 | 5.999999 | 6.000001 |

Scenario Outline: A ray down through a thin tube meets both of its walls
  Given t ← torus(1, <minor>)
    And r ← ray(point(1, 0, -5), vector(0, 0, 1))
  When xs ← local_intersect(t, r)
  Then xs.count = 2
    And xs[0].t = <t0> ± 0.000000000001
    And xs[1].t = <t1> ± 0.000000000001

  Examples:
    | minor    | t0       | t1       |
    | 0.0001   | 4.9999   | 5.0001   |
    | 0.000001 | 4.999999 | 5.000001 |

# Rays a billionth inside a tangent: each pair of roots lies next to a
# double root of the quartic (along the top of the tube, next to a fourfold
# one), where a small error in the coefficients moves the roots far.
Scenario Outline: A ray grazing the tube meets it twice close together
  Given t ← torus(1, 0.25)
    And r ← ray(<origin>, <direction>)
  When xs ← local_intersect(t, r)
  Then xs.count = 2
    And xs[0].t = <t0> ± 0.000000000001
    And xs[1].t = <t1> ± 0.000000000001

  Examples:
    | case                      | origin                    | direction       | t0                  | t1                  |
    | inside the outer equator  | point(1.249999999, -5, 0) | vector(0, 1, 0) | 4.99994999999794149 | 5.00005000000205851 |
    | along the top of the tube | point(-5, 1, 0.249999999) | vector(1, 0, 0) | 4.99331255957084450 | 5.00668744042915550 |

Scenario: A ray skimming just under the top of the tube meets it four times
  Given t ← torus(1, 0.25)
    And r ← ray(point(-5, 0, 0.249999999), vector(1, 0, 0))
  When xs ← local_intersect(t, r)
  Then xs.count = 4
    And xs[0].t = 3.99997763932025325 ± 0.000000000001
    And xs[1].t = 4.00002236067974675 ± 0.000000000001
    And xs[2].t = 5.99997763932025325 ± 0.000000000001
    And xs[3].t = 6.00002236067974675 ± 0.000000000001

Scenario: A ray through the hole of a huge torus meets all four walls
  Given t ← torus(10000, 1)
    And r ← ray(point(-30000, 0, 0), vector(1, 0, 0))
  When xs ← local_intersect(t, r)
  Then xs.count = 4
    And xs[0].t = 19999 ± 0.000000001
    And xs[1].t = 20001 ± 0.000000001
    And xs[2].t = 39999 ± 0.000000001
    And xs[3].t = 40001 ± 0.000000001

# The ray is tangent to the centre circle at (10000, 0, 0) and stays inside
# the tube for 2 √20001 units: t = 30000 ∓ √20001.
Scenario: A ray along the centre circle of a huge torus stays inside the tube for a while
  Given t ← torus(10000, 1)
    And r ← ray(point(10000, -30000, 0), vector(0, 1, 0))
  When xs ← local_intersect(t, r)
  Then xs.count = 2
    And xs[0].t = 29858.5751082729776 ± 0.000000001
    And xs[1].t = 30141.4248917270224 ± 0.000000001

# From a point on the axis, a thousandth off the axis's direction: the ray
# passes through the centre of the tube, (1, 0, 0), at t = 1000.
Scenario: A ray nearly along the axis meets the tube far below
  Given t ← torus(1, 0.25)
    And r ← ray(point(0, 0, 1000), vector(0.001, 0, -1))
  When xs ← local_intersect(t, r)
  Then xs.count = 2
    And xs[0].t = 999.750000124999906 ± 0.0000000001
    And xs[1].t = 1000.249999875000094 ± 0.0000000001

# A spindle torus (r > R) crosses its own axis at two apexes, z = ±√(r² − R²)
# (see the section on horn and spindle tori below).
Scenario: A ray along the axis of a spindle torus meets each apex twice
  Given t ← torus(1, 1.5)
    And r ← ray(point(0, 0, -5), vector(0, 0, 1))
  When xs ← local_intersect(t, r)
  Then xs.count = 4
    And xs[0].t = 3.88196601125010515 ± 0.000000000001
    And xs[1].t = 3.88196601125010515 ± 0.000000000001
    And xs[2].t = 6.11803398874989485 ± 0.000000000001
    And xs[3].t = 6.11803398874989485 ± 0.000000000001

Scenario: A ray beside the axis of a spindle torus splits each apex into two hits
  Given t ← torus(1, 1.5)
    And r ← ray(point(0.000001, 0, -5), vector(0, 0, 1))
  When xs ← local_intersect(t, r)
  Then xs.count = 4
    And xs[0].t = 3.88196511682371914 ± 0.000000000001
    And xs[1].t = 3.88196690567810114 ± 0.000000000001
    And xs[2].t = 6.11803309432189886 ± 0.000000000001
    And xs[3].t = 6.11803488317628086 ± 0.000000000001

# ---------------------------------------------------------------------------
# Normals
#
# The normal at p points away from the nearest point of the centre circle:
# with ρ = sqrt(x² + y²), local_normal_at may return
# ((1 − R/ρ) x, (1 − R/ρ) y, z) or any positive multiple of it; normal_at
# normalizes it.

Scenario Outline: The normal on a torus
  Given t ← torus(1, 0.25)
  When n ← normal_at(t, <point>)
  Then n = <normal>

  Examples:
    | case               | point                     | normal                     |
    | outer equator      | point(1.25, 0, 0)         | vector(1, 0, 0)            |
    | outer equator, -y  | point(0, -1.25, 0)        | vector(0, -1, 0)           |
    | inner equator      | point(0.75, 0, 0)         | vector(-1, 0, 0)           |
    | top of the tube    | point(0, 1, 0.25)         | vector(0, 0, 1)            |
    | bottom of the tube | point(-1, 0, -0.25)       | vector(0, 0, -1)           |
    | above, outside     | point(0.69, 0.92, 0.2)    | vector(0.36, 0.48, 0.8)    |
    | above, inside      | point(0.48, 0.64, 0.15)   | vector(-0.48, -0.64, 0.6)  |
    | below, outside     | point(-0.92, -0.69, -0.2) | vector(-0.48, -0.36, -0.8) |

# ---------------------------------------------------------------------------
# Bounds

Scenario Outline: A torus has a bounding box
  Given t ← torus(<major>, <minor>)
  When box ← bounds_of(t)
  Then box.min = <min>
    And box.max = <max>

  Examples:
    | major | minor | min                        | max                     |
    | 1     | 0.25  | point(-1.25, -1.25, -0.25) | point(1.25, 1.25, 0.25) |
    | 2     | 0.5   | point(-2.5, -2.5, -0.5)    | point(2.5, 2.5, 0.5)    |
    | 1     | 1.5   | point(-2.5, -2.5, -1.5)    | point(2.5, 2.5, 1.5)    |
    | 10000 | 1     | point(-10001, -10001, -1)  | point(10001, 10001, 1)  |

# Transforming the eight corners of bounds_of(t), as the book does for any
# shape, gives point(-1.25, -1.06066, -1.06066) and point(1.25, 1.06066,
# 1.06066) here: correct, but looser. The tight box holds the centre circle
# widened by r in every direction: on each axis of the parent, with
# (a, b, c) the first three entries of that axis's row of the transform,
# R √(a² + b²) + r √(a² + b² + c²) either side of the centre.
Scenario: A rotated torus has a tight bounding box in its parent space
  Given t ← torus(1, 0.25)
    And set_transform(t, rotation_x(π / 4))
  When box ← parent_space_bounds_of(t)
  Then box.min = point(-1.25, -0.95711, -0.95711)
    And box.max = point(1.25, 0.95711, 0.95711)

# ---------------------------------------------------------------------------
# Partial tori
#
# As in RenderMan's RiTorus, a torus can be cut to part of its surface by
# three angles of a surface point, where
#   p = ((R + r cos φ) cos θ, (R + r cos φ) sin θ, r sin φ):
#   θ (theta) around the z axis, from +x towards +y, in [0, 2π);
#   φ (phi) around the tube, 0 on the outer equator, π/2 on top (+z), ±π on
#   the inner equator.
# A point is kept when θ ≤ theta_max and φ, φ + 2π or φ − 2π lies in
# [phi_min, phi_max]. A partial torus is an open surface: it has no end caps,
# so a ray can enter the tube through a cut and meet its inside.

Scenario: A half torus keeps the hits on its half
  Given t ← torus(1, 0.25)
    And t.theta_max ← π
    And r ← ray(point(-5, 1, 0), vector(1, 0, 0))
  When xs ← local_intersect(t, r)
  Then xs.count = 2
    And xs[0].t = 4.25
    And xs[1].t = 5.75

Scenario: A ray through the removed half of a partial torus misses
  Given t ← torus(1, 0.25)
    And t.theta_max ← π
    And r ← ray(point(-5, -1, 0), vector(1, 0, 0))
  When xs ← local_intersect(t, r)
  Then xs.count = 0

# θ = 0 and θ = π, where this ray meets the tube, are the two edges of a
# half torus, and an edge belongs to the surface.
Scenario: Hits on the cut of a partial torus are kept
  Given t ← torus(1, 0.25)
    And t.theta_max ← π
    And r ← ray(point(-5, 0, 0), vector(1, 0, 0))
  When xs ← local_intersect(t, r)
  Then xs.count = 4
    And xs[0].t = 3.75
    And xs[1].t = 4.25
    And xs[2].t = 5.75
    And xs[3].t = 6.25

Scenario: A quarter torus drops the hits beyond its sweep
  Given t ← torus(1, 0.25)
    And t.theta_max ← π / 2
    And r ← ray(point(-5, 0, 0), vector(1, 0, 0))
  When xs ← local_intersect(t, r)
  Then xs.count = 2
    And xs[0].t = 5.75
    And xs[1].t = 6.25

# The ray enters the tube through the open cut at θ = 0 and leaves it
# through the kept wall at y = 0.75: a hit seen from inside.
Scenario: A ray through the open end of a partial torus meets the tube from inside
  Given t ← torus(1, 0.25)
    And t.theta_max ← π
    And r ← ray(point(1, -5, 0), vector(0, 1, 0))
  When xs ← local_intersect(t, r)
    And comps ← prepare_computations(xs[0], r, xs)
  Then xs.count = 1
    And xs[0].t = 5.75
    And comps.inside = true

# The half of the tube facing the axis, written two ways.
Scenario Outline: A phi sweep around the inner equator keeps the half of the tube facing the axis
  Given t ← torus(1, 0.25)
    And t.phi_min ← <phi_min>
    And t.phi_max ← <phi_max>
    And r ← ray(point(-5, 0, 0), vector(1, 0, 0))
  When xs ← local_intersect(t, r)
  Then xs.count = 2
    And xs[0].t = 4.25
    And xs[1].t = 5.75

  Examples:
    | phi_min | phi_max |
    | π/2     | 3π/2    |
    | -3π/2   | -π/2    |

Scenario: A phi sweep over the top of the tube keeps its upper half
  Given t ← torus(1, 0.25)
    And t.phi_min ← 0
    And t.phi_max ← π
    And r ← ray(point(1, 0, 5), vector(0, 0, -1))
  When xs ← local_intersect(t, r)
  Then xs.count = 1
    And xs[0].t = 4.75

Scenario Outline: A partial torus has a bounding box around its swept part
  Given t ← torus(1, 0.25)
    And t.theta_max ← <theta_max>
    And t.phi_min ← <phi_min>
    And t.phi_max ← <phi_max>
  When box ← bounds_of(t)
  Then box.min = <min>
    And box.max = <max>

  Examples:
    | theta_max | phi_min | phi_max | min                            | max                        |
    | π         | -π      | π       | point(-1.25, 0, -0.25)         | point(1.25, 1.25, 0.25)    |
    | π/2       | -π      | π       | point(0, 0, -0.25)             | point(1.25, 1.25, 0.25)    |
    | 3π/4      | -π      | π       | point(-0.88388, 0, -0.25)      | point(1.25, 1.25, 0.25)    |
    | 2π        | 0       | π       | point(-1.25, -1.25, 0)         | point(1.25, 1.25, 0.25)    |
    | π/4       | -π/2    | π/2     | point(0.70711, 0, -0.25)       | point(1.25, 0.88388, 0.25) |
    | 2π        | π/3     | 2π/3    | point(-1.125, -1.125, 0.21651) | point(1.125, 1.125, 0.25)  |

# ---------------------------------------------------------------------------
# Horn and spindle tori
#
# With r = R the tube touches itself at the centre (a horn torus); with
# r > R it passes through itself (a spindle torus). The quartic then has a
# second sheet inside the first, the "lemon", (ρ + R)² + z² = r², which
# meets the outer sheet at the apexes (0, 0, ±√(r² − R²)). Both sheets are
# intersected unless t.spindle ← outer keeps the outer one only.

Scenario: A ray through the centre of a horn torus touches it there twice
  Given t ← torus(1, 1)
    And r ← ray(point(-5, 0, 0), vector(1, 0, 0))
  When xs ← local_intersect(t, r)
  Then xs.count = 4
    And xs[0].t = 3
    And xs[1].t = 5
    And xs[2].t = 5
    And xs[3].t = 7

Scenario: A ray along the equator of a spindle torus meets the outer sheet and the lemon
  Given t ← torus(1, 1.5)
    And r ← ray(point(-5, 0, 0), vector(1, 0, 0))
  When xs ← local_intersect(t, r)
  Then xs.count = 4
    And xs[0].t = 2.5
    And xs[1].t = 4.5
    And xs[2].t = 5.5
    And xs[3].t = 7.5

Scenario: A spindle torus can keep its outer sheet only
  Given t ← torus(1, 1.5)
    And t.spindle ← outer
    And r ← ray(point(-5, 0, 0), vector(1, 0, 0))
  When xs ← local_intersect(t, r)
  Then xs.count = 2
    And xs[0].t = 2.5
    And xs[1].t = 7.5

# A point of the lemon belongs to the tube around the far side of the
# centre circle: R + r cos φ < 0 there, so its θ is the direction of that
# far side. Cutting a spindle torus to θ ≤ π keeps the outer sheet where
# y ≥ 0 and the lemon where y ≤ 0.
Scenario: The lemon of a half spindle torus lies across the axis from its outer half
  Given t ← torus(1, 1.5)
    And t.theta_max ← π
    And r ← ray(point(-0.3, -5, 0), vector(0, 1, 0))
  When xs ← local_intersect(t, r)
  Then xs.count = 2
    And xs[0].t = 4.6
    And xs[1].t = 7.48193472919817132

# On the lemon the normal points away from the centre of the torus (the
# lemon seen from outside it); at an apex, where the surface comes to a
# point, it is taken along the axis, away from the centre.
Scenario Outline: The normal on a spindle torus
  Given t ← torus(1, 1.5)
  When n ← normal_at(t, <point>)
  Then n = <normal>

  Examples:
    | case               | point                           | normal               |
    | outer equator      | point(-2.5, 0, 0)               | vector(-1, 0, 0)     |
    | outer sheet, above | point(1.9, 0, 1.2)              | vector(0.6, 0, 0.8)  |
    | lemon equator      | point(0.5, 0, 0)                | vector(1, 0, 0)      |
    | lemon, above       | point(-0.2, 0, 0.9)             | vector(-0.8, 0, 0.6) |
    | upper apex         | point(0, 0, 1.118033988749895)  | vector(0, 0, 1)      |
    | lower apex         | point(0, 0, -1.118033988749895) | vector(0, 0, -1)     |

Scenario: The normal at the centre of a horn torus points up the axis
  Given t ← torus(1, 1)
  When n ← normal_at(t, point(0, 0, 0))
  Then n = vector(0, 0, 1)

# ---------------------------------------------------------------------------
# Texture mapping
#
# In the manner of the texture mapping bonus chapter's spherical_map and
# cylindrical_map: toroidal_map(t, p) takes a point of the torus t to
# (u, v) in [0, 1) × [0, 1), u = θ / 2π and v = φ / 2π (wrapped into
# [0, 1)) with θ and φ as for partial tori. It needs the torus's radii.
# Both wrap around without a seam, so an image whose opposite edges match
# covers a torus seamlessly.

Scenario Outline: Using a toroidal mapping on a 3D point
  Given t ← torus(1, 0.25)
    And p ← <point>
  When (u, v) ← toroidal_map(t, p)
  Then u = <u>
    And v = <v>

  Examples:
    | point                     | u        | v        |
    | point(1.25, 0, 0)         | 0.0      | 0.0      |
    | point(0, 1.25, 0)         | 0.25     | 0.0      |
    | point(-1.25, 0, 0)        | 0.5      | 0.0      |
    | point(0, -1.25, 0)        | 0.75     | 0.0      |
    | point(1, 0, 0.25)         | 0.0      | 0.25     |
    | point(0.75, 0, 0)         | 0.0      | 0.5      |
    | point(1, 0, -0.25)        | 0.0      | 0.75     |
    | point(0, -1, 0.25)        | 0.75     | 0.25     |
    | point(0.69, 0.92, 0.2)    | 0.147584 | 0.147584 |
    | point(0.48, 0.64, 0.15)   | 0.147584 | 0.397584 |
    | point(-0.92, -0.69, -0.2) | 0.602416 | 0.852416 |

Scenario Outline: Using a toroidal mapping on a spindle torus
  Given t ← torus(1, 1.5)
    And p ← <point>
  When (u, v) ← toroidal_map(t, p)
  Then u = <u>
    And v = <v>

  Examples:
    | case          | point                          | u    | v        |
    | outer equator | point(2.5, 0, 0)               | 0.0  | 0.0      |
    | outer, +y     | point(0, 2.5, 0)               | 0.25 | 0.0      |
    | lemon, -x     | point(-0.5, 0, 0)              | 0.0  | 0.5      |
    | lemon, +x     | point(0.5, 0, 0)               | 0.5  | 0.5      |
    | lemon, above  | point(-0.2, 0, 0.9)            | 0.0  | 0.397584 |
    | upper apex    | point(0, 0, 1.118033988749895) | 0.0  | 0.366139 |

# ---------------------------------------------------------------------------
# A torus standing up
#
# rotation_x(π / 2) turns the ring into the xz-plane, its axis along y,
# the way the book's cylinders and cones stand.

Scenario: A torus rotated a quarter turn about x has its axis along y
  Given t ← torus(1, 0.25)
    And set_transform(t, rotation_x(π / 2))
    And r1 ← ray(point(0, -5, 0), vector(0, 1, 0))
    And r2 ← ray(point(-5, 0, 0), vector(1, 0, 0))
  When xs1 ← intersect(t, r1)
    And xs2 ← intersect(t, r2)
  Then xs1.count = 0
    And xs2.count = 4
    And xs2[0].t = 3.75
    And xs2[1].t = 4.25
    And xs2[2].t = 5.75
    And xs2[3].t = 6.25

Scenario: The normal on a torus rotated a quarter turn about x
  Given t ← torus(1, 0.25)
    And set_transform(t, rotation_x(π / 2))
  When n1 ← normal_at(t, point(0, 0, 1.25))
    And n2 ← normal_at(t, point(0, 0.25, 1))
  Then n1 = vector(0, 0, 1)
    And n2 = vector(0, 1, 0)
