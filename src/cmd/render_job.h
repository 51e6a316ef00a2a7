// SPDX-License-Identifier: Apache-2.0
// The steps of `toroid render` that the single-process render and the MPI
// render (mpi/mpi_render.cpp) share: its options, the checks and the scene
// load before a render, the progress bar, interrupts and the output.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "toroid/core/canvas.h"
#include "toroid/io/image_writer.h"
#include "toroid/render/camera.h"
#include "toroid/render/renderer.h"
#include "toroid/scene/scene_loader.h"

namespace toroid::cmd {

struct RenderCommandOptions {
  std::string scene;
  std::string output;
  std::optional<int> width, height;
  int samples = 1;
  std::optional<int> threads;
  int max_depth = kDefaultRemaining;
  int tile_size = 16;
  std::string solver;
  double exposure = 0;     // stops: every pixel times 2^exposure when written
  bool linear = false;     // a PNG of the linear values (PNG output only)
  std::string integrator;  // "whitted" or "path"; empty: the scene's, else whitted
  bool quiet = false;
};

// The --exposure range, in stops.
inline constexpr double kMaxExposureStops = 32;

// "whitted" or "path" (the --integrator names), and back.
const char* integrator_option_name(Integrator integrator);
std::optional<Integrator> integrator_from_option(const std::string& name);

// A scene loaded and checked, ready to render.
struct RenderJob {
  Scene scene;
  Camera camera;          // with --width and --height applied
  RenderOptions options;  // integrator, samples, threads, depth; cancelled by interrupts
};

// The job, or why there is none: `error` (without the "toroid render: "
// prefix) and the exit status.
struct PreparedRender {
  std::optional<RenderJob> job;
  std::string error;
  int exit_code = 2;
};

// Checks --linear against the output's format and the output path (when
// `check_output`), loads the scene (its warnings go to `on_warning`) and
// applies the size options and the integrator (--integrator, else the
// scene's, else whitted).
PreparedRender prepare_render(const RenderCommandOptions& opt, bool check_output,
                              const std::function<void(const std::string&)>& on_warning);

// Writes the image atomically, with --exposure and --linear; the exit
// status (0; 1 when it cannot be written, with a message; 128 + signal when
// interrupted).
int write_output(const Canvas& canvas, const RenderCommandOptions& opt);
// The same for the 8-bit codes of a PNG or PPM (encoded with --exposure and
// --linear already).
int write_output(const Image8& image, const RenderCommandOptions& opt);

// The final line: "WxH, N samples, WORKERS, S s, R rays, M Mrays/s", with
// "path integrator, " before WORKERS for the path tracer.
void print_summary(int width, int height, int samples, Integrator integrator, const std::string& workers,
                   double seconds, std::uint64_t rays);

// SIGINT and SIGTERM set interrupted(); interrupted_exit() says so (unless
// told not to) and gives the exit status, 128 + the signal. interrupt(sig)
// records an interrupt as the handler does (rank 0 of an MPI job takes on
// the interrupt a worker reports); interrupt_signal() is the signal
// recorded, 0 when none.
void catch_interrupts();
const std::atomic<bool>& interrupted();
void interrupt(int sig);
int interrupt_signal();
int interrupted_exit(bool say = true);

// The progress bar on stderr (when shows_bar: a terminal, not --quiet).
bool shows_bar(const RenderCommandOptions& opt);
void draw_bar(const RenderProgress& p);
void clear_bar();

// The render across the ranks of an MPI job (built with TOROID_MPI).
int run_render_mpi(const RenderCommandOptions& opt);

}  // namespace toroid::cmd
