// SPDX-License-Identifier: Apache-2.0
// The containers a spawned ray carries (Containers) give the n1 and n2 the
// book's list along its line gives: what the renderer sees is the same.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "toroid/math/transform.h"
#include "toroid/render/computations.h"
#include "toroid/render/world.h"
#include "toroid/shapes/csg.h"
#include "toroid/shapes/cube.h"
#include "toroid/shapes/cylinder.h"
#include "toroid/shapes/plane.h"
#include "toroid/shapes/sphere.h"
#include "toroid/shapes/torus.h"
#include "toroid/shapes/triangle.h"

namespace toroid {
namespace {

std::shared_ptr<Sphere> sphere_of_index(double index) {
  auto s = std::make_shared<Sphere>();
  Material m;
  m.refractive_index = index;
  s->set_material(m);
  return s;
}

TEST(Containers, CrossingEntersThenLeavesKeepingTheOthersInOrder) {
  const auto a = sphere_of_index(1.5), b = sphere_of_index(2.0), c = sphere_of_index(2.5);
  Containers list;
  EXPECT_TRUE(list.known());
  EXPECT_EQ(list.innermost_index(), 1.0);
  EXPECT_EQ(list.innermost_index_after(a.get()), 1.5);
  list.cross(a.get());
  list.cross(b.get());
  list.cross(c.get());
  EXPECT_EQ(list.innermost_index(), 2.5);
  EXPECT_EQ(list.innermost_index_after(c.get()), 2.0);  // leaving the innermost
  EXPECT_EQ(list.innermost_index_after(b.get()), 2.5);  // leaving one further out
  list.cross(b.get());
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(list[0], a.get());
  EXPECT_EQ(list[1], c.get());
  list.cross(c.get());
  list.cross(a.get());
  EXPECT_EQ(list.size(), 0u);
  EXPECT_EQ(list.innermost_index(), 1.0);
}

TEST(Containers, AListThatOutgrowsItsCapacityIsUnknown) {
  std::vector<std::shared_ptr<Sphere>> spheres;
  Containers list;
  for (std::size_t i = 0; i <= Containers::kCapacity; ++i) {
    spheres.push_back(sphere_of_index(1.1));
    list.cross(spheres.back().get());
  }
  EXPECT_FALSE(list.known());
  EXPECT_FALSE(Containers::unknown().known());
}

TEST(Containers, OnlyShapesThatBoundASolidOutsideCsgAreCarried) {
  EXPECT_TRUE(carried_in_containers(Sphere{}));
  EXPECT_TRUE(carried_in_containers(Cube{}));
  EXPECT_TRUE(carried_in_containers(Torus(1, 0.25)));
  EXPECT_FALSE(carried_in_containers(Plane{}));
  EXPECT_FALSE(carried_in_containers(Triangle(point(0, 0, 0), point(1, 0, 0), point(0, 1, 0))));
  Cylinder tube;
  EXPECT_FALSE(carried_in_containers(tube));  // infinite and open
  tube.minimum = -1;
  tube.maximum = 1;
  EXPECT_FALSE(carried_in_containers(tube));  // open ends
  tube.closed = true;
  EXPECT_TRUE(carried_in_containers(tube));
  Torus arc(1, 0.25);
  TorusSweep half;
  half.theta_max = std::numbers::pi;
  arc.set_sweep(half);
  EXPECT_FALSE(carried_in_containers(arc));
  arc.set_caps(true);
  EXPECT_TRUE(carried_in_containers(arc));
  const auto left = std::make_shared<Sphere>(), right = std::make_shared<Sphere>();
  const Csg lens(CsgOp::Intersection, left, right);
  EXPECT_FALSE(carried_in_containers(*left));
}

Material glass(double index) {
  Material m;
  m.color = Color{0.1, 0.1, 0.1};
  m.diffuse = 0.1;
  m.specular = 1;
  m.shininess = 300;
  m.reflective = 0.9;
  m.transparency = 0.9;
  m.refractive_index = index;
  return m;
}

// What the renderer sees against the book: color_at's spawned rays carry
// their containers, shade_hit's (from the list along the camera ray)
// build them from the list along their own lines, all the way down.
void expect_the_books_colours(World w, const Tuple& from, int* refracting) {
  index_objects(w);
  int compared = 0;
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 32; ++x) {
      const Tuple target = point(-2 + x / 8.0, 2 - y / 6.0, 0);
      const Ray ray{from, normalize(target - from)};
      Intersections xs;
      intersect_world(w, ray, xs);
      const Intersection* h = hit(xs);
      if (h == nullptr) continue;
      const Computations comps = prepare_computations(*h, ray, xs);
      const Color book = shade_hit(w, comps);
      const Color got = color_at(w, ray);
      ASSERT_EQ(got.r, book.r) << x << "," << y;
      ASSERT_EQ(got.g, book.g) << x << "," << y;
      ASSERT_EQ(got.b, book.b) << x << "," << y;
      *refracting += h->object->material().transparency > 0;
      ++compared;
    }
  EXPECT_GT(compared, 300);
}

TEST(Containers, AnAirBubbleInGlassLooksAsTheBooksList) {
  // A glass sphere holding an air bubble and a glass torus of another
  // index, over a floor: rays enter and leave nested solids.
  World w = default_world();
  w.objects.clear();
  auto floor = std::make_shared<Plane>();
  floor->set_transform(translation(0, -2, 0));
  w.objects.push_back(floor);
  auto outer = std::make_shared<Sphere>();
  outer->set_transform(scaling(2, 2, 2));
  outer->set_material(glass(1.5));
  auto bubble = std::make_shared<Sphere>();
  bubble->set_transform(translation(0.3, 0.2, 0) * scaling(0.6, 0.6, 0.6));
  bubble->set_material(glass(1.0));
  auto ring = std::make_shared<Torus>(1.2, 0.25);
  ring->set_transform(rotation_x(1.2));
  ring->set_material(glass(1.8));
  auto cube = std::make_shared<Cube>();
  cube->set_transform(translation(3, 0, 1) * scaling(0.7, 0.7, 0.7));
  cube->set_material(glass(1.3));
  for (const auto& s : std::initializer_list<std::shared_ptr<Shape>>{outer, bubble, ring, cube}) w.objects.push_back(s);
  int refracting = 0;
  expect_the_books_colours(w, point(0.2, 0.5, -6), &refracting);
  EXPECT_GT(refracting, 200);
}

TEST(Containers, AGlassLensOfCsgLooksAsTheBooksList) {
  // The book counts a CSG's crossings by the primitive hit, so the rays
  // spawned at one start from the list along their own lines.
  World w = default_world();
  w.objects.clear();
  auto left = std::make_shared<Sphere>(), right = std::make_shared<Sphere>();
  left->set_transform(translation(0, 0, 1.3) * scaling(1.6, 1.6, 1.6));
  right->set_transform(translation(0, 0, -1.3) * scaling(1.6, 1.6, 1.6));
  left->set_material(glass(1.5));
  right->set_material(glass(1.5));
  w.objects.push_back(std::make_shared<Csg>(CsgOp::Intersection, left, right));
  auto floor = std::make_shared<Plane>();
  floor->set_transform(translation(0, -2, 0));
  w.objects.push_back(floor);
  int refracting = 0;
  expect_the_books_colours(w, point(0.5, 0.4, -5), &refracting);
  EXPECT_GT(refracting, 50);
}

}  // namespace
}  // namespace toroid
