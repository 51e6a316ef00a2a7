// SPDX-License-Identifier: Apache-2.0
#include "toroid/render/renderer.h"

#include <gtest/gtest.h>

#include <cstring>

#include "toroid/math/transform.h"
#include "toroid/shapes/plane.h"
#include "toroid/shapes/torus.h"

namespace toroid {
namespace {

World torus_world() {
  World w = default_world();
  auto t = std::make_shared<Torus>(1.0, 0.3);
  t->set_transform(translation(0, 0, -1.5) * rotation_x(1.0));
  Material t_material = t->material();
  t_material.reflective = 0.3;
  t->set_material(t_material);
  w.objects.push_back(t);
  auto p = std::make_shared<Plane>();
  p->set_transform(translation(0, -1, 0));
  w.objects.push_back(p);
  return w;
}

Camera test_camera() {
  Camera c(37, 23, 1.2);
  c.set_transform(view_transform(point(0, 1.5, -6), point(0, 0, 0), vector(0, 1, 0)));
  return c;
}

bool same_bytes(const Canvas& a, const Canvas& b) {
  return a.width() == b.width() && a.height() == b.height() &&
         std::memcmp(a.pixels().data(), b.pixels().data(), a.pixels().size() * sizeof(Color)) == 0;
}

TEST(Renderer, OneSampleMatchesTheBooksRender) {
  const World w = torus_world();
  const Camera c = test_camera();
  RenderOptions o;
  o.threads = 2;
  EXPECT_TRUE(same_bytes(render_image(c, w, o), render(c, w)));
}

// Renders `w` with 1 and then 2 threads; expects the same image and ray
// count; returns the one-thread statistics.
RenderStats expect_same_with_one_and_two_threads(const World& w, int samples) {
  const Camera c = test_camera();
  RenderOptions o;
  o.samples = samples;
  o.tile_size = 8;
  o.threads = 1;
  RenderStats s1, s2;
  const Canvas one = render_image(c, w, o, &s1);
  o.threads = 2;
  const Canvas two = render_image(c, w, o, &s2);
  EXPECT_TRUE(same_bytes(one, two));
  EXPECT_EQ(s1.threads, 1);
  EXPECT_EQ(s2.threads, 2);
  EXPECT_EQ(s1.rays, s2.rays);
  return s1;
}

TEST(Renderer, ThreadCountDoesNotChangeTheImage) {
  const RenderStats s = expect_same_with_one_and_two_threads(torus_world(), 5);
  EXPECT_GE(s.rays, 37u * 23u * 5u);  // at least the camera rays
}

TEST(Renderer, AJitteredAreaLightDoesNotDependOnTheThreadCount) {
  World w = torus_world();
  w.lights.clear();
  w.area_lights.emplace_back(point(-3, 4, -4), vector(2, 0, 0), 4, vector(0, 2, 0), 3, Color{1, 1, 1}, true);
  const RenderStats s = expect_same_with_one_and_two_threads(w, 2);
  // Well over the camera rays: 12 shadow rays per lit shade.
  EXPECT_GT(s.rays, 37u * 23u * 2u * 4u);
}

TEST(Renderer, SamplesStayInTheirPixel) {
  for (int n : {1, 2, 4, 9, 10})
    for (int s = 0; s < n; ++s) {
      double dx, dy;
      sample_offset(3, 7, s, n, dx, dy);
      EXPECT_GE(dx, 0);
      EXPECT_LT(dx, 1);
      EXPECT_GE(dy, 0);
      EXPECT_LT(dy, 1);
    }
}

TEST(Renderer, ProgressEndsAtTheTotal) {
  RenderOptions o;
  o.threads = 2;
  RenderProgress last;
  o.progress = [&](const RenderProgress& p) { last = p; };
  render_image(test_camera(), torus_world(), o);
  EXPECT_EQ(last.pixels_done, 37 * 23);
  EXPECT_EQ(last.pixels_total, 37 * 23);
}

TEST(Renderer, ACancelledRenderStopsAndSaysSo) {
  std::atomic<bool> cancel{true};
  RenderOptions o;
  o.threads = 2;
  o.cancel = &cancel;
  RenderStats stats;
  render_image(test_camera(), torus_world(), o, &stats);
  EXPECT_TRUE(stats.cancelled);
  EXPECT_EQ(stats.rays, 0u);  // no tile began
}

TEST(Renderer, CancellingMidwaySkipsTheRemainingTiles) {
  std::atomic<bool> cancel{false};
  RenderOptions o;
  o.threads = 1;
  o.tile_size = 4;
  o.cancel = &cancel;
  o.progress_interval_s = 0;
  std::int64_t last_done = 0;
  o.progress = [&](const RenderProgress& p) {
    last_done = p.pixels_done;
    cancel = true;  // after the first tile
  };
  RenderStats stats;
  render_image(test_camera(), torus_world(), o, &stats);
  EXPECT_TRUE(stats.cancelled);
  EXPECT_EQ(last_done, 16);  // one 4x4 tile, and no final report
}

TEST(Renderer, AnUncancelledRenderIsComplete) {
  std::atomic<bool> cancel{false};
  RenderOptions o;
  o.cancel = &cancel;
  RenderStats stats;
  render_image(test_camera(), torus_world(), o, &stats);
  EXPECT_FALSE(stats.cancelled);
}

}  // namespace
}  // namespace toroid
