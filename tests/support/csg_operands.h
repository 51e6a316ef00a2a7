// SPDX-License-Identifier: Apache-2.0
// What the CSG tests build their operands from and read their answers with:
// spheres under a transform, groups, a shape's intersections as a list, and
// csg.feature's "Filtering a list of intersections" for operands that hold
// the scenario's two shapes however a test puts them there.
#pragma once

#include <gtest/gtest.h>

#include <cstddef>
#include <memory>
#include <vector>

#include "toroid/core/intersection.h"
#include "toroid/core/ray.h"
#include "toroid/math/matrix.h"
#include "toroid/shapes/csg.h"
#include "toroid/shapes/cube.h"
#include "toroid/shapes/group.h"
#include "toroid/shapes/sphere.h"

namespace toroid::testing {

inline std::shared_ptr<Sphere> sphere_with(const Matrix4& transform) {
  auto s = std::make_shared<Sphere>();
  s->set_transform(transform);
  return s;
}

inline std::shared_ptr<Group> group_of(const std::vector<std::shared_ptr<Shape>>& shapes) {
  auto g = std::make_shared<Group>();
  for (const auto& s : shapes) g->add_child(s);
  return g;
}

// What s.intersect appends for a ray in s's parent space.
inline Intersections intersections_of(const Shape& s, const Ray& r) {
  Intersections xs;
  s.intersect(r, xs);
  return xs;
}

// What s.local_intersect appends for a ray in s's object space.
inline Intersections local_intersections_of(const Shape& s, const Ray& r) {
  Intersections xs;
  s.local_intersect(r, xs);
  return xs;
}

// csg.feature's "Filtering a list of intersections": of the intersections
// of a sphere s1 and a cube s2 at t = 1 (s1), 2 (s2), 3 (s1) and 4 (s2), a
// CSG keeps the two that its operation allows, in order. make_csg(op, s1,
// s2) returns the CSG (a std::shared_ptr<Csg>), s1 in its left operand and
// s2 in its right.
template <typename MakeCsg>
void expect_filtering_a_list_of_intersections(MakeCsg make_csg) {
  struct Example {
    CsgOp op;
    std::size_t x0, x1;
  };
  const Example examples[] = {{CsgOp::Union, 0, 3}, {CsgOp::Intersection, 1, 2}, {CsgOp::Difference, 0, 1}};
  for (const Example& e : examples) {
    SCOPED_TRACE(static_cast<int>(e.op));
    std::shared_ptr<Shape> s1 = std::make_shared<Sphere>(), s2 = std::make_shared<Cube>();
    const std::shared_ptr<const Csg> c = make_csg(e.op, s1, s2);
    const Intersections xs{{1, s1.get()}, {2, s2.get()}, {3, s1.get()}, {4, s2.get()}};
    Intersections result = xs;
    c->filter_intersections(result);
    ASSERT_EQ(result.size(), 2u);
    EXPECT_EQ(result[0].t, xs[e.x0].t);
    EXPECT_EQ(result[0].object, xs[e.x0].object);
    EXPECT_EQ(result[1].t, xs[e.x1].t);
    EXPECT_EQ(result[1].object, xs[e.x1].object);
  }
}

}  // namespace toroid::testing
