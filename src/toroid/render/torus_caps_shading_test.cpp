// SPDX-License-Identifier: Apache-2.0
// Capped partial tori in a world: refraction sees one closed solid (n1 and
// n2 at the caps, no black pixels through a glass one), the caps shade with
// their own normals, and the torus uv map on the caps.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "support/approx.h"
#include "support/torus_cases.h"
#include "toroid/math/transform.h"
#include "toroid/render/computations.h"
#include "toroid/render/uv_mapping.h"
#include "toroid/render/world.h"
#include "toroid/shapes/plane.h"
#include "toroid/shapes/sphere.h"
#include "toroid/shapes/torus.h"

namespace toroid {
namespace {

std::shared_ptr<Torus> capped_torus(double theta_max, double phi_min = -M_PI, double phi_max = M_PI) {
  auto t = partial_torus(theta_max, phi_min, phi_max);
  t->set_caps(true);
  return t;
}

// Clear glass: what it shows is only what it reflects and refracts.
Material glass() {
  Material m;
  m.color = Color{0, 0, 0};
  m.ambient = 0;
  m.diffuse = 0;
  m.specular = 0;
  m.transparency = 1;
  m.reflective = 0.9;
  m.refractive_index = 1.5;
  return m;
}

TEST(TorusCapsShading, RefractionEntersAtTheCapAndLeavesThroughTheTube) {
  const auto t = capped_torus(M_PI);
  t->set_material(glass());
  const Ray r{point(-1, -5, 0.05), vector(0, 1, 0)};
  const Intersections xs = intersect_sorted(*t, r);
  ASSERT_EQ(xs.size(), 2u);
  const Computations in = prepare_computations(xs[0], r, xs);
  EXPECT_DOUBLE_EQ(in.n1, 1.0);
  EXPECT_DOUBLE_EQ(in.n2, 1.5);
  EXPECT_FALSE(in.inside);
  EXPECT_APPROX(in.normalv, vector(0, -1, 0));
  EXPECT_LT(in.under_point.y, 0 + 1e-3);  // just inside the cap
  EXPECT_GT(in.under_point.y, 0);
  const Computations out = prepare_computations(xs[1], r, xs);
  EXPECT_DOUBLE_EQ(out.n1, 1.5);
  EXPECT_DOUBLE_EQ(out.n2, 1.0);
  EXPECT_TRUE(out.inside);
}

// Along every ray through a glass capped torus, the containers algorithm
// sees one solid: entered (1 -> 1.5) and left (1.5 -> 1) in turn.
TEST(TorusCapsShading, RefractionSeesTheSolidEnteredAndLeftInTurn) {
  for (const auto& t : {capped_torus(4.4), capped_torus(2 * M_PI, 0.45, 2.75), capped_torus(5.0, -0.3, 4.0)}) {
    t->set_material(glass());
    t->set_transform(rotation_x(0.7));
    int rays = 0;
    for (int i = 0; i < 50; ++i)
      for (int j = 0; j < 50; ++j) {
        const Tuple from = point(0.3, -4, -3);
        const Tuple to = point(-1.3 + 2.6 * i / 49, -1.3 + 2.6 * j / 49, 0.05);
        const Ray r{from, normalize(to - from)};
        const Intersections xs = intersect_sorted(*t, r);
        SCOPED_TRACE(::testing::Message() << "ray " << i << ", " << j);
        ASSERT_EQ(xs.size() % 2, 0u);
        rays += !xs.empty();
        for (std::size_t k = 0; k < xs.size(); ++k) {
          const Computations c = prepare_computations(xs[k], r, xs);
          ASSERT_DOUBLE_EQ(c.n1, k % 2 ? 1.5 : 1.0) << "hit " << k;
          ASSERT_DOUBLE_EQ(c.n2, k % 2 ? 1.0 : 1.5) << "hit " << k;
          ASSERT_EQ(c.inside, k % 2 == 1) << "hit " << k;
        }
      }
    EXPECT_GT(rays, 300);
  }
}

// A glass doughnut with a bite (theta_max = 4.4) in front of a lit wall,
// seen through its cut faces: every ray must come back finite and not black.
// Open, the rays that enter through a cut see the glass from inside with no
// way out the containers agree on.
TEST(TorusCapsShading, AGlassCappedTorusShadesWithoutBlackPixels) {
  World w;
  w.lights.push_back({point(-4, 6, -8), Color{1, 1, 1}});
  const auto t = capped_torus(4.4);
  t->set_material(glass());
  // Axis up (+y), the bite towards the camera at -z.
  t->set_transform(rotation_y(2.8) * rotation_x(-M_PI / 2));
  w.objects.push_back(t);
  // A sky all round, as bright from inside as the light makes it.
  auto sky = std::make_shared<Sphere>();
  sky->set_transform(scaling(50, 50, 50));
  Material blue;
  blue.color = Color{0.5, 0.6, 0.9};
  blue.ambient = 0.5;
  sky->set_material(blue);
  sky->casts_shadow = false;
  w.objects.push_back(sky);
  auto floor = std::make_shared<Plane>();
  floor->set_transform(translation(0, -1, 0));
  Material lit;
  lit.ambient = 0.3;
  floor->set_material(lit);
  w.objects.push_back(floor);
  int through_caps = 0, dark = 0;
  for (int i = 0; i < 60; ++i)
    for (int j = 0; j < 40; ++j) {
      const Tuple from = point(0, 1.2, -5);
      const Tuple to = point(-1.5 + 3.0 * i / 59, -0.6 + 1.5 * j / 39, 0);
      const Ray r{from, normalize(to - from)};
      Intersections xs;
      t->intersect(r, xs);
      for (const Intersection& x : xs) through_caps += Torus::face_of(x) != TorusFace::Tube;
      const Color c = color_at(w, r);
      SCOPED_TRACE(::testing::Message() << "ray " << i << ", " << j);
      ASSERT_TRUE(std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b));
      dark += c.r + c.g + c.b < 0.05;
    }
  EXPECT_EQ(dark, 0);
  EXPECT_GT(through_caps, 100);
}

TEST(TorusCapsShading, ACapIsLitFromOutsideTheSolid) {
  // The cap at theta = pi faces -y; a light beyond it lights it, a light
  // behind it (inside the half torus's side) leaves it in shadow.
  const auto t = capped_torus(M_PI);
  World front, back;
  front.lights.push_back({point(-1, -10, 0), Color{1, 1, 1}});
  back.lights.push_back({point(-1, 10, 0.02), Color{1, 1, 1}});
  front.objects.push_back(t);
  back.objects.push_back(t);
  const Ray r{point(-1, -5, 0.02), vector(0, 1, 0)};
  const Color ambient = t->material().color * t->material().ambient;
  const Color lit = color_at(front, r);
  EXPECT_GT(lit.r, ambient.r + 0.5);  // head-on: ambient + diffuse + specular
  EXPECT_APPROX(color_at(back, r), ambient);
}

TEST(TorusCapsShading, TheTorusMapGivesACapPointTheUvOfTheRimBeyondIt) {
  // The map is the tube's (u: theta, v: phi, in turns). A point of a theta
  // cap has the cut's theta and the angle phi of its direction from the
  // tube's centre; a point of a phi cap has its own theta and the cut's
  // phi: each takes the uv of the rim point straight out from the centre
  // circle, so that the texture runs on across the rim.
  const double R = 1, r = 0.25;
  for (const double theta : {0.0, 1.0, 4.4})
    for (const double phi : {-2.0, -0.5, 0.3, 1.5, 3.0})
      for (const double s : {0.1, 0.5, 0.9}) {
        const double rim_rho = R + r * std::cos(phi), rho = R + s * r * std::cos(phi);
        const Tuple rim = point(rim_rho * std::cos(theta), rim_rho * std::sin(theta), r * std::sin(phi));
        const Tuple in = point(rho * std::cos(theta), rho * std::sin(theta), s * r * std::sin(phi));
        const UvCoord a = toroidal_map(R, r, rim), b = toroidal_map(R, r, in);
        EXPECT_NEAR(a.u, b.u, 1e-12);
        EXPECT_NEAR(a.v, b.v, 1e-12);
      }
  // The cap at theta = pi/2 of a quarter torus: u = 0.25 all over it; v goes
  // once round the disc (0 at its outer edge, 0.25 at its top).
  EXPECT_NEAR(toroidal_map(R, r, point(0, 1.2, 0)).u, 0.25, 1e-15);
  EXPECT_NEAR(toroidal_map(R, r, point(0, 1.2, 0)).v, 0, 1e-15);
  EXPECT_NEAR(toroidal_map(R, r, point(0, 1, 0.1)).v, 0.25, 1e-15);
  EXPECT_NEAR(toroidal_map(R, r, point(0, 0.9, 0)).v, 0.5, 1e-15);
}

}  // namespace
}  // namespace toroid
