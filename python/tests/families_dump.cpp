// SPDX-License-Identifier: Apache-2.0
// Writes the rays of the accuracy families, and the C++ answers for them, to
// a file that python/tests/test_toroid.py (CppAgreementTest) reads, calls the
// module on the same inputs and compares bit for bit. The answers are those
// of checked.h in the module's terms: roots padded with NaN to four, inf for
// no nearest root.
//
// Usage: toroid_python_families FILE
//
// The file is a sequence of named arrays, each: uint32 name length, the name,
// a 4-byte NumPy dtype string ("<f8", "<i4", "<i8", "|u1", NUL-padded),
// uint32 ndim, ndim uint64 extents, then the values in C order, little-endian
// (the machine's: this runs where the test runs).
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "accuracy/harness.h"
#include "toroid/torus/checked.h"

namespace {

static_assert(std::endian::native == std::endian::little, "the file is little-endian");

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Writer {
  std::FILE* f;
  bool ok = true;

  void bytes(const void* p, std::size_t n) { ok = ok && std::fwrite(p, 1, n, f) == n; }

  template <typename T>
  void array(const std::string& name, const char* dtype, std::vector<std::uint64_t> shape, const std::vector<T>& v) {
    const auto name_length = static_cast<std::uint32_t>(name.size());
    bytes(&name_length, sizeof name_length);
    bytes(name.data(), name.size());
    char code[4] = {};
    std::strncpy(code, dtype, sizeof code);
    bytes(code, sizeof code);
    const auto ndim = static_cast<std::uint32_t>(shape.size());
    bytes(&ndim, sizeof ndim);
    bytes(shape.data(), shape.size() * sizeof(std::uint64_t));
    bytes(v.data(), v.size() * sizeof(T));
  }
};

struct Ray {
  int family;
  double major, minor, origin[3], direction[3];
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s FILE\n", argv[0]);
    return 2;
  }
  using toroid::accuracy::Family;
  using toroid::accuracy::RayCase;

  std::vector<std::string> names;
  std::vector<Ray> rays;
  for (const Family& f : toroid::accuracy::make_families(2000)) {
    names.push_back(f.name);
    for (const RayCase& c : f.rays)
      rays.push_back({static_cast<int>(names.size()) - 1,
                      c.major,
                      c.minor,
                      {c.origin[0], c.origin[1], c.origin[2]},
                      {c.direction[0], c.direction[1], c.direction[2]}});
  }
  // Rays with no roots by the C API's rules, and valid ones at the edges of
  // the range, through the same comparison.
  names.push_back("bad-rays");
  const int bad = static_cast<int>(names.size()) - 1;
  const double o[3] = {-5, 0.1, 0.05}, d[3] = {1, 0, 0};
  const double edge_rays[][2][3] = {
      {{kNaN, 0, 0}, {1, 0, 0}},    {{-5, kInf, 0}, {1, 0, 0}},  {{-5, 0, 0}, {-kInf, 0, 0}},
      {{-5, 0, 0}, {1, kNaN, 0}},   {{-5, 0, 0}, {0, 0, 0}},     {{-5, 0, 0}, {-0.0, 0, -0.0}},
      {{-5, 0, 0}, {1e-310, 0, 0}}, {{-1e300, 0, 0}, {1, 0, 0}}, {{o[0], o[1], o[2]}, {d[0], d[1], d[2]}},
  };
  for (const auto& r : edge_rays)
    rays.push_back({bad, 1.0, 0.25, {r[0][0], r[0][1], r[0][2]}, {r[1][0], r[1][1], r[1][2]}});

  const std::size_t n = rays.size();
  std::vector<double> radii, origins, directions, roots;
  std::vector<std::int32_t> family, counts;
  for (const Ray& r : rays) {
    family.push_back(r.family);
    radii.insert(radii.end(), {r.major, r.minor});
    origins.insert(origins.end(), r.origin, r.origin + 3);
    directions.insert(directions.end(), r.direction, r.direction + 3);
    double t[4] = {kNaN, kNaN, kNaN, kNaN};
    const int count = toroid::intersect_torus_checked(r.major, r.minor, r.origin, r.direction, t);
    counts.push_back(count);
    for (int k = 0; k < 4; ++k) roots.push_back(k < count ? t[k] : kNaN);
  }

  // nearest in fixed windows, the first being the module's default.
  const std::vector<double> windows = {0.0, kInf, -kInf, kInf, -kInf, 0.0, 2.5, 10.0, 1.0, 1.0};
  const std::size_t n_windows = windows.size() / 2;
  std::vector<double> nearest;
  for (std::size_t w = 0; w < n_windows; ++w)
    for (const Ray& r : rays) {
      double t = kInf;
      toroid::intersect_torus_nearest_checked(r.major, r.minor, r.origin, r.direction, windows[2 * w],
                                              windows[2 * w + 1], &t);
      nearest.push_back(t);
    }

  // nearest in the windows that start or end at each root (the root itself
  // is outside), and the unit normal at each root's point.
  std::vector<std::int64_t> root_ray, point_ray;
  std::vector<double> root_t, after_root, before_root, points, normals;
  for (std::size_t i = 0; i < n; ++i) {
    const Ray& r = rays[i];
    for (int k = 0; k < counts[i]; ++k) {
      const double t = roots[4 * i + k];
      double after = kInf, before = kInf;
      toroid::intersect_torus_nearest_checked(r.major, r.minor, r.origin, r.direction, t, kInf, &after);
      toroid::intersect_torus_nearest_checked(r.major, r.minor, r.origin, r.direction, -kInf, t, &before);
      root_ray.push_back(static_cast<std::int64_t>(i));
      root_t.push_back(t);
      after_root.push_back(after);
      before_root.push_back(before);

      const double p[3] = {r.origin[0] + t * r.direction[0], r.origin[1] + t * r.direction[1],
                           r.origin[2] + t * r.direction[2]};
      point_ray.push_back(static_cast<std::int64_t>(i));
      points.insert(points.end(), p, p + 3);
    }
  }
  // Points with no normal (NaN), on the axis, and far away, on the first
  // torus of the bad-rays family.
  const double edge_points[][3] = {{kNaN, 0, 0}, {0, kInf, 0}, {1, 0, 0},     {0, -1, 0},
                                   {0, 0, 0},    {0, 0, 2},    {1e300, 0, 0}, {1e-300, 0, 1e-300}};
  const std::size_t first_bad = n - std::size(edge_rays);
  for (const auto& p : edge_points) {
    point_ray.push_back(static_cast<std::int64_t>(first_bad));
    points.insert(points.end(), p, p + 3);
  }
  for (std::size_t j = 0; j < point_ray.size(); ++j) {
    const Ray& r = rays[static_cast<std::size_t>(point_ray[j])];
    double m[3];
    toroid::torus_unit_normal(r.major, r.minor, &points[3 * j], m);
    normals.insert(normals.end(), m, m + 3);
  }

  std::string joined;
  for (const std::string& name : names) joined += name + "\n";
  const std::vector<std::uint8_t> name_bytes(joined.begin(), joined.end());

  std::FILE* f = std::fopen(argv[1], "wb");
  if (f == nullptr) {
    std::perror(argv[1]);
    return 1;
  }
  Writer w{f};
  const std::uint64_t roots_n = root_ray.size(), points_n = point_ray.size();
  w.bytes("TOROIDPY", 8);
  w.array("family_names", "|u1", {name_bytes.size()}, name_bytes);
  w.array("family", "<i4", {n}, family);
  w.array("radii", "<f8", {n, 2}, radii);
  w.array("origins", "<f8", {n, 3}, origins);
  w.array("directions", "<f8", {n, 3}, directions);
  w.array("counts", "<i4", {n}, counts);
  w.array("roots", "<f8", {n, 4}, roots);
  w.array("windows", "<f8", {n_windows, 2}, windows);
  w.array("nearest", "<f8", {n_windows, n}, nearest);
  w.array("root_ray", "<i8", {roots_n}, root_ray);
  w.array("root_t", "<f8", {roots_n}, root_t);
  w.array("nearest_after_root", "<f8", {roots_n}, after_root);
  w.array("nearest_before_root", "<f8", {roots_n}, before_root);
  w.array("point_ray", "<i8", {points_n}, point_ray);
  w.array("points", "<f8", {points_n, 3}, points);
  w.array("normals", "<f8", {points_n, 3}, normals);
  const bool closed = std::fclose(f) == 0;
  if (!w.ok || !closed) {
    std::fprintf(stderr, "%s: write failed\n", argv[1]);
    return 1;
  }
  std::printf("%s: %zu rays of %zu families, %llu roots, %llu points\n", argv[1], n, names.size(),
              static_cast<unsigned long long>(roots_n), static_cast<unsigned long long>(points_n));
  return 0;
}
