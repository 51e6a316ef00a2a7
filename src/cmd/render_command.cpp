// SPDX-License-Identifier: Apache-2.0
// `toroid render`: a YAML scene to a PNG, PPM or OpenEXR image.
#include "cmd/render_command.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "cmd/cli.h"
#include "cmd/mpi_launch.h"
#include "cmd/render_job.h"
#include "toroid/io/image_writer.h"
#include "toroid/render/image_limits.h"
#include "toroid/render/renderer.h"
#include "toroid/scene/scene_loader.h"

namespace toroid::cmd {

std::string format_duration(double s) {
  if (!std::isfinite(s) || s < 0) return "--:--";
  const long t = std::lround(s);
  char buf[32];
  if (t >= 3600)
    std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", t / 3600, (t / 60) % 60, t % 60);
  else
    std::snprintf(buf, sizeof buf, "%02ld:%02ld", t / 60, t % 60);
  return buf;
}

void draw_bar(const RenderProgress& p) {
  const double frac = p.pixels_total > 0 ? static_cast<double>(p.pixels_done) / p.pixels_total : 1.0;
  constexpr int kWidth = 30;
  const int filled = static_cast<int>(frac * kWidth);
  std::string bar(static_cast<std::size_t>(filled), '#');
  bar.append(static_cast<std::size_t>(kWidth - filled), '-');
  const double eta = frac > 0 ? p.elapsed_s * (1 - frac) / frac : NAN;
  const double mrays = p.elapsed_s > 0 ? p.rays / p.elapsed_s / 1e6 : 0;
  std::fprintf(stderr, "\r[%s] %5.1f%%  elapsed %s  ETA %s  %.2f Mrays/s\x1b[K", bar.c_str(), frac * 100,
               format_duration(p.elapsed_s).c_str(), format_duration(eta).c_str(), mrays);
  std::fflush(stderr);
}

void clear_bar() { std::fputs("\r\x1b[K", stderr); }

bool shows_bar(const RenderCommandOptions& opt) { return !opt.quiet && isatty(STDERR_FILENO); }

namespace {

// SIGINT / SIGTERM: the handler only records the signal; the render skips its
// remaining tiles, or the image write stops and removes its temporary file,
// and the command exits 128 + signal without writing.
static_assert(std::atomic<bool>::is_always_lock_free, "the signal handler needs a lock-free flag");
std::atomic<bool> g_interrupted{false};
volatile std::sig_atomic_t g_signal = 0;

extern "C" void on_interrupt(int sig) {
  g_signal = sig;
  g_interrupted.store(true, std::memory_order_relaxed);
}

}  // namespace

void interrupt(int sig) { on_interrupt(sig); }

int interrupt_signal() { return g_signal; }

void catch_interrupts() {
  struct sigaction sa {};
  sa.sa_handler = on_interrupt;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

const std::atomic<bool>& interrupted() { return g_interrupted; }

int interrupted_exit(bool say) {
  if (say) std::cerr << "toroid render: interrupted; nothing written\n";
  return 128 + g_signal;
}

const char* integrator_option_name(Integrator integrator) {
  return integrator == Integrator::path ? "path" : "whitted";
}

std::optional<Integrator> integrator_from_option(const std::string& name) {
  if (name == "whitted") return Integrator::whitted;
  if (name == "path") return Integrator::path;
  return std::nullopt;
}

PreparedRender prepare_render(const RenderCommandOptions& opt, bool check_output,
                              const std::function<void(const std::string&)>& on_warning) {
  PreparedRender out;
  // Everything that can be checked is checked before the render starts.
  // --linear changes only how a PNG encodes; PPM and EXR files are linear
  // already, and a flag that would change nothing is refused rather than
  // left to look as if it did something. (An unknown extension is
  // check_image_path's to report.)
  if (const std::optional<ImageFormat> format = image_format_of(opt.output);
      opt.linear && format && *format != ImageFormat::png) {
    out.error = "--linear is for .png output only: '" + opt.output + "' holds linear values already (drop --linear)";
    return out;
  }
  if (check_output) {
    try {
      check_image_path(opt.output);
    } catch (const ImageWriteError& e) {
      out.error = e.what();
      return out;
    }
  }
  SceneLoadOptions load_options;
  if (!opt.solver.empty()) load_options.solver = solver_from_name(opt.solver);
  load_options.on_warning = on_warning;
  std::optional<Scene> scene;
  try {
    scene.emplace(load_scene(opt.scene, load_options));
  } catch (const SceneError& e) {
    out.error = e.what();
    return out;
  }
  Camera camera = scene->camera;
  if (opt.width || opt.height) {
    const int w = opt.width.value_or(camera.hsize()), h = opt.height.value_or(camera.vsize());
    if (const std::string e = image_size_error(w, h); !e.empty()) {
      out.error = "image size: " + e;
      return out;
    }
    camera = Camera(w, h, camera.field_of_view());
    camera.set_transform(scene->camera.transform());
  }
  RenderOptions ro;
  ro.integrator = integrator_from_option(opt.integrator).value_or(scene->integrator.value_or(Integrator::whitted));
  ro.samples = opt.samples;
  ro.threads = opt.threads.value_or(0);
  ro.max_depth = opt.max_depth;
  ro.tile_size = opt.tile_size;
  ro.cancel = &g_interrupted;
  out.job.emplace(RenderJob{std::move(*scene), camera, ro});
  out.exit_code = 0;
  return out;
}

namespace {

// Runs `write` (write_image), reporting an ImageWriteError; the exit status.
int write_reporting(const std::function<bool()>& write) {
  try {
    if (!write()) return interrupted_exit();
  } catch (const std::exception& e) {
    std::cerr << "toroid render: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace

int write_output(const Canvas& canvas, const RenderCommandOptions& opt) {
  ImageWriteOptions wo;
  wo.scale = std::exp2(opt.exposure);
  wo.linear_png = opt.linear;
  wo.cancel = &g_interrupted;
  return write_reporting([&] { return write_image(canvas, opt.output, wo); });
}

int write_output(const Image8& image, const RenderCommandOptions& opt) {
  return write_reporting([&] { return write_image(image, opt.output, &g_interrupted); });
}

void print_summary(int width, int height, int samples, Integrator integrator, const std::string& workers,
                   double seconds, std::uint64_t rays) {
  std::fprintf(stderr, "%dx%d, %d samples, %s%s, %.2f s, %llu rays, %.2f Mrays/s\n", width, height, samples,
               integrator == Integrator::path ? "path integrator, " : "", workers.c_str(), seconds,
               static_cast<unsigned long long>(rays), seconds > 0 ? static_cast<double>(rays) / seconds / 1e6 : 0.0);
}

namespace {

int run_render(const RenderCommandOptions& opt) {
  catch_interrupts();
  if (launched_by_mpi()) {
#ifdef TOROID_HAVE_MPI
    return run_render_mpi(opt);
#else
    if (launcher_rank() == 0)
      std::cerr << "toroid render: started by mpirun, but this toroid was built without MPI: install Open MPI "
                   "(Debian: libopenmpi-dev) and build again (TOROID_MPI)\n";
    return 2;
#endif
  }
  // Warnings carry the prefix that errors have, and print even with --quiet.
  PreparedRender prepared =
      prepare_render(opt, true, [](const std::string& w) { std::cerr << "toroid render: " << w << "\n"; });
  if (!prepared.job) {
    std::cerr << "toroid render: " << prepared.error << "\n";
    return prepared.exit_code;
  }
  RenderJob& job = *prepared.job;
  if (g_interrupted) return interrupted_exit();

  const bool show_bar = shows_bar(opt);
  if (show_bar) job.options.progress = draw_bar;
  const int width = job.camera.hsize(), height = job.camera.vsize();
  RenderStats stats;
  int code = 0;
  if (const ImageFormat format = *image_format_of(opt.output); format == ImageFormat::exr) {
    const Canvas canvas = render_image(job.camera, job.scene.world, job.options, &stats);
    if (show_bar) clear_bar();
    if (stats.cancelled || g_interrupted) return interrupted_exit();
    code = write_output(canvas, opt);
  } else {
    // A PNG or PPM holds 8-bit codes: each tile is encoded as it arrives,
    // so the render never holds the image's linear colours (24 bytes a
    // pixel, where the codes take 3).
    ImageWriteOptions wo;
    wo.linear_png = opt.linear;
    Image8 image(width, height, srgb_codes(format, wo));
    const double scale = std::exp2(opt.exposure);
    const TileGrid grid{width, height, std::max(1, job.options.tile_size)};
    stats = render_tiles(job.camera, job.scene.world, job.options, 0, grid.count(),
                         [&](int, const PixelRect& r, const Color* pixels) {
                           for (int y = r.y0; y < r.y1; ++y, pixels += r.width())
                             encode_codes(pixels, r.width(), scale, image.srgb(), image.row(y) + 3 * r.x0);
                         });
    if (show_bar) clear_bar();
    if (stats.cancelled || g_interrupted) return interrupted_exit();
    code = write_output(image, opt);
  }
  if (code != 0) return code;
  if (!opt.quiet)
    print_summary(width, height, job.options.samples, job.options.integrator,
                  std::to_string(stats.threads) + " threads", stats.seconds, stats.rays);
  return 0;
}

}  // namespace

void add_render_command(CLI::App& app, int& exit_code) {
  auto opt = std::make_shared<RenderCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "render", "Render a scene (Ray Tracer Challenge YAML, plus 'add: torus') to a PNG, PPM or OpenEXR image");
  add_version_flag(*sub);
  sub->footer(std::string("When done it prints WIDTHxHEIGHT, samples, 'path integrator' for the path tracer,\n"
                          "threads, time, rays and Mrays/s on stderr; while it renders, a progress bar when\n"
                          "stderr is a terminal.\n"
                          "\nExample:\n  ") +
              kRenderExample + "\n\n" + kDocsLine + "\nEvery error message and exit status: docs/errors.md.");
  CLI::Option* scene = sub->add_option("scene", opt->scene, "Scene file (.yml/.yaml)")->required();
  // Under mpirun the scene is read by every rank, and a rank that cannot read
  // it says so through rank 0 (run_render_mpi), not alone.
  if (!launched_by_mpi()) scene->check(CLI::ExistingFile);
  sub->add_option("-o,--output", opt->output,
                  "Output image: .png (8-bit sRGB; with --linear the linear values), .ppm (the book's plain PPM: "
                  "8-bit linear values) or .exr (OpenEXR: 32-bit float linear RGB, unclamped, for HDR work)")
      ->required();
  const auto side = CLI::Range(1, kMaxImageSide);
  sub->add_option("--width", opt->width, "Image width in pixels (overrides the camera's; keeps its field of view)")
      ->check(side);
  sub->add_option("--height", opt->height, "Image height in pixels (overrides the camera's; keeps its field of view)")
      ->check(side);
  sub->add_option("--samples", opt->samples, "Samples per pixel (>= 1): a stratified, deterministically jittered grid")
      ->check(CLI::Range(1, 65536))
      ->capture_default_str();
  sub->add_option("--threads", opt->threads, "Worker threads (>= 1; default: every core)")->check(CLI::Range(1, 4096));
  sub->add_option("--max-depth", opt->max_depth, "Reflection/refraction recursion limit (>= 0)")
      ->check(CLI::Range(0, 1000))
      ->capture_default_str();
  sub->add_option("--tile-size", opt->tile_size,
                  "Tile side in pixels: the unit of work of a thread, and of a rank under mpirun (the image is the "
                  "same)")
      ->check(CLI::Range(1, 1024))
      ->capture_default_str();
  sub->add_option("--solver", opt->solver, "Quartic solver for every torus (overrides the scene's 'solver:')")
      ->check(CLI::IsMember({"default", "ferrari", "tianheng"}));
  sub->add_option("--integrator", opt->integrator,
                  "How a camera ray's colour is computed: whitted (the book's recursive shading) or path (the path "
                  "tracer); overrides the scene's 'add: integrator' (default: the scene's, else whitted)")
      ->check(CLI::IsMember({"whitted", "path"}));
  static_assert(kMaxExposureStops == 32, "the message and the help below give the range");
  const CLI::Validator stops(
      [](std::string& s) {
        std::size_t used = 0;
        double v = 0;
        try {
          v = std::stod(s, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used == 0 || used != s.size() || !(std::fabs(v) <= kMaxExposureStops))
          return "must be a number of stops from -32 to 32, got '" + s + "'";
        return std::string{};
      },
      "STOPS");
  sub->add_option("--exposure", opt->exposure,
                  "Multiply every pixel by 2^E before it is written, in every format (stops, -32 to 32)")
      ->check(stops)
      ->capture_default_str();
  sub->add_flag("--linear", opt->linear,
                "PNG only: write the linear values, as the PPM holds them (no sRGB transfer, no colour chunk)");
  sub->add_flag("-q,--quiet", opt->quiet, "Print nothing on success");
  sub->callback([opt, &exit_code] { exit_code = run_render(*opt); });
}

}  // namespace toroid::cmd
