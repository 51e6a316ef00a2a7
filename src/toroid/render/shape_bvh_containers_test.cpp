// SPDX-License-Identifier: Apache-2.0
// The index's list up to the hit gives the refraction the book's list gives.
#include <gtest/gtest.h>

#include <vector>

#include "support/scattered_shapes.h"
#include "toroid/render/computations.h"
#include "toroid/shapes/shape_bvh.h"

namespace toroid {
namespace {

TEST(ShapeBvhContainers, ListUpToTheHitGivesTheContainersOfTheWholeLine) {
  // Glass spheres, tori (closed surfaces, some overlapping) and planes
  // (each one toggles the containers): n1 and n2 from the index's list are
  // those of the book's list of every intersection along the line.
  auto shapes = scattered_shapes();
  shapes.erase(shapes.end() - 4);  // no group
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    Material glass;
    glass.transparency = 0.9;
    glass.refractive_index = 1.1 + 0.01 * static_cast<double>(i);
    shapes[i]->set_material(glass);
  }
  const ShapeBvh bvh(shapes);
  Intersections got;
  int compared = 0;
  for (const Ray& ray : random_rays(12000)) {
    const Intersections all = line_intersections(shapes, ray);
    const Intersection* h = hit(all);
    if (!h) continue;
    bvh.intersect_up_to_hit(ray, got);
    std::erase_if(got, [&h](const Intersection& x) { return x.t > h->t; });
    sort_intersections(got);
    const Intersection* g = hit(got);
    ASSERT_TRUE(g);
    ASSERT_EQ(g->t, h->t);
    const Computations want = prepare_computations(*h, ray, all);
    const Computations have = prepare_computations(*g, ray, got);
    EXPECT_EQ(have.n1, want.n1);
    EXPECT_EQ(have.n2, want.n2);
    ++compared;
  }
  EXPECT_GT(compared, 1000);
}

}  // namespace
}  // namespace toroid
