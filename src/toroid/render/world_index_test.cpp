// SPDX-License-Identifier: Apache-2.0
// The world's index (index_objects) changes how rays find objects, never
// what they see.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "toroid/math/transform.h"
#include "toroid/render/camera.h"
#include "toroid/render/computations.h"
#include "toroid/render/world.h"
#include "toroid/shapes/group.h"
#include "toroid/shapes/plane.h"
#include "toroid/shapes/sphere.h"
#include "toroid/shapes/torus.h"

namespace toroid {
namespace {

World torus_world(bool glass) {
  World w = default_world();
  auto floor = std::make_shared<Plane>();
  floor->set_transform(translation(0, -1, 0));
  Material floor_material = floor->material();
  floor_material.reflective = 0.3;
  floor->set_material(floor_material);
  w.objects.push_back(floor);
  for (int i = 0; i < 6; ++i) {
    auto t = std::make_shared<Torus>(0.8, 0.2);
    t->set_transform(translation(-2.5 + i, 0, 1.5) * rotation_x(0.4 * i));
    if (glass && i % 2 == 0) {
      Material t_material = t->material();
      t_material.transparency = 0.9;
      t_material.reflective = 0.9;
      t_material.refractive_index = 1.5;
      t->set_material(t_material);
    }
    w.objects.push_back(t);
  }
  return w;
}

void expect_same_picture_with_and_without_index(World w) {
  Camera camera(48, 32, 1.0);
  camera.set_transform(view_transform(point(0, 2, -6), point(0, 0, 0.5), vector(0, 1, 0)));
  const Canvas plain = render(camera, w);
  index_objects(w);
  ASSERT_EQ(w.index.size(), w.objects.size());
  const Canvas indexed = render(camera, w);
  int lit = 0;
  for (int y = 0; y < camera.vsize(); ++y)
    for (int x = 0; x < camera.hsize(); ++x) {
      const Color a = plain.pixel_at(x, y), b = indexed.pixel_at(x, y);
      ASSERT_EQ(a.r, b.r) << x << "," << y;
      ASSERT_EQ(a.g, b.g) << x << "," << y;
      ASSERT_EQ(a.b, b.b) << x << "," << y;
      lit += a.r > 0;
    }
  EXPECT_GT(lit, camera.hsize() * camera.vsize() / 2);
}

TEST(WorldIndex, OpaqueTorusWorldLooksTheSame) { expect_same_picture_with_and_without_index(torus_world(false)); }

TEST(WorldIndex, GlassTorusWorldLooksTheSame) { expect_same_picture_with_and_without_index(torus_world(true)); }

TEST(WorldIndex, ColorAtIsTheBooksWithTheWholeList) {
  // color_at takes shortcuts (the list only up to the hit and unsorted,
  // the containers only for a refracting hit, and the rays a glass torus
  // spawns carry theirs and ask for the nearest hit); the book shades every
  // ray from the sorted list of all intersections. Camera rays, and rays
  // from inside the glass tori (their hits leave the glass: n1 is the
  // glass's).
  World w = torus_world(true);
  index_objects(w);
  Camera camera(48, 32, 1.0);
  camera.set_transform(view_transform(point(0, 2, -6), point(0, 0, 0.5), vector(0, 1, 0)));
  std::vector<Ray> rays;
  for (int y = 0; y < camera.vsize(); ++y)
    for (int x = 0; x < camera.hsize(); ++x) rays.push_back(camera.ray_for_pixel(x, y));
  for (const auto& object : w.objects) {
    const auto* t = dynamic_cast<const Torus*>(object.get());
    if (t == nullptr || t->material().transparency == 0) continue;
    for (int i = 0; i < 40; ++i) {
      const double a = 0.157 * i;  // around the tube's centre circle, inside the glass
      const Tuple inside = t->transform() * point(0.8 * std::cos(a), 0.8 * std::sin(a), 0);
      rays.push_back({inside, normalize(vector(std::cos(3 * a), 0.5, std::sin(5 * a)))});
    }
  }
  // The rays refracted into a glass tube ask for their exit from inside it,
  // which the torus finds from the ray's start (intersect_torus_nearest):
  // the list's root to the solver's accuracy, not always its bits, so a
  // colour is the book's bit for bit or within the rounding that carries
  // (1e-12 here; a wrong n1 or n2 moves it by more than 1e-3).
  int leaving_glass = 0, same_bits = 0;
  for (const Ray& ray : rays) {
    Intersections xs;
    intersect_world(w, ray, xs);
    const Intersection* h = hit(xs);
    const Computations book_comps = h ? prepare_computations(*h, ray, xs) : Computations{};
    const Color book = h ? shade_hit(w, book_comps) : Color{0, 0, 0};
    const Color got = color_at(w, ray);
    ASSERT_NEAR(got.r, book.r, 1e-12);
    ASSERT_NEAR(got.g, book.g, 1e-12);
    ASSERT_NEAR(got.b, book.b, 1e-12);
    same_bits += got.r == book.r && got.g == book.g && got.b == book.b;
    leaving_glass += h && book_comps.n1 > 1;
  }
  EXPECT_GT(leaving_glass, 50);
  EXPECT_GT(same_bits, 0.9 * static_cast<double>(rays.size()));
}

// Camera rays that start inside nothing (EyeContainers) ask for the nearest
// hit: the colour is color_at's from the book's list, bit for bit.
void expect_eye_rays_as_the_books(const World& w, const Tuple& eye, const Tuple& look_at, int want_known) {
  Camera camera(48, 32, 1.0);
  camera.set_transform(view_transform(eye, look_at, vector(0, 1, 0)));
  const EyeContainers eye_containers(w, camera.ray_for_pixel(0, 0).origin);
  int known = 0;
  for (int y = 0; y < camera.vsize(); ++y)
    for (int x = 0; x < camera.hsize(); ++x) {
      const Ray ray = camera.ray_for_pixel(x, y);
      const Containers inside = eye_containers.for_ray(ray);
      known += inside.known();
      const Color book = color_at(w, ray), got = color_at(w, ray, kDefaultRemaining, inside);
      ASSERT_EQ(got.r, book.r) << x << "," << y;
      ASSERT_EQ(got.g, book.g) << x << "," << y;
      ASSERT_EQ(got.b, book.b) << x << "," << y;
    }
  if (want_known > 0) {
    EXPECT_GE(known, want_known);
  } else {
    EXPECT_EQ(known, 0);
  }
}

TEST(EyeContainers, CameraRaysFromOutsideEveryObjectSeeWhatTheBookSees) {
  World w = torus_world(true);
  index_objects(w);
  // Looking down at the glass tori: most rays' lines meet the floor ahead
  // (the top rows' rise, and meet it behind the eye).
  expect_eye_rays_as_the_books(w, point(0, 2, -6), point(0, 0, 0.5), 1000);
}

TEST(EyeContainers, RaysWhoseLineMeetsAPlaneBehindTheEyeAreUnknown) {
  // A floor of refractive index 1.3 below a glass sphere, seen from just
  // above the floor looking up: in the book's walk the rays that rise start
  // inside the floor, so a refracting hit's n1 is the floor's.
  World w;
  w.lights.push_back(PointLight{point(-10, 10, -10), Color{1, 1, 1}});
  auto floor = std::make_shared<Plane>();
  Material floor_material;
  floor_material.refractive_index = 1.3;
  floor->set_material(floor_material);
  auto ball = std::make_shared<Sphere>();
  ball->set_transform(translation(0, 1.5, 0));
  Material glass;
  glass.transparency = 0.9;
  glass.reflective = 0.5;
  glass.refractive_index = 1.5;
  ball->set_material(glass);
  w.objects = {floor, ball};
  index_objects(w);
  expect_eye_rays_as_the_books(w, point(0, 0.5, -5), point(0, 2, 0), 1);
}

TEST(EyeContainers, AnEyeInsideAnObjectsBoxOrAWorldWithOpenShapesLeavesEveryRayUnknown) {
  World w = torus_world(true);
  index_objects(w);
  // Inside the box of a torus (in its hole).
  expect_eye_rays_as_the_books(w, point(-2.5, 0, 1.5), point(0, 0, 5), 0);
  // A group among the objects.
  World grouped = torus_world(true);
  auto group = std::make_shared<Group>();
  group->add_child(std::make_shared<Sphere>());
  group->set_transform(translation(0, 3, 3));
  grouped.objects.push_back(group);
  index_objects(grouped);
  expect_eye_rays_as_the_books(grouped, point(0, 2, -6), point(0, 0, 0.5), 0);
}

TEST(WorldIndex, IsIgnoredOnceObjectsAreAdded) {
  World w = torus_world(false);
  index_objects(w);
  auto s = std::make_shared<Sphere>();
  s->set_transform(translation(0, 0, -4));  // right in front of the ray below
  w.objects.push_back(s);
  Intersection h;
  ASSERT_TRUE(intersect_nearest(w, Ray{point(0, 0, -8), vector(0, 0, 1)}, h));
  EXPECT_EQ(h.object, s.get());
}

}  // namespace
}  // namespace toroid
