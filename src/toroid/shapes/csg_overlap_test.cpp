// SPDX-License-Identifier: Apache-2.0
// CSG whose operand is a group of overlapping shapes: the operand is their
// union (the book's one flag per operand, flipped at every crossing, takes
// the second of two overlapping entries for an exit), while a mesh of
// triangles, whose pieces are each crossed once, keeps the book's rule.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "support/csg_operands.h"
#include "toroid/math/transform.h"
#include "toroid/shapes/csg.h"
#include "toroid/shapes/cube.h"
#include "toroid/shapes/group.h"
#include "toroid/shapes/sphere.h"
#include "toroid/shapes/torus.h"
#include "toroid/shapes/triangle.h"

namespace toroid {
namespace {

using testing::group_of;
using testing::intersections_of;

std::shared_ptr<Sphere> sphere_at(double x, double y, double z, double radius) {
  return testing::sphere_with(translation(x, y, z) * scaling(radius, radius, radius));
}

// The torus of the tests: R = 1, r = 0.25, its ring in the xy plane.
std::shared_ptr<Torus> doughnut() { return std::make_shared<Torus>(1.0, 0.25); }

// Two spheres of radius 0.5 centred on the tube's centre circle at x = 1,
// y = -0.3 and y = 0.3: they overlap across y = 0, where each covers the
// tube.
std::vector<std::shared_ptr<Shape>> overlapping_pair() {
  return {sphere_at(1, -0.3, 0, 0.5), sphere_at(1, 0.3, 0, 0.5)};
}

TEST(CsgOverlap, AGroupOfOverlappingSpheresCutsATorusWithNoSliceLeftBetweenThem) {
  const auto torus = doughnut();
  const Csg bite(CsgOp::Difference, torus, group_of(overlapping_pair()));
  // Along z through (1, 0.05): inside the second sphere for |z| < 0.433,
  // the first for |z| < 0.357, the tube for |z| < 0.25. The book's flag
  // takes the first sphere's entry for the cutter's exit and keeps the tube
  // between the spheres' entries and exits.
  const Ray through_overlap{point(1, 0.05, -5), vector(0, 0, 1)};
  Intersections raw;
  torus->intersect(through_overlap, raw);
  ASSERT_EQ(raw.size(), 2u);  // the ray does cross the tube
  EXPECT_TRUE(intersections_of(bite, through_overlap).empty());
  // Two more rays through the overlap, where both spheres hold the tube.
  EXPECT_TRUE(intersections_of(bite, {point(1.15, -0.04, -5), vector(0, 0, 1)}).empty());
  EXPECT_TRUE(intersections_of(bite, {point(0.5, -1, -5), vector(0.1, 0.2, 1)}).empty());
  // Beside the spheres the tube stands: through (0.6, 0.8), on the tube's
  // centre circle, the ray crosses the tube and neither sphere.
  const Ray beside{point(0.6, 0.8, -5), vector(0, 0, 1)};
  const Intersections kept = intersections_of(bite, beside);
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_EQ(kept[0].object, torus.get());
  EXPECT_EQ(kept[1].object, torus.get());
}

// The group of overlapping spheres gives what the nested union of the same
// spheres gives (which the book's rule already handled), intersection for
// intersection, for every operation and rays across the whole bite.
TEST(CsgOverlap, AGroupOfOverlappingSpheresActsAsTheirUnion) {
  for (const CsgOp op : {CsgOp::Difference, CsgOp::Intersection, CsgOp::Union}) {
    SCOPED_TRACE(static_cast<int>(op));
    const auto spheres = overlapping_pair();
    const auto third = sphere_at(1.2, 0, 0.1, 0.35);  // overlaps both
    const Csg with_group(op, doughnut(), group_of({spheres[0], spheres[1], third}));
    const auto u0 = sphere_at(1, -0.3, 0, 0.5), u1 = sphere_at(1, 0.3, 0, 0.5), u2 = sphere_at(1.2, 0, 0.1, 0.35);
    const auto inner = std::make_shared<Csg>(CsgOp::Union, u1, u2);
    const Csg with_unions(op, doughnut(), std::make_shared<Csg>(CsgOp::Union, u0, inner));
    // The same spheres in groups inside the group (as the bonus chapter's
    // divide makes them): pieces further down than the operand's children.
    const Csg with_subgroups(
        op, doughnut(),
        group_of({group_of({sphere_at(1, -0.3, 0, 0.5)}),
                  group_of({sphere_at(1, 0.3, 0, 0.5), group_of({sphere_at(1.2, 0, 0.1, 0.35)})})}));
    int differing = 0, crossings = 0;
    for (int i = 0; i <= 40; ++i)
      for (int j = 0; j <= 40; ++j) {
        const double a = 0.3 + 1.2 * i / 40, b = -0.9 + 1.8 * j / 40;
        for (const Ray& r : {Ray{point(a, b, -5), vector(0, 0, 1)}, Ray{point(a, -5, b * 0.5), vector(0, 1, 0)},
                             Ray{point(-5, b, a - 0.75), vector(1, 0.05, 0.02)}}) {
          const Intersections g = intersections_of(with_group, r), u = intersections_of(with_unions, r),
                              d = intersections_of(with_subgroups, r);
          crossings += static_cast<int>(g.size());
          bool same = g.size() == u.size() && d.size() == u.size();
          for (std::size_t k = 0; same && k < g.size(); ++k) same = g[k].t == u[k].t && d[k].t == u[k].t;
          differing += same ? 0 : 1;
        }
      }
    EXPECT_EQ(differing, 0);
    EXPECT_GT(crossings, 1000);
  }
}

// csg.feature's "Filtering a list of intersections" with each operand in a
// group of its own (the rule for groups, which must agree with the book
// where nothing overlaps).
TEST(CsgOverlap, FilteringAListOfIntersectionsOnGroupedOperands) {
  testing::expect_filtering_a_list_of_intersections([](CsgOp op, std::shared_ptr<Shape> s1, std::shared_ptr<Shape> s2) {
    return std::make_shared<Csg>(op, group_of({s1}), group_of({s2}));
  });
}

// A cube of twelve triangles: each triangle is crossed once, so the mesh's
// pieces share the book's one flag and the mesh cuts like the cube it
// encloses.
std::shared_ptr<Group> triangle_cube() {
  auto g = std::make_shared<Group>();
  const auto p = [](int i) { return point(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1); };
  // The six faces as corner indices, each split along one diagonal.
  const int faces[6][4] = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
  for (const auto& f : faces) {
    g->add_child(std::make_shared<Triangle>(p(f[0]), p(f[1]), p(f[2])));
    g->add_child(std::make_shared<Triangle>(p(f[0]), p(f[2]), p(f[3])));
  }
  return g;
}

TEST(CsgOverlap, AClosedMeshOfTrianglesKeepsTheBooksRule) {
  const auto scaled = [](std::shared_ptr<Shape> s) {
    s->set_transform(scaling(0.4, 0.4, 0.4) * translation(0, 0, 0.5));
    return s;
  };
  const Csg mesh_cut(CsgOp::Difference, std::make_shared<Sphere>(), scaled(triangle_cube()));
  const Csg cube_cut(CsgOp::Difference, std::make_shared<Sphere>(), scaled(std::make_shared<Cube>()));
  for (const double x : {-0.31, -0.13, 0.07, 0.29}) {
    const Ray r{point(x, 0.11, -5), vector(0, 0, 1)};
    const Intersections m = intersections_of(mesh_cut, r), c = intersections_of(cube_cut, r);
    ASSERT_EQ(m.size(), c.size()) << x;
    ASSERT_EQ(m.size(), 4u) << x;  // the sphere, the cube's near face, its far face, the sphere
    for (std::size_t k = 0; k < m.size(); ++k) EXPECT_NEAR(m[k].t, c[k].t, 1e-12) << x << " " << k;
  }
}

}  // namespace
}  // namespace toroid
