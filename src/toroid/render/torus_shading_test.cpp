// SPDX-License-Identifier: Apache-2.0
// The Torus shape in a world: shadows, refraction through the hole, and
// the inside of a partial torus seen through its open edge.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "support/approx.h"
#include "support/torus_cases.h"
#include "toroid/math/transform.h"
#include "toroid/render/computations.h"
#include "toroid/render/world.h"
#include "toroid/shapes/sphere.h"
#include "toroid/shapes/torus.h"

namespace toroid {
namespace {

TEST(TorusShading, ATorusCastsAShadow) {
  World w;
  w.lights.push_back({point(0, 0, 1000), Color{1, 1, 1}});  // nearly overhead
  auto t = std::make_shared<Torus>(1, 0.25);
  w.objects.push_back(t);
  EXPECT_TRUE(is_shadowed(w, point(1, 0, -5), w.lights[0]));   // under the tube
  EXPECT_FALSE(is_shadowed(w, point(0, 0, -5), w.lights[0]));  // under the hole
  EXPECT_FALSE(is_shadowed(w, point(2, 0, -5), w.lights[0]));  // beside it
}

TEST(TorusShading, RefractionThroughAGlassTorusCrossesTheHole) {
  // A ray through the hole leaves and re-enters the same torus: the
  // containers algorithm must give n1/n2 = 1.5/1.0 on leaving, 1.0/1.5 on
  // re-entering.
  auto t = std::make_shared<Torus>(1, 0.25);
  Material t_material = t->material();
  t_material.transparency = 1.0;
  t_material.refractive_index = 1.5;
  t->set_material(t_material);
  const Ray r{point(-5, 0, 0), vector(1, 0, 0)};
  const Intersections xs = intersect_sorted(*t, r);
  ASSERT_EQ(xs.size(), 4u);
  const double want[4][2] = {{1.0, 1.5}, {1.5, 1.0}, {1.0, 1.5}, {1.5, 1.0}};
  for (int i = 0; i < 4; ++i) {
    const Computations c = prepare_computations(xs[i], r, xs);
    EXPECT_DOUBLE_EQ(c.n1, want[i][0]) << "intersection " << i;
    EXPECT_DOUBLE_EQ(c.n2, want[i][1]) << "intersection " << i;
  }
}

TEST(TorusShading, AGlassTorusShadesWithoutBlackPixels) {
  // Looking through the hole of a glass torus at a lit sphere behind it:
  // every ray must come back finite and not black.
  World w;
  w.lights.push_back({point(-10, 10, -10), Color{1, 1, 1}});
  auto t = std::make_shared<Torus>(1, 0.25);
  Material t_material = t->material();
  t_material.transparency = 0.9;
  t_material.refractive_index = 1.5;
  t_material.reflective = 0.1;
  t->set_material(t_material);
  t->set_transform(rotation_x(M_PI / 2));  // ring faces the camera (axis along z -> y... axis now -y)
  w.objects.push_back(t);
  auto s = std::make_shared<Sphere>();
  s->set_transform(translation(0, 0, 5) * scaling(3, 3, 3));
  w.objects.push_back(s);
  for (double x = -1.3; x <= 1.3; x += 0.05) {
    const Color c = color_at(w, {point(x, 0, -10), vector(0, 0, 1)});
    EXPECT_TRUE(std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b));
    EXPECT_GT(c.r + c.g + c.b, 0.0) << "black pixel at x = " << x;
  }
}

TEST(TorusShading, ARayThroughTheOpenEdgeSeesTheInside) {
  const auto t = partial_torus(M_PI);
  const Ray r{point(1, -5, 0), vector(0, 1, 0)};
  const Intersections xs = intersect_sorted(*t, r);
  ASSERT_EQ(xs.size(), 1u);
  const Computations comps = prepare_computations(xs[0], r, xs);
  EXPECT_APPROX(comps.point, point(1, 0.75, 0));
  EXPECT_TRUE(comps.inside);
  // The outward normal (0.8, 0.6, 0), flipped to face the ray.
  EXPECT_APPROX(comps.normalv, vector(-0.8, -0.6, 0));
  // Shadow rays start inside the tube.
  const Tuple& op = comps.over_point;
  EXPECT_LT(std::pow(std::hypot(op.x, op.y) - 1, 2) + op.z * op.z, 0.25 * 0.25);
}

TEST(TorusShading, TheInsideSeenThroughTheOpenEdgeIsLitLikeTheOutside) {
  // The wall at (1, 0.75, 0), lit from the front of each side, shades alike
  // (the scenes are mirror images); lit from behind it gets ambient only.
  auto t = std::make_shared<Torus>(1, 0.25);
  t->set_sweep({M_PI, -M_PI, M_PI});
  World inside_lit, outside_lit, inside_dark;
  inside_lit.lights.push_back({point(1, -10, 0), Color{1, 1, 1}});
  outside_lit.lights.push_back({point(1, 10, 0), Color{1, 1, 1}});
  inside_dark.lights.push_back({point(1, 10, 0), Color{1, 1, 1}});
  for (World* w : {&inside_lit, &outside_lit, &inside_dark}) w->objects.push_back(t);
  const Ray into_edge{point(1, -5, 0), vector(0, 1, 0)}, onto_wall{point(1, 5, 0), vector(0, -1, 0)};
  const Color in = color_at(inside_lit, into_edge);
  const Color out = color_at(outside_lit, onto_wall);
  const Color dark = color_at(inside_dark, into_edge);
  EXPECT_APPROX(in, out);
  const Color ambient = t->material().color * t->material().ambient;
  EXPECT_GT(in.r, ambient.r + 0.5);
  EXPECT_APPROX(dark, ambient);
}

TEST(TorusShading, APhiSweepKeepsTheTopOfTheTube) {
  const auto t = partial_torus(2 * M_PI, 0, M_PI);  // phi 0..pi: z >= 0
  const Intersections down = intersect_sorted(*t, {point(1, 0, 5), vector(0, 0, -1)});
  ASSERT_EQ(down.size(), 1u);
  EXPECT_DOUBLE_EQ(down[0].t, 4.75);
  // From below the bottom is gone: the ray meets the top from inside.
  const Ray up{point(1, 0, -5), vector(0, 0, 1)};
  const Intersections xs = intersect_sorted(*t, up);
  ASSERT_EQ(xs.size(), 1u);
  EXPECT_DOUBLE_EQ(xs[0].t, 5.25);
  const Computations comps = prepare_computations(xs[0], up, xs);
  EXPECT_TRUE(comps.inside);
  EXPECT_APPROX(comps.normalv, vector(0, 0, -1));
}

}  // namespace
}  // namespace toroid
