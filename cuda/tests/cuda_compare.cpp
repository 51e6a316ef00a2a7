// SPDX-License-Identifier: Apache-2.0
#include "cuda_compare.h"

#include <cuda_runtime_api.h>

#include <bit>
#include <cmath>
#include <limits>

#include "toroid/torus/checked.h"

namespace toroid::cuda_check {

std::string device_problem() {
  int devices = 0;
  const cudaError_t err = cudaGetDeviceCount(&devices);
  if (err != cudaSuccess) return std::string("no CUDA device: cudaGetDeviceCount: ") + cudaGetErrorString(err);
  if (devices == 0) return "no CUDA device: cudaGetDeviceCount found none";
  return "";
}

namespace {

// Runs [begin, end) of the rays through `batch` in runs of one torus each.
template <typename Call>
int run_by_torus(const std::vector<accuracy::RayCase>& rays, Answers* out, Call call) {
  const std::size_t n = rays.size();
  out->counts.assign(n, 0);
  out->roots.assign(4 * n, 0.0);
  std::vector<double> origins, directions;
  std::size_t begin = 0;
  while (begin < n) {
    std::size_t end = begin + 1;
    const auto same = [&](std::size_t i) {
      return std::bit_cast<std::uint64_t>(rays[i].major) == std::bit_cast<std::uint64_t>(rays[begin].major) &&
             std::bit_cast<std::uint64_t>(rays[i].minor) == std::bit_cast<std::uint64_t>(rays[begin].minor);
    };
    while (end < n && same(end)) ++end;
    origins.clear();
    directions.clear();
    for (std::size_t i = begin; i < end; ++i)
      for (int k = 0; k < 3; ++k) {
        origins.push_back(rays[i].origin[k]);
        directions.push_back(rays[i].direction[k]);
      }
    const int err = call(rays[begin].major, rays[begin].minor, end - begin, origins.data(), directions.data(),
                         out->counts.data() + begin, out->roots.data() + 4 * begin);
    if (err != 0) return err;
    begin = end;
  }
  return 0;
}

}  // namespace

int run_rays(const std::vector<accuracy::RayCase>& rays, HostBatch batch, Answers* out) {
  return run_by_torus(rays, out, batch);
}

Answers run_rays_cpu(const std::vector<accuracy::RayCase>& rays) {
  Answers out;
  run_by_torus(rays, &out,
               [](double major, double minor, std::size_t n, const double* o, const double* d, int* c, double* r) {
                 toroid::intersect_torus_batch(major, minor, n, o, d, c, r);
                 return 0;
               });
  return out;
}

std::uint64_t ulps_apart(double a, double b) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b) ? 0 : UINT64_MAX;
  // Doubles as integers ordered like the values (-0 and +0 one apart).
  const auto ordered = [](double x) {
    const std::int64_t i = std::bit_cast<std::int64_t>(x);
    return i < 0 ? static_cast<std::int64_t>(0x8000000000000000ULL - static_cast<std::uint64_t>(i)) - 1 : i;
  };
  const std::int64_t ia = ordered(a), ib = ordered(b);
  return ia > ib ? static_cast<std::uint64_t>(ia - ib) : static_cast<std::uint64_t>(ib - ia);
}

Difference compare(const Answers& a, const Answers& b) {
  Difference d;
  d.rays = a.counts.size();
  for (std::size_t i = 0; i < d.rays; ++i) {
    if (a.counts[i] != b.counts[i]) {
      ++d.counts_differ;
      continue;
    }
    bool row = false;
    for (int k = 0; k < 4; ++k) {
      const double x = a.roots[4 * i + k], y = b.roots[4 * i + k];
      if (std::bit_cast<std::uint64_t>(x) == std::bit_cast<std::uint64_t>(y)) continue;
      row = true;
      ++d.roots_differ;
      const std::uint64_t u = ulps_apart(x, y);
      if (u > d.max_ulps) d.max_ulps = u;
      if (std::abs(x - y) > d.max_abs) d.max_abs = std::abs(x - y);
    }
    if (row) ++d.rows_differ;
  }
  return d;
}

std::vector<accuracy::RayCase> bad_input_rays() {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  constexpr double inf = std::numeric_limits<double>::infinity();
  const accuracy::RayCase good{1.0, 0.25, {-3, 0.1, 0.05}, {1, 0, 0}};
  std::vector<accuracy::RayCase> rays;
  const double radii[][2] = {{1.0, 0.25}, {0.0, 0.25}, {-1.0, 0.25}, {1.0, 0.0}, {nan, 0.25},
                             {1.0, nan},  {inf, 0.25}, {1.0, -inf},  {0.5, 1.0}};
  for (const auto& rr : radii) {
    accuracy::RayCase c = good;
    c.major = rr[0];
    c.minor = rr[1];
    rays.push_back(c);  // a good ray
    for (int k = 0; k < 3; ++k) {
      for (const double bad : {nan, inf, -inf}) {
        accuracy::RayCase o = c, d = c;
        o.origin[k] = bad;
        d.direction[k] = bad;
        rays.push_back(o);
        rays.push_back(d);
      }
    }
    accuracy::RayCase zero = c;
    zero.direction[0] = zero.direction[1] = zero.direction[2] = 0;
    rays.push_back(zero);
    accuracy::RayCase tiny = c;  // not bad: a direction of 1e-300 is solved, rescaled
    tiny.direction[0] = 1e-300;
    rays.push_back(tiny);
  }
  return rays;
}

}  // namespace toroid::cuda_check
