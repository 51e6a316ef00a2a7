// SPDX-License-Identifier: Apache-2.0
// tools/gpu-check.sh's program: the accuracy families through the CUDA batch
// with the CPU's bars, its answers against the CPU batch's (bit for bit with
// --fmad=false; in ulps with a copy compiled with --fmad=true), the bad
// inputs, and rays per second for a mixed batch against the CPU batch on
// every core. Prints markdown tables. Without a CUDA device it runs the CPU
// half and exits 77.
//
//   toroid_gpu_check [--rays-per-family N] [--speed-rays N] [--threads T] [--speed-only]
#include <cuda_runtime.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <numbers>
#include <numeric>
#include <string>
#include <thread>
#include <vector>

#include "accuracy/harness.h"
#include "check/torus_cuda_fmad.h"
#include "cuda_compare.h"
#include "toroid/torus/checked.h"
#include "toroid/torus_cuda.h"

namespace {

using namespace toroid;
using namespace toroid::cuda_check;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

bool check(int err, const char* what) {
  if (err == 0) return true;
  std::printf("CUDA error in %s: %s\n", what, cudaGetErrorString(static_cast<cudaError_t>(err)));
  return false;
}

// The CPU batch on `threads` threads, each on its own slice of the rays.
void cpu_batch_threads(double major, double minor, std::size_t n, const double* o, const double* d, int* c, double* r,
                       unsigned threads) {
  std::vector<std::thread> pool;
  const std::size_t slice = (n + threads - 1) / threads;
  for (unsigned t = 0; t < threads; ++t) {
    const std::size_t begin = std::min(n, t * slice), end = std::min(n, begin + slice);
    pool.emplace_back([=] {
      intersect_torus_batch(major, minor, end - begin, o + 3 * begin, d + 3 * begin, c + begin, r + 4 * begin);
    });
  }
  for (std::thread& th : pool) th.join();
}

std::string ulps_text(const Difference& d) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%zu / %llu / %.1e", d.rows_differ, static_cast<unsigned long long>(d.max_ulps),
                d.max_abs);
  return buf;
}

// Rays per second for one batch: the CPU batch on every core, the kernel by
// CUDA events (best of three after a warm-up, with and without contraction)
// and the host call with its allocations and copies; the kernel's answers
// against the CPU's. Prints table rows; false if a check fails.
bool speed(const char* batch, double major, double minor, const std::vector<double>& o, const std::vector<double>& d,
           unsigned threads, bool gpu) {
  const std::size_t n = o.size() / 3;
  std::vector<double> roots_cpu(4 * n), roots_gpu(4 * n);
  std::vector<int> counts_cpu(n), counts_gpu(n);
  const auto row = [&](const char* path, double s) {
    std::printf("| %s | %s | %zu | %.4f | %.3e |\n", batch, path, n, s, static_cast<double>(n) / s);
  };
  bool ok = true;
  double best = 1e300;
  for (int rep = 0; rep < 2; ++rep) {
    const Clock::time_point t0 = Clock::now();
    cpu_batch_threads(major, minor, n, o.data(), d.data(), counts_cpu.data(), roots_cpu.data(), threads);
    best = std::min(best, seconds_since(t0));
  }
  const std::size_t hits =
      static_cast<std::size_t>(std::count_if(counts_cpu.begin(), counts_cpu.end(), [](int c) { return c > 0; }));
  char label[96];
  std::snprintf(label, sizeof label, "CPU batch, %u threads (%.0f%% of the rays hit)", threads,
                100.0 * static_cast<double>(hits) / static_cast<double>(n));
  row(label, best);
  if (!gpu) return ok;
  double *d_o = nullptr, *d_d = nullptr, *d_r = nullptr;
  int* d_c = nullptr;
  const bool mem = check(cudaMalloc(&d_o, 3 * n * sizeof(double)), "cudaMalloc") &&
                   check(cudaMalloc(&d_d, 3 * n * sizeof(double)), "cudaMalloc") &&
                   check(cudaMalloc(&d_c, n * sizeof(int)), "cudaMalloc") &&
                   check(cudaMalloc(&d_r, 4 * n * sizeof(double)), "cudaMalloc") &&
                   check(cudaMemcpy(d_o, o.data(), 3 * n * sizeof(double), cudaMemcpyHostToDevice), "cudaMemcpy") &&
                   check(cudaMemcpy(d_d, d.data(), 3 * n * sizeof(double), cudaMemcpyHostToDevice), "cudaMemcpy");
  ok &= mem;
  if (mem) {
    cudaEvent_t start, stop;
    cudaEventCreate(&start);
    cudaEventCreate(&stop);
    const auto kernel_time = [&](bool fmad) {
      float best_ms = 1e30f;
      for (int rep = 0; rep < 4; ++rep) {  // the first is the warm-up
        cudaEventRecord(start);
        const int err = fmad ? toroid_check_batch_fmad(major, minor, n, d_o, d_d, d_c, d_r)
                             : toroid_torus_intersect_batch_cuda(major, minor, n, d_o, d_d, d_c, d_r, nullptr);
        cudaEventRecord(stop);
        ok &= check(err, "the kernel") && check(cudaEventSynchronize(stop), "the kernel's run");
        float ms = 0;
        cudaEventElapsedTime(&ms, start, stop);
        if (rep > 0) best_ms = std::min(best_ms, ms);
      }
      return best_ms / 1e3;
    };
    row("GPU kernel, --fmad=true (CUDA events)", kernel_time(true));
    row("GPU kernel, --fmad=false (CUDA events)", kernel_time(false));
    cudaEventDestroy(start);
    cudaEventDestroy(stop);
  }
  cudaFree(d_o);
  cudaFree(d_d);
  cudaFree(d_c);
  cudaFree(d_r);
  double best_host = 1e300;
  for (int rep = 0; rep < 2; ++rep) {
    const Clock::time_point t0 = Clock::now();
    ok &= check(toroid_torus_intersect_batch_cuda_host(major, minor, n, o.data(), d.data(), counts_gpu.data(),
                                                       roots_gpu.data()),
                "the host batch");
    best_host = std::min(best_host, seconds_since(t0));
  }
  row("GPU with transfers (host arrays, cudaMalloc and copies included), --fmad=false", best_host);
  const Difference dd = compare(Answers{counts_gpu, roots_gpu}, Answers{counts_cpu, roots_cpu});
  ok &= dd.counts_differ == 0 && dd.rows_differ == 0;
  std::printf(
      "| %s | --fmad=false against the CPU: %zu counts differ; %s rows differ in bits / max ulps / max abs | | | |\n",
      batch, dd.counts_differ, ulps_text(dd).c_str());
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  int per_family = 2000;
  std::size_t speed_rays = std::size_t{1} << 24;
  unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  bool speed_only = false;
  for (int i = 1; i < argc; ++i) {
    const bool value = i + 1 < argc;
    if (!std::strcmp(argv[i], "--speed-only")) {
      speed_only = true;
    } else if (value && !std::strcmp(argv[i], "--rays-per-family")) {
      per_family = std::atoi(argv[++i]);
    } else if (value && !std::strcmp(argv[i], "--speed-rays")) {
      speed_rays = std::strtoull(argv[++i], nullptr, 10);
    } else if (value && !std::strcmp(argv[i], "--threads")) {
      threads = static_cast<unsigned>(std::atoi(argv[++i]));
    } else {
      std::fprintf(stderr, "usage: %s [--rays-per-family N] [--speed-rays N] [--threads T] [--speed-only]\n", argv[0]);
      return 2;
    }
  }
  if (per_family < 1 || speed_rays < 1 || threads < 1) {
    std::fprintf(stderr, "%s: --rays-per-family, --speed-rays and --threads must be at least 1\n", argv[0]);
    return 2;
  }
  const std::string problem = device_problem();
  const bool gpu = problem.empty();
  if (gpu) {
    cudaDeviceProp prop{};
    cudaGetDeviceProperties(&prop, 0);
    std::printf("device: %s (sm_%d%d), %d SMs\n", prop.name, prop.major, prop.minor, prop.multiProcessorCount);
  } else {
    std::printf("%s: the GPU half is skipped\n", problem.c_str());
  }
  bool ok = true;

  // 1. The accuracy families (skipped by --speed-only, for a profiler).
  const std::vector<accuracy::Family> families = accuracy::make_families(per_family);
  if (!speed_only)
    std::printf(
        "\n| family | rays | missed | spurious | extra | grazing pairs found | p99 | p99 bar | max | bars "
        "| counts != CPU | rows != CPU bits / max ulps / max abs, --fmad=false | rows != CPU bits / max ulps / max "
        "abs, --fmad=true |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|---:|\n");
  for (const accuracy::Family& f : families) {
    if (speed_only) break;
    const Answers cpu = run_rays_cpu(f.rays);
    Answers gpu_off = cpu, gpu_on = cpu;
    if (gpu) {
      ok &= check(run_rays(f.rays, toroid_torus_intersect_batch_cuda_host, &gpu_off), "the batch");
      ok &= check(run_rays(f.rays, toroid_check_batch_fmad_host, &gpu_on), "the --fmad=true batch");
    }
    const Answers& judged = gpu ? gpu_off : cpu;
    const accuracy::ReferenceSet ref = accuracy::compute_references(f);
    const accuracy::Metrics m = accuracy::measure(f, ref, [&](const accuracy::RayCase& c, double t[4]) {
      const std::size_t i = static_cast<std::size_t>(&c - f.rays.data());
      const int n = std::max(judged.counts[i], 0);
      for (int k = 0; k < n; ++k) t[k] = judged.roots[4 * i + k];
      return n;
    });
    const bool bars = accuracy::bar_violations(f, m).empty();
    ok &= bars;
    const Difference d_off = compare(gpu_off, cpu), d_on = compare(gpu_on, cpu);
    ok &= d_off.counts_differ == 0 && d_off.rows_differ == 0;
    std::printf("| %s%s | %d | %d | %d | %d | %d/%d | %.1e | %.0e | %.1e | %s | %zu | %s | %s |\n", f.name.c_str(),
                gpu ? "" : " (CPU)", m.rays, m.missed, m.spurious, m.extra, m.grazing_pairs_found, m.grazing_pairs,
                m.p99, f.p99_bar, m.max, bars ? "met" : "NOT MET", d_off.counts_differ,
                gpu ? ulps_text(d_off).c_str() : "-", gpu ? ulps_text(d_on).c_str() : "-");
  }

  // 2. The bad inputs.
  const std::vector<accuracy::RayCase> bad = bad_input_rays();
  const Answers bad_cpu = run_rays_cpu(bad);
  if (gpu && !speed_only) {
    Answers bad_gpu;
    ok &= check(run_rays(bad, toroid_torus_intersect_batch_cuda_host, &bad_gpu), "the bad-input batch");
    const Difference d = compare(bad_gpu, bad_cpu);
    ok &= d.counts_differ == 0 && d.rows_differ == 0;
    std::printf(
        "\nbad inputs: %zu rays (NaN, infinite, zero directions; radii 0, < 0, NaN, infinite): %zu counts "
        "and %zu rows differ from the CPU batch's bits\n",
        d.rays, d.counts_differ, d.rows_differ);
  }

  // 3. Speed: the families' rays on their usual torus, interleaved (every
  // kind of ray in every warp), and a camera's primary rays (neighbours
  // alike, as a renderer sends them), against the CPU batch on every core.
  std::vector<const accuracy::RayCase*> pool;
  for (const accuracy::Family& f : families)
    for (const accuracy::RayCase& c : f.rays)
      if (c.major == families[0].rays[0].major && c.minor == families[0].rays[0].minor) pool.push_back(&c);
  const double major = pool[0]->major, minor = pool[0]->minor;
  std::size_t stride = 7919;  // a prime: interleaves the families
  if (std::gcd(stride, pool.size()) != 1) stride = 1;
  const std::size_t n = speed_rays;
  std::vector<double> o(3 * n), d(3 * n);
  for (std::size_t j = 0; j < n; ++j) {
    const accuracy::RayCase& c = *pool[(j * stride) % pool.size()];
    for (int k = 0; k < 3; ++k) o[3 * j + k] = c.origin[k], d[3 * j + k] = c.direction[k];
  }
  std::printf("\n| batch | path | rays | seconds | rays/s |\n|---|---|---:|---:|---:|\n");
  ok &= speed("mixed", major, minor, o, d, threads, gpu);
  // A square image of about n pixels seen from (0, -4 R, 2 R) towards the
  // centre, 36 degrees wide: the torus fills most of its width.
  const std::size_t side = std::max<std::size_t>(1, static_cast<std::size_t>(std::sqrt(static_cast<double>(n))));
  const std::size_t m = side * side;
  o.resize(3 * m);
  d.resize(3 * m);
  const double eye[3] = {0, -4 * major, 2 * major};
  const double len = std::sqrt(eye[1] * eye[1] + eye[2] * eye[2]);
  const double fwd[3] = {0, -eye[1] / len, -eye[2] / len}, right[3] = {1, 0, 0};
  const double up[3] = {0, -fwd[2], fwd[1]};  // right x fwd
  const double half = std::tan(std::numbers::pi / 10);
  for (std::size_t y = 0; y < side; ++y) {
    for (std::size_t x = 0; x < side; ++x) {
      const std::size_t j = y * side + x;
      const double u = (2 * (x + 0.5) / side - 1) * half, v = (1 - 2 * (y + 0.5) / side) * half;
      for (int k = 0; k < 3; ++k) o[3 * j + k] = eye[k], d[3 * j + k] = fwd[k] + u * right[k] + v * up[k];
    }
  }
  ok &= speed("primary", major, minor, o, d, threads, gpu);
  std::printf("\n%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
  if (!ok) return 1;
  return gpu ? 0 : 77;
}
