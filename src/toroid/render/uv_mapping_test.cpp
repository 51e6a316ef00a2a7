// SPDX-License-Identifier: Apache-2.0
// Texture mapping bonus chapter: spherical, planar, cylindrical and cube
// mappings; then the torus mapping and the inverse maps (beyond the book).
#include "toroid/render/uv_mapping.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "support/approx.h"

namespace toroid {
namespace {

struct UvCase {
  Tuple p;
  double u, v;
};

void expect_uv(UvCoord (*map)(const Tuple&), std::initializer_list<UvCase> cases) {
  for (const UvCase& c : cases) {
    SCOPED_TRACE(::testing::Message() << "point " << c.p);
    const UvCoord uv = map(c.p);
    EXPECT_NEAR(uv.u, c.u, kEpsilon);
    EXPECT_NEAR(uv.v, c.v, kEpsilon);
  }
}

TEST(UvMappings, UsingASphericalMappingOnA3DPoint) {
  const double h = std::sqrt(2) / 2;
  expect_uv(spherical_map, {{point(0, 0, -1), 0.0, 0.5},
                            {point(1, 0, 0), 0.25, 0.5},
                            {point(0, 0, 1), 0.5, 0.5},
                            {point(-1, 0, 0), 0.75, 0.5},
                            {point(0, 1, 0), 0.5, 1.0},
                            {point(0, -1, 0), 0.5, 0.0},
                            {point(h, h, 0), 0.25, 0.75}});
}

TEST(UvMappings, UsingAPlanarMappingOnA3DPoint) {
  expect_uv(planar_map, {{point(0.25, 0, 0.5), 0.25, 0.5},
                         {point(0.25, 0, -0.25), 0.25, 0.75},
                         {point(0.25, 0.5, -0.25), 0.25, 0.75},
                         {point(1.25, 0, 0.5), 0.25, 0.5},
                         {point(0.25, 0, -1.75), 0.25, 0.25},
                         {point(1, 0, -1), 0.0, 0.0},
                         {point(0, 0, 0), 0.0, 0.0}});
}

TEST(UvMappings, UsingACylindricalMappingOnA3DPoint) {
  expect_uv(cylindrical_map, {{point(0, 0, -1), 0.0, 0.0},
                              {point(0, 0.5, -1), 0.0, 0.5},
                              {point(0, 1, -1), 0.0, 0.0},
                              {point(0.70711, 0.5, -0.70711), 0.125, 0.5},
                              {point(1, 0.5, 0), 0.25, 0.5},
                              {point(0.70711, 0.5, 0.70711), 0.375, 0.5},
                              {point(0, -0.25, 1), 0.5, 0.75},
                              {point(-0.70711, 0.5, 0.70711), 0.625, 0.5},
                              {point(-1, 1.25, 0), 0.75, 0.25},
                              {point(-0.70711, 0.5, -0.70711), 0.875, 0.5}});
}

TEST(UvMappings, IdentifyingTheFaceOfACubeFromAPoint) {
  EXPECT_EQ(face_from_point(point(-1, 0.5, -0.25)), CubeFace::Left);
  EXPECT_EQ(face_from_point(point(1.1, -0.75, 0.8)), CubeFace::Right);
  EXPECT_EQ(face_from_point(point(0.1, 0.6, 0.9)), CubeFace::Front);
  EXPECT_EQ(face_from_point(point(-0.7, 0, -2)), CubeFace::Back);
  EXPECT_EQ(face_from_point(point(0.5, 1, 0.9)), CubeFace::Up);
  EXPECT_EQ(face_from_point(point(-0.2, -1.3, 1.1)), CubeFace::Down);
}

TEST(UvMappings, UvMappingTheFrontFaceOfACube) {
  expect_uv(cube_uv_front, {{point(-0.5, 0.5, 1), 0.25, 0.75}, {point(0.5, -0.5, 1), 0.75, 0.25}});
}

TEST(UvMappings, UvMappingTheBackFaceOfACube) {
  expect_uv(cube_uv_back, {{point(0.5, 0.5, -1), 0.25, 0.75}, {point(-0.5, -0.5, -1), 0.75, 0.25}});
}

TEST(UvMappings, UvMappingTheLeftFaceOfACube) {
  expect_uv(cube_uv_left, {{point(-1, 0.5, -0.5), 0.25, 0.75}, {point(-1, -0.5, 0.5), 0.75, 0.25}});
}

TEST(UvMappings, UvMappingTheRightFaceOfACube) {
  expect_uv(cube_uv_right, {{point(1, 0.5, 0.5), 0.25, 0.75}, {point(1, -0.5, -0.5), 0.75, 0.25}});
}

TEST(UvMappings, UvMappingTheUpperFaceOfACube) {
  expect_uv(cube_uv_up, {{point(-0.5, 1, -0.5), 0.25, 0.75}, {point(0.5, 1, 0.5), 0.75, 0.25}});
}

TEST(UvMappings, UvMappingTheLowerFaceOfACube) {
  expect_uv(cube_uv_down, {{point(-0.5, -1, 0.5), 0.25, 0.75}, {point(0.5, -1, -0.5), 0.75, 0.25}});
}

// Beyond the book ------------------------------------------------------------

// The book's u = 1 - (raw_u + 0.5) is 1 for a point at -z with x = -0: wrap
// to 0, so that u stays in [0, 1) like every other mapping.
TEST(UvMappings, SphericalAndCylindricalUStayBelowOne) {
  EXPECT_EQ(spherical_map(point(-0.0, 0, -1)).u, 0.0);
  EXPECT_EQ(cylindrical_map(point(-0.0, 0.5, -1)).u, 0.0);
}

// The point of a torus (R, r) at angle a around the axis, b around the tube.
Tuple torus_point(double R, double r, double a, double b) {
  const double rho = R + r * std::cos(b);
  return point(rho * std::cos(a), rho * std::sin(a), r * std::sin(b));
}

UvCoord torus_uv(const Tuple& p) { return toroidal_map(1.0, 0.25, p); }

TEST(UvMappings, TheTorusMappingAtKnownPoints) {
  // u: around the axis from +x towards +y; v: around the tube from the
  // outer equator over the top (+z), past the inner equator and the bottom.
  expect_uv(torus_uv, {{point(1.25, 0, 0), 0.0, 0.0},
                       {point(0, 1.25, 0), 0.25, 0.0},
                       {point(-1.25, 0, 0), 0.5, 0.0},
                       {point(0, -1.25, 0), 0.75, 0.0},
                       {point(1, 0, 0.25), 0.0, 0.25},
                       {point(0.75, 0, 0), 0.0, 0.5},
                       {point(0, 0.75, 0), 0.25, 0.5},
                       {point(1, 0, -0.25), 0.0, 0.75},
                       {point(-0.75, 0, 0), 0.5, 0.5},
                       {point(0, -1, 0.25), 0.75, 0.25}});
}

// Every point of tori thin, fat, horn and spindle maps to the angles it was
// made from: u, v in [0, 1) whatever the radii.
TEST(UvMappings, TheTorusMappingRecoversTheAnglesForAnyRadii) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> turn(0.0, 1.0);
  const double radii[][2] = {{1, 0.25}, {1, 0.01}, {3, 1.5}, {1, 1}, {1, 1.6}, {1e3, 10}};
  for (const auto& rr : radii) {
    for (int i = 0; i < 2000; ++i) {
      const double u = turn(rng), v = turn(rng);
      const Tuple p = torus_point(rr[0], rr[1], 2 * std::numbers::pi * u, 2 * std::numbers::pi * v);
      // Points of a spindle's inner lemon (R + r cos v < 0) are across the
      // axis from their tube centre: they map back to their own angles too.
      const UvCoord uv = toroidal_map(rr[0], rr[1], p);
      ASSERT_GE(uv.u, 0.0);
      ASSERT_LT(uv.u, 1.0);
      ASSERT_GE(uv.v, 0.0);
      ASSERT_LT(uv.v, 1.0);
      // Distances on the circle of turns (0.999999 is next to 0).
      const double du = std::remainder(uv.u - u, 1.0), dv = std::remainder(uv.v - v, 1.0);
      EXPECT_LT(std::abs(du), 1e-9) << "R " << rr[0] << " r " << rr[1] << " u " << u << " v " << v;
      EXPECT_LT(std::abs(dv), 1e-9) << "R " << rr[0] << " r " << rr[1] << " u " << u << " v " << v;
    }
  }
}

// No seam: points a hair either side of u = 0 (the +x half-plane) and of
// v = 0 (the outer equator) map next to each other on the circle of turns,
// and the values just below 1 never round up to 1.
TEST(UvMappings, TheTorusMappingIsContinuousAcrossBothSeams) {
  for (const double eps : {1e-3, 1e-9, 1e-15}) {
    SCOPED_TRACE(eps);
    const UvCoord below_u = torus_uv(torus_point(1, 0.25, -eps, 0.3));
    const UvCoord above_u = torus_uv(torus_point(1, 0.25, eps, 0.3));
    EXPECT_LT(below_u.u, 1.0);
    EXPECT_GT(below_u.u, 0.99);
    EXPECT_LT(above_u.u, 0.01);
    EXPECT_LT(std::abs(std::remainder(above_u.u - below_u.u, 1.0)), 2 * eps);
    EXPECT_NEAR(below_u.v, above_u.v, 1e-12);

    const UvCoord below_v = torus_uv(torus_point(1, 0.25, 2.0, -eps));
    const UvCoord above_v = torus_uv(torus_point(1, 0.25, 2.0, eps));
    EXPECT_LT(below_v.v, 1.0);
    EXPECT_GT(below_v.v, 0.99);
    EXPECT_LT(above_v.v, 0.01);
    EXPECT_LT(std::abs(std::remainder(above_v.v - below_v.v, 1.0)), 2 * eps);
    EXPECT_NEAR(below_v.u, above_v.u, 1e-12);
  }
  // Exactly on the seams, and on the -x half-plane where atan2 jumps.
  EXPECT_EQ(torus_uv(point(1.25, 0, 0)).u, 0.0);
  EXPECT_EQ(torus_uv(point(1.25, -0.0, 0)).u, 0.0);
  EXPECT_EQ(torus_uv(point(1.25, 0, -0.0)).v, 0.0);
  EXPECT_NEAR(torus_uv(point(-1.25, 1e-15, 0)).u, 0.5, 1e-12);
  EXPECT_NEAR(torus_uv(point(-1.25, -1e-15, 0)).u, 0.5, 1e-12);
}

// A point off the surface (rounding, or a scaled pattern) still maps by its
// angles; a point on the axis of a spindle torus (its apex) maps without NaN.
TEST(UvMappings, TheTorusMappingOffTheSurfaceAndOnTheAxis) {
  const UvCoord off = toroidal_map(2, 0.5, point(0, 2.0 + 1e-6, 0.7));
  EXPECT_NEAR(off.u, 0.25, 1e-12);
  EXPECT_NEAR(off.v, 0.25, 1e-5);
  const UvCoord apex = toroidal_map(1, 2, point(0, 0, std::sqrt(3.0)));
  EXPECT_FALSE(std::isnan(apex.u));
  EXPECT_FALSE(std::isnan(apex.v));
  // The apex is where R + r cos v = 0: v = arccos(-1/2) / 2 pi = 1/3.
  EXPECT_NEAR(apex.v, 1.0 / 3.0, 1e-12);
}

TEST(UvMappings, TheInverseMapsRoundTrip) {
  for (double u = 0.05; u < 1; u += 0.1)
    for (double v = 0.05; v < 1; v += 0.1) {
      const UvCoord s = spherical_map(spherical_point({u, v}));
      EXPECT_NEAR(s.u, u, 1e-12);
      EXPECT_NEAR(s.v, v, 1e-12);
      EXPECT_NEAR(magnitude(spherical_point({u, v}) - point(0, 0, 0)), 1.0, 1e-12);
      for (const CubeFace f :
           {CubeFace::Left, CubeFace::Right, CubeFace::Front, CubeFace::Back, CubeFace::Up, CubeFace::Down}) {
        const Tuple p = cube_point(f, {u, v});
        EXPECT_EQ(face_from_point(p), f);
        const UvCoord c = cube_uv(f, p);
        EXPECT_NEAR(c.u, u, 1e-12);
        EXPECT_NEAR(c.v, v, 1e-12);
      }
    }
}

}  // namespace
}  // namespace toroid
