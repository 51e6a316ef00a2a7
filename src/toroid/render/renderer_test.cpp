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

TEST(TileGrid, CoversTheImageRowByRowWithNarrowerLastTiles) {
  const TileGrid g{37, 23, 16};
  EXPECT_EQ(g.columns(), 3);
  EXPECT_EQ(g.rows(), 2);
  EXPECT_EQ(g.count(), 6);
  const PixelRect first = g.rect(0), third = g.rect(2), last = g.rect(5);
  EXPECT_EQ(first.x0, 0);
  EXPECT_EQ(first.x1, 16);
  EXPECT_EQ(third.x0, 32);
  EXPECT_EQ(third.x1, 37);  // 5 wide
  EXPECT_EQ(last.y0, 16);
  EXPECT_EQ(last.y1, 23);  // 7 high
  EXPECT_EQ(last.pixels(), 5 * 7);
}

// The image rendered in pieces, out of order and with other thread counts,
// is the image rendered in one call, bit for bit.
TEST(Renderer, TilesRenderedInPiecesMakeTheSameImage) {
  RenderOptions o;
  o.samples = 4;
  o.threads = 2;
  o.tile_size = 8;
  const Camera camera = test_camera();
  const World world = torus_world();
  const Canvas whole = render_image(camera, world, o);
  Canvas pieces(camera.hsize(), camera.vsize());
  auto sink = [&](int, const PixelRect& r, const Color* pixels) {
    for (int y = r.y0; y < r.y1; ++y)
      for (int x = r.x0; x < r.x1; ++x) pieces.write_pixel(x, y, *pixels++);
  };
  const int count = TileGrid{camera.hsize(), camera.vsize(), 8}.count();  // 5 x 3
  o.threads = 1;
  std::int64_t pixels = 0;
  o.progress = [&](const RenderProgress& p) { pixels = p.pixels_total; };
  render_tiles(camera, world, o, 9, count - 9, sink);
  EXPECT_EQ(pixels, 5 * 8 + 7 * 37);  // tile 9 (the second row's last, 5 wide) and the last row (7 high)
  render_tiles(camera, world, o, 0, 4, sink);
  o.threads = 3;
  render_tiles(camera, world, o, 4, 5, sink);
  EXPECT_TRUE(same_bytes(whole, pieces));
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
