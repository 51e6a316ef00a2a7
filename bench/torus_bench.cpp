// SPDX-License-Identifier: Apache-2.0
// ns per ray-torus intersection, per solver (docs/torus.md records the figures).
//   mixed:   rays from 2-6 sizes away aimed at random points of the torus's
//            bounding box, hits and misses as a camera sees them;
//   hits:    the subset of those rays that hit;
//   nearest: the renderer's query, the nearest root in (0, inf), mixed set;
//   blocks:  the shadow query, torus_blocks: whether a root lies in (0, inf),
//            mixed set;
//   surface: the shadow query and the nearest root on rays that leave the
//            torus, as a renderer's shadow and reflected rays do: from 1e-5
//            above a random point of the surface (the renderer's
//            over-point), in a random direction away from it;
//   inside:  the nearest root on rays that start inside the tube, as a
//            renderer's refracted rays do: from 1e-5 below a random point
//            of the surface (the renderer's under-point), in a random
//            direction into the tube;
//   batch:   intersect_torus_batch_on each path (scalar, avx2, avx512) over
//            the 4096 rays of a set: ns per ray, all roots.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "toroid/torus/batch.h"
#include "toroid/torus/intersect.h"

namespace {

constexpr double kR = 1.0, kr = 0.25;

struct BenchRay {
  double o[3], d[3];
};

// A random point of the unit ball, not too near its centre, by rejection;
// returns its squared length.
double random_in_ball(std::mt19937_64& rng, std::uniform_real_distribution<double>& u, double p[3]) {
  double len2 = 0;
  do {
    for (int i = 0; i < 3; ++i) p[i] = u(rng);
    len2 = p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
  } while (len2 > 1 || len2 < 1e-6);
  return len2;
}

std::vector<BenchRay> make_rays(bool hits_only) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<BenchRay> rays;
  const double size = kR + kr;
  while (rays.size() < 4096) {
    double dir[3];
    const double len2 = random_in_ball(rng, u, dir);
    const double dist = (4 + 2 * u(rng)) * size / std::sqrt(len2);
    BenchRay r;
    const double target[3] = {u(rng) * size, u(rng) * size, u(rng) * kr};
    for (int i = 0; i < 3; ++i) {
      r.o[i] = dir[i] * dist;
      r.d[i] = target[i] - r.o[i];
    }
    const double n = std::sqrt(r.d[0] * r.d[0] + r.d[1] * r.d[1] + r.d[2] * r.d[2]);
    for (double& c : r.d) c /= n;
    double t[4];
    if (hits_only && toroid::intersect_torus(kR, kr, r.o, r.d, t) == 0) continue;
    rays.push_back(r);
  }
  return rays;
}

// Rays from 1e-5 off a random point of the surface, in a random direction
// away from the tube (outward) or into it.
std::vector<BenchRay> make_surface_rays(bool outward) {
  std::mt19937_64 rng(outward ? 7 : 11);
  const double side = outward ? 1 : -1;
  std::uniform_real_distribution<double> angle(0, 2 * M_PI), u(-1, 1);
  std::vector<BenchRay> rays;
  while (rays.size() < 4096) {
    const double theta = angle(rng), phi = angle(rng);
    const double n[3] = {std::cos(phi) * std::cos(theta), std::cos(phi) * std::sin(theta), std::sin(phi)};
    double dir[3];
    double len2 = 0;
    do {
      len2 = random_in_ball(rng, u, dir);
    } while (side * (dir[0] * n[0] + dir[1] * n[1] + dir[2] * n[2]) <= 0);
    BenchRay r;
    const double ring[3] = {kR * std::cos(theta), kR * std::sin(theta), 0};
    for (int i = 0; i < 3; ++i) {
      r.o[i] = ring[i] + (kr + side * 1e-5) * n[i];
      r.d[i] = dir[i] / std::sqrt(len2);
    }
    rays.push_back(r);
  }
  return rays;
}

const std::vector<BenchRay>& surface_rays() {
  static const std::vector<BenchRay> surface = make_surface_rays(true);
  return surface;
}

const std::vector<BenchRay>& inside_rays() {
  static const std::vector<BenchRay> inside = make_surface_rays(false);
  return inside;
}

const std::vector<BenchRay>& rays(bool hits_only) {
  static const std::vector<BenchRay> mixed = make_rays(false), hits = make_rays(true);
  return hits_only ? hits : mixed;
}

// Which rays a window query asks about.
enum class From { Afar, Surface, Inside };

const std::vector<BenchRay>& rays_from(From from) {
  return from == From::Surface ? surface_rays() : from == From::Inside ? inside_rays() : rays(false);
}

void BM_AllRoots(benchmark::State& state, toroid::TorusSolver solver, bool hits_only) {
  const auto& rs = rays(hits_only);
  size_t i = 0;
  double t[4];
  for (auto _ : state) {
    const BenchRay& r = rs[i++ & (rs.size() - 1)];
    benchmark::DoNotOptimize(toroid::intersect_torus(kR, kr, r.o, r.d, t, solver));
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations());
}

// A window query's start: 1e-9, or a renderer's -denorm_min (a root at t = 0
// counts), which must cost the same (no arithmetic on the subnormal start).
constexpr double kFromZero = -std::numeric_limits<double>::denorm_min();

void BM_Nearest(benchmark::State& state, toroid::TorusSolver solver, From from, double t_min = 1e-9) {
  const auto& rs = rays_from(from);
  size_t i = 0;
  double t = 0;
  for (auto _ : state) {
    const BenchRay& r = rs[i++ & (rs.size() - 1)];
    benchmark::DoNotOptimize(
        toroid::intersect_torus_nearest(kR, kr, r.o, r.d, t_min, std::numeric_limits<double>::infinity(), &t, solver));
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_Blocks(benchmark::State& state, toroid::TorusSolver solver, From from, double t_min = 1e-9) {
  const auto& rs = rays_from(from);
  size_t i = 0;
  for (auto _ : state) {
    const BenchRay& r = rs[i++ & (rs.size() - 1)];
    benchmark::DoNotOptimize(
        toroid::torus_blocks(kR, kr, r.o, r.d, t_min, std::numeric_limits<double>::infinity(), solver));
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_Batch(benchmark::State& state, toroid::BatchPath path, bool hits_only) {
  if (!toroid::batch_path_available(path)) {
    state.SkipWithError("this CPU or build has no such path");
    return;
  }
  const auto& rs = rays(hits_only);
  const std::size_t n = rs.size();
  std::vector<double> origins(3 * n), directions(3 * n), roots(4 * n);
  std::vector<int> counts(n);
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) origins[3 * i + k] = rs[i].o[k], directions[3 * i + k] = rs[i].d[k];
  for (auto _ : state) {
    benchmark::DoNotOptimize(toroid::intersect_torus_batch_on(path, kR, kr, n, origins.data(), directions.data(),
                                                              counts.data(), roots.data()));
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(n));
}

using toroid::BatchPath;
using toroid::TorusSolver;

// The minimum over repetitions is what the code costs; the mean and median
// also carry whatever else the machine was doing.
double min_of(const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); }
#define TOROID_BENCH(...) BENCHMARK_CAPTURE(__VA_ARGS__)->Repetitions(10)->ComputeStatistics("min", min_of)

TOROID_BENCH(BM_AllRoots, default_mixed, TorusSolver::Default, false);
TOROID_BENCH(BM_AllRoots, ferrari_mixed, TorusSolver::Ferrari, false);
TOROID_BENCH(BM_AllRoots, tianheng_mixed, TorusSolver::Tianheng, false);
TOROID_BENCH(BM_AllRoots, default_hits, TorusSolver::Default, true);
TOROID_BENCH(BM_AllRoots, ferrari_hits, TorusSolver::Ferrari, true);
TOROID_BENCH(BM_AllRoots, tianheng_hits, TorusSolver::Tianheng, true);
TOROID_BENCH(BM_Nearest, default_mixed, TorusSolver::Default, From::Afar);
TOROID_BENCH(BM_Nearest, ferrari_mixed, TorusSolver::Ferrari, From::Afar);
TOROID_BENCH(BM_Nearest, tianheng_mixed, TorusSolver::Tianheng, From::Afar);
TOROID_BENCH(BM_Nearest, default_surface, TorusSolver::Default, From::Surface);
TOROID_BENCH(BM_Nearest, default_surface_from_zero, TorusSolver::Default, From::Surface, kFromZero);
TOROID_BENCH(BM_Nearest, ferrari_surface, TorusSolver::Ferrari, From::Surface);
TOROID_BENCH(BM_Nearest, default_inside, TorusSolver::Default, From::Inside);
TOROID_BENCH(BM_Nearest, ferrari_inside, TorusSolver::Ferrari, From::Inside);
TOROID_BENCH(BM_Blocks, default_mixed, TorusSolver::Default, From::Afar);
TOROID_BENCH(BM_Blocks, ferrari_mixed, TorusSolver::Ferrari, From::Afar);
TOROID_BENCH(BM_Blocks, default_surface, TorusSolver::Default, From::Surface);
TOROID_BENCH(BM_Blocks, default_surface_from_zero, TorusSolver::Default, From::Surface, kFromZero);
TOROID_BENCH(BM_Blocks, ferrari_surface, TorusSolver::Ferrari, From::Surface);
TOROID_BENCH(BM_Batch, scalar_mixed, BatchPath::Scalar, false);
TOROID_BENCH(BM_Batch, avx2_mixed, BatchPath::Avx2, false);
TOROID_BENCH(BM_Batch, avx512_mixed, BatchPath::Avx512, false);
TOROID_BENCH(BM_Batch, scalar_hits, BatchPath::Scalar, true);
TOROID_BENCH(BM_Batch, avx2_hits, BatchPath::Avx2, true);
TOROID_BENCH(BM_Batch, avx512_hits, BatchPath::Avx512, true);

}  // namespace
