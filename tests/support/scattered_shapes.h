// SPDX-License-Identifier: Apache-2.0
// A scene of many shapes and random rays through it, for tests that check
// the index's queries against the book's list of every intersection.
#pragma once

#include <memory>
#include <random>
#include <vector>

#include "toroid/core/intersection.h"
#include "toroid/core/ray.h"
#include "toroid/math/transform.h"
#include "toroid/shapes/group.h"
#include "toroid/shapes/plane.h"
#include "toroid/shapes/sphere.h"
#include "toroid/shapes/torus.h"

namespace toroid {

// Spheres and tori scattered in a 20-unit cube, one group, three planes.
inline std::vector<std::shared_ptr<Shape>> scattered_shapes() {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> pos(-10, 10), angle(0, 6.283), size(0.2, 1.0);
  std::vector<std::shared_ptr<Shape>> shapes;
  for (int i = 0; i < 120; ++i) {
    std::shared_ptr<Shape> s;
    if (i % 2 == 0)
      s = std::make_shared<Sphere>();
    else
      s = std::make_shared<Torus>(1.0, 0.3);
    const double k = size(rng);
    s->set_transform(translation(pos(rng), pos(rng), pos(rng)) * rotation_y(angle(rng)) * rotation_x(angle(rng)) *
                     scaling(k, k, k));
    if (i % 7 == 0) s->casts_shadow = false;
    shapes.push_back(s);
  }
  auto g = std::make_shared<Group>();
  g->add_child(std::make_shared<Sphere>());
  g->set_transform(translation(0, 0, 12));
  shapes.push_back(g);
  // Planes, tested apart from the hierarchy by their height alone: one
  // level, one tilted and scaled, one tilted that casts no shadow.
  auto p = std::make_shared<Plane>();
  p->set_transform(translation(0, -11, 0));
  shapes.push_back(p);
  auto tilted = std::make_shared<Plane>();
  tilted->set_transform(translation(3, 12, -1) * rotation_z(0.4) * rotation_x(0.3) * scaling(2, 0.5, 3));
  shapes.push_back(tilted);
  auto clear = std::make_shared<Plane>();
  clear->set_transform(translation(0, 0, 13) * rotation_x(1.2));
  clear->casts_shadow = false;
  shapes.push_back(clear);
  return shapes;
}

inline std::vector<Ray> random_rays(int n) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> pos(-14, 14), dir(-1, 1);
  std::vector<Ray> rays;
  for (int i = 0; i < n; ++i) {
    const Tuple d = normalize(vector(dir(rng), dir(rng), dir(rng)));
    rays.push_back({point(pos(rng), pos(rng), pos(rng)), d});
  }
  return rays;
}

// The book's list: every intersection of every shape along the ray's line.
inline Intersections line_intersections(const std::vector<std::shared_ptr<Shape>>& shapes, const Ray& ray) {
  Intersections all;
  for (const auto& s : shapes) s->intersect(ray, all);
  sort_intersections(all);
  return all;
}

}  // namespace toroid
