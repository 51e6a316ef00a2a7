// SPDX-License-Identifier: Apache-2.0
// `toroid render` across the ranks of an MPI job, in the manner of OSPRay's
// MPI offload. Every rank loads the scene. Rank 0 hands out runs of tiles as
// the ranks ask for them, renders tiles itself on a thread of its own,
// gathers the pixels and writes the image. A pixel is computed the same way
// whichever rank renders it (render_tiles), so the image is the
// single-process image, byte for byte.
//
// Only the main thread of each rank calls MPI (MPI_THREAD_FUNNELED).
#include <mpi.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cmd/render_job.h"

namespace toroid::cmd {

namespace {

enum Tag : int { kRequest = 1, kAssign = 2, kResult = 3, kMessage = 4, kInterrupted = 5, kNever = 6 };

int world_rank() {
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

int world_size() {
  int n = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &n);
  return n;
}

// One step's outcome on every rank (collective). Returns 0 when every rank
// succeeded; otherwise rank 0 prints the error of the lowest failing rank
// (naming it when it is not rank 0) and every rank returns that rank's exit
// status.
int agree(int exit_code, const std::string& error) {
  const int rank = world_rank(), size = world_size();
  const int mine = exit_code != 0 ? rank : size;
  int first = size;
  MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  if (first == size) return 0;
  int code = exit_code;
  MPI_Bcast(&code, 1, MPI_INT, first, MPI_COMM_WORLD);
  if (first != 0 && rank == first)
    MPI_Send(error.data(), static_cast<int>(error.size()), MPI_CHAR, 0, kMessage, MPI_COMM_WORLD);
  if (rank == 0) {
    std::string text = error;
    if (first != 0) {
      MPI_Status status;
      MPI_Probe(first, kMessage, MPI_COMM_WORLD, &status);
      int n = 0;
      MPI_Get_count(&status, MPI_CHAR, &n);
      text.assign(static_cast<std::size_t>(n), '\0');
      MPI_Recv(text.data(), n, MPI_CHAR, first, kMessage, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      text = "rank " + std::to_string(first) + ": " + text;
    }
    std::cerr << "toroid render: " << text << "\n";
  }
  return code;
}

// FNV-1a over the scene file's bytes and the options that decide the
// pixels: ranks that read different files (a stale copy on one node) or were
// given different options would make a picture of pieces.
std::uint64_t fingerprint(const RenderCommandOptions& opt, const RenderJob& job) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  auto mix = [&h](unsigned char c) { h = (h ^ c) * 0x100000001b3ULL; };
  std::ifstream in(opt.scene, std::ios::binary);
  for (std::istreambuf_iterator<char> it(in), end; it != end; ++it) mix(static_cast<unsigned char>(*it));
  // The exposure as a hexadecimal float: every bit of it counts.
  char exposure[64];
  std::snprintf(exposure, sizeof exposure, "%a", opt.exposure);
  const std::string options = std::to_string(job.camera.hsize()) + "x" + std::to_string(job.camera.vsize()) + " " +
                              std::to_string(opt.samples) + " " + std::to_string(opt.max_depth) + " " + opt.solver +
                              " " + std::to_string(job.options.tile_size) + " " +
                              integrator_option_name(job.options.integrator) + " " + exposure +
                              (opt.linear ? " linear" : "");
  for (char c : options) mix(static_cast<unsigned char>(c));
  return h;
}

// The tiles not yet handed out, in runs that shrink as the work runs out
// (guided scheduling), so that the ranks finish together.
class TileQueue {
 public:
  TileQueue(int tiles, int ranks) : tiles_(tiles), ranks_(ranks) {}

  // The next run for a rank of `threads` threads: {first, count}, count 0
  // when every tile is handed out.
  std::pair<int, int> take(int threads) {
    std::lock_guard lock(mutex_);
    const int left = tiles_ - next_;
    const int count = std::min(left, std::max(threads, std::min(left / (4 * ranks_), 16 * threads)));
    const int first = next_;
    next_ += count;
    return {first, count};
  }

 private:
  std::mutex mutex_;
  int tiles_, ranks_, next_ = 0;
};

// Ranks 1..: ask for a run, render it, send its pixels back, until rank 0
// says there is no more. The request for the next run goes out before this
// one is rendered, so that no rank waits for its next run.
int serve_as_worker(RenderJob& job) {
  const TileGrid grid{job.camera.hsize(), job.camera.vsize(), job.options.tile_size};
  const int threads = render_threads(job.options);
  MPI_Send(&threads, 1, MPI_INT, 0, kRequest, MPI_COMM_WORLD);
  std::vector<double> message;
  std::vector<std::int64_t> offsets;
  for (;;) {
    int run[2];
    MPI_Recv(run, 2, MPI_INT, 0, kAssign, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (run[1] == 0) return 0;
    MPI_Send(&threads, 1, MPI_INT, 0, kRequest, MPI_COMM_WORLD);
    // [first, count, rays, then each tile's pixels as r, g, b]
    offsets.assign(1, 3);
    for (int t = run[0]; t < run[0] + run[1]; ++t) offsets.push_back(offsets.back() + 3 * grid.rect(t).pixels());
    message.resize(static_cast<std::size_t>(offsets.back()));
    const RenderStats stats = render_tiles(job.camera, job.scene.world, job.options, run[0], run[1],
                                           [&](int tile, const PixelRect& r, const Color* pixels) {
                                             double* out = message.data() + offsets[tile - run[0]];
                                             for (std::int64_t i = 0; i < r.pixels(); ++i) {
                                               *out++ = pixels[i].r;
                                               *out++ = pixels[i].g;
                                               *out++ = pixels[i].b;
                                             }
                                           });
    if (stats.cancelled || interrupted()) {
      // Rank 0 says so and ends the job: a worker that ended first would
      // have mpirun kill rank 0 before it could. So the worker reports the
      // signal and waits, on a message that never comes, to be ended.
      int sig = interrupt_signal();
      MPI_Send(&sig, 1, MPI_INT, 0, kInterrupted, MPI_COMM_WORLD);
      MPI_Recv(&sig, 1, MPI_INT, 0, kNever, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      return interrupted_exit(false);
    }
    message[0] = run[0];
    message[1] = run[1];
    message[2] = static_cast<double>(stats.rays);
    MPI_Send(message.data(), static_cast<int>(message.size()), MPI_DOUBLE, 0, kResult, MPI_COMM_WORLD);
  }
}

struct GatherResult {
  bool interrupted = false;
  std::uint64_t rays = 0;
  double seconds = 0;
  std::vector<int> tiles;  // rendered by each rank
};

// Rank 0: hands out runs and gathers the pixels on this thread, and renders
// runs of its own on another.
GatherResult serve_as_root(RenderJob& job, Canvas& canvas, bool show_bar) {
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  const int size = world_size();
  const TileGrid grid{job.camera.hsize(), job.camera.vsize(), job.options.tile_size};
  TileQueue queue(grid.count(), size);
  std::atomic<std::int64_t> local_pixels{0};
  std::atomic<int> local_tiles{0};
  std::atomic<std::uint64_t> local_rays{0};
  std::atomic<bool> local_done{false};
  auto write = [&canvas](const PixelRect& r, const Color* pixels) {
    for (int y = r.y0; y < r.y1; ++y)
      for (int x = r.x0; x < r.x1; ++x) canvas.write_pixel(x, y, *pixels++);
  };
  std::thread local([&] {
    const int threads = render_threads(job.options);
    for (;;) {
      const auto [first, count] = queue.take(threads);
      if (count == 0 || interrupted()) break;
      const RenderStats stats = render_tiles(job.camera, job.scene.world, job.options, first, count,
                                             [&](int, const PixelRect& r, const Color* pixels) {
                                               write(r, pixels);
                                               local_pixels.fetch_add(r.pixels(), std::memory_order_relaxed);
                                               local_tiles.fetch_add(1, std::memory_order_relaxed);
                                             });
      local_rays.fetch_add(stats.rays, std::memory_order_relaxed);
      if (stats.cancelled) break;
    }
    local_done = true;
  });

  GatherResult result;
  result.tiles.assign(static_cast<std::size_t>(size), 0);
  std::int64_t remote_pixels = 0;
  std::uint64_t remote_rays = 0;
  int working = size - 1;  // ranks not yet told that the work is done
  std::int64_t total_pixels = static_cast<std::int64_t>(grid.width) * grid.height;
  auto elapsed = [&] { return std::chrono::duration<double>(clock::now() - start).count(); };
  double next_bar = 0.25;
  std::vector<double> message;
  while (working > 0 || remote_pixels + local_pixels.load() < total_pixels || !local_done) {
    if (interrupted()) {
      result.interrupted = true;
      break;
    }
    int pending = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &pending, &status);
    if (!pending) {
      if (show_bar && elapsed() >= next_bar) {
        next_bar = elapsed() + 0.25;
        draw_bar(RenderProgress{remote_pixels + local_pixels.load(), total_pixels, elapsed(),
                                remote_rays + local_rays.load()});
      }
      std::this_thread::sleep_for(std::chrono::microseconds(100));
      continue;
    }
    if (status.MPI_TAG == kRequest) {
      int threads = 1;
      MPI_Recv(&threads, 1, MPI_INT, status.MPI_SOURCE, kRequest, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      const auto [first, count] = queue.take(std::max(1, threads));
      const int run[2] = {first, count};
      if (count == 0) --working;
      MPI_Send(run, 2, MPI_INT, status.MPI_SOURCE, kAssign, MPI_COMM_WORLD);
    } else if (status.MPI_TAG == kInterrupted) {
      int sig = 0;
      MPI_Recv(&sig, 1, MPI_INT, status.MPI_SOURCE, kInterrupted, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      interrupt(sig);  // the next turn of the loop stops
    } else if (status.MPI_TAG == kResult) {
      int n = 0;
      MPI_Get_count(&status, MPI_DOUBLE, &n);
      message.resize(static_cast<std::size_t>(n));
      MPI_Recv(message.data(), n, MPI_DOUBLE, status.MPI_SOURCE, kResult, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      const int first = static_cast<int>(message[0]), count = static_cast<int>(message[1]);
      remote_rays += static_cast<std::uint64_t>(message[2]);
      result.tiles[static_cast<std::size_t>(status.MPI_SOURCE)] += count;
      const double* in = message.data() + 3;
      for (int t = first; t < first + count; ++t) {
        const PixelRect r = grid.rect(t);
        for (int y = r.y0; y < r.y1; ++y)
          for (int x = r.x0; x < r.x1; ++x, in += 3) canvas.write_pixel(x, y, Color{in[0], in[1], in[2]});
        remote_pixels += r.pixels();
      }
    }
  }
  local.join();
  result.tiles[0] = local_tiles.load();
  if (show_bar) clear_bar();
  result.interrupted = result.interrupted || interrupted();
  result.rays = remote_rays + local_rays.load();
  result.seconds = elapsed();
  return result;
}

}  // namespace

int run_render_mpi(const RenderCommandOptions& opt) {
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  const int rank = world_rank(), size = world_size();
  const auto finish = [](int code) {
    MPI_Finalize();
    return code;
  };
  if (provided < MPI_THREAD_FUNNELED)
    return finish(agree(2, "this MPI library does not allow threads (MPI_THREAD_FUNNELED)"));

  // Every rank loads the scene; rank 0 alone checks the output path and
  // prints the warnings.
  PreparedRender prepared = prepare_render(opt, rank == 0, [rank](const std::string& w) {
    if (rank == 0) std::cerr << "toroid render: " << w << "\n";
  });
  if (const int code = agree(prepared.job ? 0 : prepared.exit_code, prepared.error); code != 0) return finish(code);
  RenderJob& job = *prepared.job;

  std::uint64_t mine = fingerprint(opt, job), root = mine;
  MPI_Bcast(&root, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
  if (const int code = agree(mine == root ? 0 : 2,
                             "its scene file or options differ from rank 0's (every rank must read the same scene "
                             "file, given the same options)");
      code != 0)
    return finish(code);
  int threads = render_threads(job.options), all_threads = 0;
  MPI_Reduce(&threads, &all_threads, 1, MPI_INT, MPI_SUM, 0, MPI_COMM_WORLD);

  if (rank != 0) {
    const int code = serve_as_worker(job);
    return code == 0 ? finish(0) : code;
  }
  Canvas canvas(job.camera.hsize(), job.camera.vsize());
  const GatherResult gathered = serve_as_root(job, canvas, shows_bar(opt));
  if (gathered.interrupted) return interrupted_exit();
  const int code = write_output(canvas, opt);
  if (code == 0 && !opt.quiet) {
    std::ostringstream workers;
    workers << size << (size == 1 ? " rank, " : " ranks, ") << all_threads << " threads (tiles by rank:";
    for (int t : gathered.tiles) workers << ' ' << t;
    workers << ')';
    print_summary(canvas.width(), canvas.height(), opt.samples, job.options.integrator, workers.str(), gathered.seconds,
                  gathered.rays);
  }
  return code == 0 ? finish(0) : code;
}

}  // namespace toroid::cmd
