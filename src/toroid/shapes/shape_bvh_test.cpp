// SPDX-License-Identifier: Apache-2.0
#include "toroid/shapes/shape_bvh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <span>

#include "support/scattered_shapes.h"
#include "toroid/math/transform.h"
#include "toroid/shapes/group.h"
#include "toroid/shapes/plane.h"
#include "toroid/shapes/sphere.h"
#include "toroid/shapes/torus.h"

namespace toroid {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The nearest hit by asking every shape in turn.
bool nearest_of_every_shape(const std::vector<std::shared_ptr<Shape>>& shapes, const Ray& ray, Intersection& hit) {
  bool found = false;
  double t_max = kInf;
  for (const auto& s : shapes)
    if (s->intersect_nearest(ray, t_max, hit)) {
      found = true;
      t_max = hit.t;
    }
  return found;
}

TEST(ShapeBvh, NearestHitIsTheOneEveryShapeGives) {
  const auto shapes = scattered_shapes();
  const ShapeBvh bvh(shapes);
  EXPECT_EQ(bvh.size(), shapes.size());
  int hits = 0;
  for (const Ray& ray : random_rays(3000)) {
    Intersection expected, got;
    const bool found = nearest_of_every_shape(shapes, ray, expected);
    ASSERT_EQ(bvh.intersect_nearest(ray, kInf, got), found);
    if (!found) continue;
    ++hits;
    EXPECT_EQ(got.t, expected.t);
    EXPECT_EQ(got.object, expected.object);
  }
  EXPECT_GT(hits, 1000);  // the rays do exercise the hierarchy
}

TEST(ShapeBvh, AxisParallelRaysAlongBoxFacesFindWhatEveryShapeGives) {
  // A grid of unit spheres (boxes from whole numbers to whole numbers, exact
  // in float): rays parallel to two axes, their origins on box faces and
  // edges, so that a slab test meets 0 * infinity (NaN), which must leave the
  // interval as it was, in both lanes of the two-child test as in the
  // one-box test.
  std::vector<std::shared_ptr<Shape>> shapes;
  for (int x = 0; x < 4; ++x)
    for (int y = 0; y < 4; ++y) {
      auto s = std::make_shared<Sphere>();
      s->set_transform(translation(3.0 * x, 3.0 * y, 0));
      shapes.push_back(s);
    }
  const ShapeBvh bvh(shapes);
  int hits = 0;
  for (double along : {-1.0, 0.0, 0.5, 1.0, 2.0, 3.0, 4.0})
    for (double across : {-1.0, 0.0, 1.0, 2.0, 3.0}) {
      for (const Ray& ray :
           {Ray{point(-5, along, across), vector(1, 0, 0)}, Ray{point(along, 20, across), vector(0, -1, 0)},
            Ray{point(along, across, -5), vector(0, 0, 1)}, Ray{point(along, across, 5), vector(0, 0, -1)}}) {
        Intersection expected, got;
        const bool found = nearest_of_every_shape(shapes, ray, expected);
        ASSERT_EQ(bvh.intersect_nearest(ray, kInf, got), found) << ray.origin << " " << ray.direction;
        if (!found) continue;
        ++hits;
        EXPECT_EQ(got.t, expected.t);
        EXPECT_EQ(got.object, expected.object);
      }
    }
  EXPECT_GT(hits, 20);
}

// An index of two shapes asks both once the ray enters their common box
// (not each one's box): the nearest hit and the shadow test are still every
// shape's, for two shapes apart, overlapping, and one inside the other.
TEST(ShapeBvh, AnIndexOfTwoShapesFindsWhatEveryShapeGives) {
  const auto sphere_at = [](double x, double y, double z, double radius) {
    auto s = std::make_shared<Sphere>();
    s->set_transform(translation(x, y, z) * scaling(radius, radius, radius));
    return s;
  };
  auto torus = std::make_shared<Torus>(1.0, 0.3);
  torus->set_transform(translation(2, 1, -1) * rotation_x(0.8));
  const std::vector<std::vector<std::shared_ptr<Shape>>> worlds = {
      {sphere_at(-6, 0, 0, 3), sphere_at(6, 2, 1, 4)},   // apart
      {sphere_at(0, 0, 0, 5), sphere_at(0, 0, 0, 2.5)},  // one inside the other (air in glass)
      {sphere_at(1, 0, 0, 4), torus}};                   // overlapping
  for (const auto& shapes : worlds) {
    const ShapeBvh bvh(shapes);
    int hits = 0, blocked = 0;
    for (const Ray& ray : random_rays(3000)) {
      Intersection expected, got;
      const bool found = nearest_of_every_shape(shapes, ray, expected);
      ASSERT_EQ(bvh.intersect_nearest(ray, kInf, got), found);
      if (found) {
        ++hits;
        EXPECT_EQ(got.t, expected.t);
        EXPECT_EQ(got.object, expected.object);
      }
      for (double t_max : {2.0, 8.0, kInf}) {
        const bool blocks = shapes[0]->blocks(ray, t_max) || shapes[1]->blocks(ray, t_max);
        ASSERT_EQ(bvh.blocks(ray, t_max), blocks);
        blocked += blocks;
      }
    }
    EXPECT_GT(hits, 100);  // the rays do meet the shapes
    EXPECT_GT(blocked, 100);
  }
  // The list up to the hit still leaves out a shape wholly behind the
  // origin (its box, which the list query tests).
  const auto& apart = worlds[0];
  const ShapeBvh bvh(apart);
  Intersections xs;
  const Intersection* h = bvh.intersect_up_to_hit({point(0, 0, 0), vector(1, 0.2, 0.1)}, xs);
  ASSERT_NE(h, nullptr);
  EXPECT_EQ(h->object, apart[1].get());
  EXPECT_TRUE(std::none_of(xs.begin(), xs.end(), [&](const Intersection& x) { return x.object == apart[0].get(); }));
}

// An index of three to eight shapes tests each shape's box and asks the
// shapes whose box the ray enters, nearest entry first (walk_small): the
// nearest hit and the shadow test are every shape's, for every count from
// three to nine (nine takes the hierarchy), odd and even, in a room of
// squashed-sphere walls (boxes as large as the room) with rays from inside
// and outside it.
TEST(ShapeBvh, AnIndexOfAFewShapesFindsWhatEveryShapeGives) {
  std::vector<std::shared_ptr<Shape>> pool;
  const auto wall = [&](const Matrix4& place) {
    auto s = std::make_shared<Sphere>();
    s->set_transform(place * scaling(10, 0.1, 10));
    pool.push_back(s);
  };
  wall(translation(0, -4, 0));
  wall(translation(0, 0, 8) * rotation_y(-0.7853) * rotation_x(1.5707));
  auto torus = std::make_shared<Torus>(1.0, 0.3);
  torus->set_transform(translation(2, 1, -1) * rotation_x(0.8));
  pool.push_back(torus);
  wall(translation(0, 0, 8) * rotation_y(0.7853) * rotation_x(1.5707));
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> pos(-6, 6), size(0.3, 2.0);
  for (int i = 0; i < 5; ++i) {
    auto s = std::make_shared<Sphere>();
    const double k = size(rng);
    s->set_transform(translation(pos(rng), pos(rng), pos(rng)) * scaling(k, k * 0.7, k));
    if (i == 2) s->casts_shadow = false;
    pool.push_back(s);
  }
  std::vector<Ray> rays = random_rays(1500);
  std::uniform_real_distribution<double> inside(-3, 3), dir(-1, 1);
  for (int i = 0; i < 1500; ++i)
    rays.push_back({point(inside(rng), inside(rng), inside(rng)), normalize(vector(dir(rng), dir(rng), dir(rng)))});
  for (std::size_t count = 3; count <= 9; ++count) {
    const std::vector<std::shared_ptr<Shape>> shapes(pool.begin(), pool.begin() + static_cast<std::ptrdiff_t>(count));
    const ShapeBvh bvh(shapes);
    int hits = 0, blocked = 0;
    for (const Ray& ray : rays) {
      Intersection expected, got;
      const bool found = nearest_of_every_shape(shapes, ray, expected);
      ASSERT_EQ(bvh.intersect_nearest(ray, kInf, got), found) << count << " shapes";
      if (found) {
        ++hits;
        EXPECT_EQ(got.t, expected.t) << count << " shapes";
        EXPECT_EQ(got.object, expected.object) << count << " shapes";
      }
      for (double t_max : {1.0, 4.0, kInf}) {
        const bool blocks =
            std::any_of(shapes.begin(), shapes.end(), [&](const auto& s) { return s->blocks(ray, t_max); });
        ASSERT_EQ(bvh.blocks(ray, t_max), blocks) << count << " shapes, t_max " << t_max;
        blocked += blocks;
      }
    }
    EXPECT_GT(hits, 1000) << count << " shapes";  // the rays do meet the shapes
    EXPECT_GT(blocked, 1000) << count << " shapes";
  }
}

TEST(ShapeBvh, BlocksWhenSomeShadowCasterLiesBeforeTMax) {
  const auto shapes = scattered_shapes();
  const ShapeBvh bvh(shapes);
  int blocked = 0;
  for (const Ray& ray : random_rays(3000))
    for (double t_max : {2.0, 8.0, kInf}) {
      const bool expected =
          std::any_of(shapes.begin(), shapes.end(), [&](const auto& s) { return s->blocks(ray, t_max); });
      ASSERT_EQ(bvh.blocks(ray, t_max), expected);
      blocked += expected;
    }
  EXPECT_GT(blocked, 1000);
}

// The light buffers answer each shadow ray as the walk does: lights inside
// the cloud of shapes (some boxes hold them or nearly touch them), on a box's
// face, beside it and far away; shadow rays from points around and inside
// the cloud, and from far beyond it (which walk the index instead).
TEST(ShapeBvh, ShadowRaysTowardsAPointLightAreBlockedAsTheWalkSays) {
  const auto shapes = scattered_shapes();
  const BoundingBox box1 = shapes[1]->parent_space_bounds(), box2 = shapes[2]->parent_space_bounds();
  const std::vector<Tuple> lights = {
      point(0.5, 0.3, -0.2), point(-10, 12, -10),         point(25, -3, 8), point(1000, 2000, -1500),
      point(0, 0, 12),       (box1.min + box1.max) * 0.5, box2.min};
  const ShapeBvh bvh(shapes, lights);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> near(-30, 30), far(-1e9, 1e9);
  int blocked = 0, open = 0;
  for (std::size_t light = 0; light < lights.size(); ++light)
    for (int i = 0; i < 4000; ++i) {
      const Tuple from = i % 50 == 0 ? point(far(rng), far(rng), far(rng)) : point(near(rng), near(rng), near(rng));
      const Ray ray{from, lights[light] - from};
      const bool expected = bvh.blocks(ray, 1);
      // (From a billion units away the rounding of the slab tests and of the
      // shapes' own tests may differ: there the walk is the reference.)
      if (i % 50 != 0) {
        ASSERT_EQ(expected,
                  std::any_of(shapes.begin(), shapes.end(), [&](const auto& s) { return s->blocks(ray, 1); }));
      }
      ASSERT_EQ(bvh.blocks_towards_light(light, lights[light], ray, 1), expected)
          << "light " << light << ", from " << from.x << " " << from.y << " " << from.z;
      (expected ? blocked : open) += 1;
    }
  EXPECT_GT(blocked, 2000);
  EXPECT_GT(open, 2000);
}

// A light far from every shape sees them all in a few cells, each holding
// many: more than a walk of the hierarchy tests, so it keeps no buffer (the
// index is no larger than without it); a light beside the shapes sees them
// spread over many cells, a few to a cell, and keeps one.
TEST(ShapeBvh, ALightThatSeesTheShapesManyToACellKeepsNoBuffer) {
  const auto shapes = scattered_shapes();
  const std::size_t without = ShapeBvh(shapes).bytes();
  EXPECT_EQ(ShapeBvh(shapes, std::vector<Tuple>{point(1000, 2000, -1500)}).bytes(), without);
  EXPECT_GT(ShapeBvh(shapes, std::vector<Tuple>{point(25, -3, 8)}).bytes(), without);
}

TEST(ShapeBvh, AMovedOrUnknownLightIsAnsweredByTheWalk) {
  const auto shapes = scattered_shapes();
  const ShapeBvh bvh(shapes, std::vector<Tuple>{point(0, 0, -30)});
  // A light the buffer was not built for: its shape lists would be wrong.
  const Tuple moved = point(0, 0, 0);
  int blocked = 0;
  for (const Ray& ray : random_rays(2000)) {
    const Ray shadow{ray.origin, moved - ray.origin};
    const bool expected = bvh.blocks(shadow, 1);
    EXPECT_EQ(bvh.blocks_towards_light(0, moved, shadow, 1), expected);
    EXPECT_EQ(bvh.blocks_towards_light(1, moved, shadow, 1), expected);
    blocked += expected;
  }
  EXPECT_GT(blocked, 200);
}

// Every shape made glass, or only the spheres: the index lists everything
// up to the hit only for a hit that refracts.
void make_glass(std::span<const std::shared_ptr<Shape>> shapes, bool spheres_only) {
  Material glass;
  glass.transparency = 0.9;
  glass.refractive_index = 1.5;
  for (const auto& s : shapes) {
    if (!spheres_only || dynamic_cast<const Sphere*>(s.get())) s->set_material(glass);
    if (const auto* g = dynamic_cast<const Group*>(s.get())) make_glass(g->children(), spheres_only);
  }
}

TEST(ShapeBvh, ListUpToARefractingHitHoldsEveryIntersectionBeforeItOfShapesNotBehindAndEveryPlanes) {
  const auto shapes = scattered_shapes();
  make_glass(shapes, false);
  const ShapeBvh bvh(shapes);
  Intersections got;
  int left_out = 0, planes = 0;
  for (const Ray& ray : random_rays(2000)) {
    const Intersections all = line_intersections(shapes, ray);
    const Intersection* returned = bvh.intersect_up_to_hit(ray, got);
    ASSERT_EQ(returned, hit(got));  // the hit it names is hit()'s, in its own list
    const Intersection* h = hit(all);
    if (!h) continue;  // no hit: no list to read
    const double t_hit = h->t;
    ASSERT_EQ(returned->t, t_hit);
    // It may hold some beyond the hit: the containers algorithm reads up to it.
    std::erase_if(got, [t_hit](const Intersection& x) { return x.t > t_hit; });
    sort_intersections(got);  // the index lists them in no particular order
    // Every intersection up to the hit (negative t included), in order,
    // unless all of its shape's intersections lie behind the origin; a
    // plane's always (a plane is never wholly behind).
    const auto behind = [&](const Shape* s) {
      return dynamic_cast<const Plane*>(s) == nullptr &&
             std::none_of(all.begin(), all.end(), [&](const Intersection& x) { return x.object == s && x.t >= 0; });
    };
    for (const Intersection& x : got) ASSERT_LE(x.t, t_hit);  // nothing beyond the hit
    std::size_t j = 0;
    for (const Intersection& x : all) {
      if (x.t > t_hit) break;
      if (behind(x.object)) {
        ++left_out;
        continue;
      }
      if (dynamic_cast<const Plane*>(x.object) && x.t < 0) ++planes;
      while (j < got.size() && !(got[j].t == x.t && got[j].object == x.object)) ++j;
      ASSERT_LT(j, got.size()) << "missing t = " << x.t;
    }
  }
  EXPECT_GT(left_out, 100);  // the rays do start in front of shapes
  EXPECT_GT(planes, 500);    // and have planes behind them
}

TEST(ShapeBvh, UpToTheHitNamesTheNearestHitInItsListWhetherItRefractsOrNot) {
  // Glass spheres among opaque tori, a group and planes: an opaque hit's
  // list need not be whole, but it holds the hit.
  const auto shapes = scattered_shapes();
  make_glass(shapes, true);
  const ShapeBvh bvh(shapes);
  Intersections got;
  int refracting = 0, opaque = 0, on_planes = 0;
  for (const Ray& ray : random_rays(4000)) {
    const Intersections all = line_intersections(shapes, ray);
    const Intersection* h = hit(all);
    const Intersection* returned = bvh.intersect_up_to_hit(ray, got);
    if (!h) {
      ASSERT_EQ(returned, nullptr);
      continue;
    }
    ASSERT_NE(returned, nullptr);
    ASSERT_GE(returned, got.data());
    ASSERT_LT(returned, got.data() + got.size());
    ASSERT_EQ(returned->t, h->t);
    ASSERT_EQ(returned->object, h->object);
    ++(h->object->material().transparency > 0 ? refracting : opaque);
    on_planes += dynamic_cast<const Plane*>(h->object) != nullptr;
  }
  EXPECT_GT(refracting, 100);
  EXPECT_GT(opaque, 100);
  EXPECT_GT(on_planes, 100);
}

TEST(ShapeBvh, KnowsWhetherSomethingBelowRefracts) {
  auto shapes = scattered_shapes();
  EXPECT_FALSE(ShapeBvh(shapes).any_transparent());
  auto g = std::dynamic_pointer_cast<Group>(shapes[shapes.size() - 4]);
  ASSERT_TRUE(g);
  Material glass;
  glass.transparency = 0.5;
  g->children()[0]->set_material(glass);
  EXPECT_TRUE(ShapeBvh(shapes).any_transparent());
}

TEST(ShapeBvh, SeesNothingWhenEmpty) {
  const ShapeBvh bvh;
  Intersection h;
  const Ray ray{point(0, 0, -5), vector(0, 0, 1)};
  EXPECT_FALSE(bvh.intersect_nearest(ray, kInf, h));
  EXPECT_FALSE(bvh.blocks(ray, kInf));
  EXPECT_EQ(bvh.size(), 0u);
}

// Spheres each three times the size of the last, side by side: the surface
// area heuristic alone peels them off nearly one at a time (89 levels for
// 200 spheres, past the walk's stack of 64); the index keeps within 64
// levels, and its answers stay exact.
TEST(ShapeBvh, StaysWithinItsDepthBoundOnShapesOfGrowingSizes) {
  std::vector<std::shared_ptr<Shape>> spheres;
  std::vector<std::pair<double, double>> centre_radius;
  double x = 0;
  for (int i = 0; i < 200; ++i) {
    const double radius = std::pow(3.0, i);
    x += 2.5 * radius;
    auto s = std::make_shared<Sphere>();
    s->set_transform(translation(x, 0, 0) * scaling(radius, radius, radius));
    spheres.push_back(s);
    centre_radius.emplace_back(x, radius);
  }
  const ShapeBvh bvh(spheres);
  EXPECT_GT(bvh.depth(), 32);  // the heuristic peeled down to where the median takes over
  EXPECT_LE(bvh.depth(), 64);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> offset(-0.7, 0.7);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    const auto [cx, r] = centre_radius[static_cast<std::size_t>(i) % centre_radius.size()];
    const Ray ray{point(cx + offset(rng) * r, offset(rng) * r, -10 * r), vector(0, 0, 1)};
    Intersection expected, got;
    double t_max = kInf;
    bool found = false;
    for (const auto& s : spheres)
      if (s->intersect_nearest(ray, t_max, expected)) t_max = expected.t, found = true;
    ASSERT_EQ(bvh.intersect_nearest(ray, kInf, got), found);
    if (!found) continue;
    ++hits;
    EXPECT_EQ(got.t, expected.t);
    EXPECT_EQ(got.object, expected.object);
  }
  EXPECT_GT(hits, 1000);
}

}  // namespace
}  // namespace toroid
