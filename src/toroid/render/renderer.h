// SPDX-License-Identifier: Apache-2.0
// Parallel rendering of a camera's view of a world: 16x16 tiles on oneTBB,
// stratified, deterministically jittered supersampling.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>

#include "toroid/core/canvas.h"
#include "toroid/render/camera.h"
#include "toroid/render/world.h"

namespace toroid {

struct RenderProgress {
  std::int64_t pixels_done = 0;
  std::int64_t pixels_total = 0;
  double elapsed_s = 0;
  std::uint64_t rays = 0;  // rays traced so far (see rays_traced_on_this_thread)
};

// How a camera ray's colour is computed: `whitted`, the book's recursive
// Phong shading (color_at); `path`, the unbiased path tracer
// (render/path_tracer.h).
enum class Integrator { whitted, path };

struct RenderOptions {
  Integrator integrator = Integrator::whitted;
  // Samples per pixel (>= 1). 1: one ray through the pixel centre (the book).
  // N > 1: a ceil(sqrt N)-column stratified grid, each sample jittered within
  // its cell by a hash of (pixel, sample), so the image does not depend on the
  // number of threads or on scheduling.
  int samples = 1;
  // Worker threads (>= 1); 0: every core.
  int threads = 0;
  // Bounces for reflection and refraction (whitted); path vertices after the
  // camera's (path).
  int max_depth = kDefaultRemaining;
  int tile_size = 16;
  // Called now and then (at most every progress_interval_s, from a worker
  // thread, never concurrently) and once at the end.
  std::function<void(const RenderProgress&)> progress;
  double progress_interval_s = 0.25;
  // When given and set (e.g. by a signal handler), the tiles not yet begun
  // are skipped and render_image returns early with stats->cancelled set.
  const std::atomic<bool>* cancel = nullptr;
};

struct RenderStats {
  double seconds = 0;
  std::uint64_t rays = 0;  // camera + shadow + reflected + refracted rays
  int threads = 0;
  bool cancelled = false;  // stopped by RenderOptions::cancel: the image is incomplete
};

// The worker threads a render with these options uses: options.threads, or
// every core when it is 0.
int render_threads(const RenderOptions& options);

// Renders the image; fills `stats` when given. Precondition: options valid.
Canvas render_image(const Camera& camera, const World& world, const RenderOptions& options,
                    RenderStats* stats = nullptr);

// The pixels x0 <= x < x1, y0 <= y < y1.
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
  std::int64_t pixels() const { return static_cast<std::int64_t>(width()) * height(); }
};

// An image cut into tiles: squares of `size` pixels in rows from the top
// left, numbered row by row (the last column and row may be narrower).
struct TileGrid {
  int width = 0, height = 0, size = 16;
  int columns() const { return (width + size - 1) / size; }
  int rows() const { return (height + size - 1) / size; }
  int count() const { return columns() * rows(); }
  PixelRect rect(int tile) const;
};

// Receives a finished tile: its pixels row by row, top row first. Called
// from worker threads, concurrently for different tiles.
using TileSink = std::function<void(int tile, const PixelRect& rect, const Color* pixels)>;

// Renders tiles first .. first + count - 1 of the camera's image (a TileGrid
// of options.tile_size) in parallel, handing each to `sink`. A pixel comes
// out the same whichever call renders it, so that the image may be rendered
// in pieces (render_image is one call over every tile). The progress
// callback counts this call's pixels; a cancelled call skips the tiles not
// yet begun and does not hand out the tile it stopped in.
RenderStats render_tiles(const Camera& camera, const World& world, const RenderOptions& options, int first, int count,
                         const TileSink& sink);

// The sub-pixel offset (dx, dy in [0, 1)) of sample `s` of `n` for pixel (x, y).
void sample_offset(int x, int y, int s, int n, double& dx, double& dy);

}  // namespace toroid
