// SPDX-License-Identifier: Apache-2.0
#include "toroid/render/renderer.h"

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/info.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <vector>

#include "toroid/math/hash.h"
#include "toroid/render/path_tracer.h"

namespace toroid {

void sample_offset(int x, int y, int s, int n, double& dx, double& dy) {
  if (n <= 1) {
    dx = dy = 0.5;
    return;
  }
  const int cols = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
  const int rows = (n + cols - 1) / cols;
  const std::uint64_t key = (static_cast<std::uint64_t>(static_cast<std::uint32_t>(x)) << 32) ^
                            (static_cast<std::uint64_t>(static_cast<std::uint32_t>(y)) << 12) ^
                            static_cast<std::uint64_t>(s) * 0x632be59bd9b4e019ULL;
  const std::uint64_t h1 = splitmix64(key);
  const std::uint64_t h2 = splitmix64(h1);
  dx = ((s % cols) + unit_interval(h1)) / cols;
  dy = ((s / cols) + unit_interval(h2)) / rows;
}

int render_threads(const RenderOptions& options) {
  return options.threads > 0 ? options.threads : tbb::info::default_concurrency();
}

PixelRect TileGrid::rect(int tile) const {
  const int x0 = (tile % columns()) * size, y0 = (tile / columns()) * size;
  return {x0, y0, std::min(width, x0 + size), std::min(height, y0 + size)};
}

RenderStats render_tiles(const Camera& camera, const World& world, const RenderOptions& options, int first, int count,
                         const TileSink& sink) {
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  const TileGrid grid{camera.hsize(), camera.vsize(), std::max(1, options.tile_size)};
  const int threads = render_threads(options);
  const int samples = std::max(1, options.samples);
  const bool path = options.integrator == Integrator::path;
  std::int64_t total = 0;
  for (int t = first; t < first + count; ++t) total += grid.rect(t).pixels();

  std::atomic<std::int64_t> pixels_done{0};
  std::atomic<std::uint64_t> rays{0};
  std::mutex progress_mutex;
  double next_report = options.progress_interval_s;  // guarded by progress_mutex
  auto elapsed = [&] { return std::chrono::duration<double>(clock::now() - start).count(); };

  // Camera rays start at one point: where what they start inside is known,
  // they ask for the nearest hit, not the list up to it (world.h).
  const EyeContainers eye(world, camera.ray_for_pixel(0, 0).origin);
  auto cancelled = [&] { return options.cancel != nullptr && options.cancel->load(std::memory_order_relaxed); };
  auto render_tile = [&](int t, std::vector<Color>& pixels) {
    const PixelRect r = grid.rect(t);
    pixels.resize(static_cast<std::size_t>(r.pixels()));
    const std::uint64_t before = rays_traced_on_this_thread();
    Color* out = pixels.data();
    for (int y = r.y0; y < r.y1; ++y)
      for (int x = r.x0; x < r.x1; ++x) {
        if (cancelled()) return;  // per pixel: a tile of many samples can take seconds
        Color sum = kBlack;
        for (int s = 0; s < samples; ++s) {
          double dx, dy;
          sample_offset(x, y, s, samples, dx, dy);
          const Ray ray = camera.ray_for_pixel(x, y, dx, dy);
          sum += path ? trace_path(world, ray, options.max_depth, path_seed(x, y, s))
                      : color_at(world, ray, options.max_depth, eye.for_ray(ray));
        }
        *out++ = samples == 1 ? sum : sum / static_cast<double>(samples);
      }
    sink(t, r, pixels.data());
    rays.fetch_add(rays_traced_on_this_thread() - before, std::memory_order_relaxed);
    const std::int64_t done = pixels_done.fetch_add(r.pixels()) + r.pixels();
    if (options.progress && done < total) {
      std::unique_lock lock(progress_mutex, std::try_to_lock);
      if (lock.owns_lock()) {
        const double e = elapsed();
        if (e >= next_report) {
          next_report = e + options.progress_interval_s;
          options.progress(RenderProgress{done, total, e, rays.load(std::memory_order_relaxed)});
        }
      }
    }
  };

  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
    tbb::task_arena arena(threads);
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<int>(first, first + count, 1), [&](const tbb::blocked_range<int>& range) {
        std::vector<Color> pixels;
        for (int t = range.begin(); t != range.end(); ++t) render_tile(t, pixels);
      });
    });
  }
  const double seconds = elapsed();
  const bool stopped = cancelled();
  if (options.progress && !stopped) options.progress(RenderProgress{total, total, seconds, rays.load()});
  return RenderStats{seconds, rays.load(), threads, stopped};
}

Canvas render_image(const Camera& camera, const World& world, const RenderOptions& options, RenderStats* stats) {
  Canvas canvas(camera.hsize(), camera.vsize());
  const TileGrid grid{camera.hsize(), camera.vsize(), std::max(1, options.tile_size)};
  const RenderStats s =
      render_tiles(camera, world, options, 0, grid.count(), [&](int, const PixelRect& r, const Color* pixels) {
        for (int y = r.y0; y < r.y1; ++y)
          for (int x = r.x0; x < r.x1; ++x) canvas.write_pixel(x, y, *pixels++);
      });
  if (stats) *stats = s;
  return canvas;
}

}  // namespace toroid
