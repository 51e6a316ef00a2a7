// SPDX-License-Identifier: Apache-2.0
// The Embree adapter against the torus library: bounds, hits, the
// tnear/tfar window, occlusion, filters, packets, instances and bad inputs.
#include <embree3/rtcore.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "toroid/embree_tori.h"
#include "toroid/torus/checked.h"
#include "toroid/torus/float_api.h"
#include "toroid/torus/intersect.h"
#include "toroid/torus/surface.h"

namespace {

using toroid::embree::EmbreeTorus;
using toroid::embree::ToriGeometry;

constexpr float kFloatInf = std::numeric_limits<float>::infinity();
constexpr double kPi = std::numbers::pi;

// ------------------------------------------------------------ affine maps

// A 3x4 affine map with its inverse built alongside, operation by operation
// (not by inverting the product), so that the tests' object-space rays do not
// come from the adapter's own inversion.
struct Affine {
  std::array<std::array<double, 4>, 3> m{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}};
  std::array<std::array<double, 4>, 3> inv{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}};
};

using Rows = std::array<std::array<double, 4>, 3>;

Rows multiply(const Rows& a, const Rows& b) {
  Rows r{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 4; ++j) {
      double s = j == 3 ? a[i][3] : 0;
      for (int k = 0; k < 3; ++k) s += a[i][k] * b[k][j];
      r[i][j] = s;
    }
  }
  return r;
}

// Applies `op` after what `a` already does.
Affine then(const Affine& a, const Rows& op, const Rows& op_inverse) {
  Affine r;
  r.m = multiply(op, a.m);
  r.inv = multiply(a.inv, op_inverse);
  return r;
}

Rows rotation(int axis, double angle) {
  Rows r{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}};
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  r[i][i] = std::cos(angle), r[i][j] = -std::sin(angle);
  r[j][i] = std::sin(angle), r[j][j] = std::cos(angle);
  return r;
}

Affine rotate(const Affine& a, int axis, double angle) {
  return then(a, rotation(axis, angle), rotation(axis, -angle));
}
Affine scale(const Affine& a, double x, double y, double z) {
  return then(a, Rows{{{x, 0, 0, 0}, {0, y, 0, 0}, {0, 0, z, 0}}},
              Rows{{{1 / x, 0, 0, 0}, {0, 1 / y, 0, 0}, {0, 0, 1 / z, 0}}});
}
Affine translate(const Affine& a, double x, double y, double z) {
  return then(a, Rows{{{1, 0, 0, x}, {0, 1, 0, y}, {0, 0, 1, z}}}, Rows{{{1, 0, 0, -x}, {0, 1, 0, -y}, {0, 0, 1, -z}}});
}

struct TestTorus {
  EmbreeTorus torus;
  Affine xf;
};

TestTorus make(double major, double minor, const Affine& xf) {
  TestTorus t;
  t.torus.major = major;
  t.torus.minor = minor;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) t.torus.object_to_world[i][j] = xf.m[i][j];
  t.xf = xf;
  return t;
}

void apply(const Rows& m, const double p[3], double out[3], bool point) {
  for (int i = 0; i < 3; ++i) out[i] = m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] + (point ? m[i][3] : 0);
}

// A point on the torus at RenderMan's angles (object space).
void surface_point(double major, double minor, double theta, double phi, double p[3]) {
  const double rho = major + minor * std::cos(phi);
  p[0] = rho * std::cos(theta), p[1] = rho * std::sin(theta), p[2] = minor * std::sin(phi);
}

// Random tori: rotated about every axis, scaled non-uniformly, moved; thin
// rings, fat ones, a horn and spindles.
std::vector<TestTorus> random_tori(std::mt19937_64& rng, int count) {
  std::uniform_real_distribution<double> angle(-kPi, kPi), s(0.3, 3.0), move(-20, 20);
  const double aspects[] = {1.0 / 1024, 0.01, 0.1, 0.25, 0.5, 0.9, 1.0, 1.3, 2.0};
  std::vector<TestTorus> tori;
  for (int k = 0; k < count; ++k) {
    Affine xf;
    xf = rotate(xf, 0, angle(rng));
    xf = scale(xf, s(rng), s(rng), s(rng));
    xf = rotate(xf, 1, angle(rng));
    xf = rotate(xf, 2, angle(rng));
    if (k % 3 == 0) xf = scale(xf, -1, 1, 1);  // mirrored
    xf = translate(xf, move(rng), move(rng), move(rng));
    const double major = std::exp2(std::uniform_real_distribution<double>(-3, 3)(rng));
    tori.push_back(make(major, major * aspects[k % std::size(aspects)], xf));
  }
  return tori;
}

std::vector<EmbreeTorus> plain(const std::vector<TestTorus>& tori) {
  std::vector<EmbreeTorus> r;
  for (const TestTorus& t : tori) r.push_back(t.torus);
  return r;
}

// ------------------------------------------------------------ Embree set-up

struct Device {
  RTCDevice device = rtcNewDevice(nullptr);
  Device() {
    rtcSetDeviceErrorFunction(
        device, [](void*, RTCError code, const char* str) { ADD_FAILURE() << "Embree error " << code << ": " << str; },
        nullptr);
  }
  ~Device() { rtcReleaseDevice(device); }
  Device(const Device&) = delete;
  Device& operator=(const Device&) = delete;
};

struct Scene {
  RTCScene scene;
  explicit Scene(RTCDevice d, RTCSceneFlags flags = RTC_SCENE_FLAG_NONE) : scene(rtcNewScene(d)) {
    rtcSetSceneFlags(scene, flags);
  }
  ~Scene() { rtcReleaseScene(scene); }
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;
};

RTCRayHit make_ray(const float o[3], const float d[3], float tnear = 0, float tfar = kFloatInf) {
  RTCRayHit rh{};
  rh.ray.org_x = o[0], rh.ray.org_y = o[1], rh.ray.org_z = o[2];
  rh.ray.dir_x = d[0], rh.ray.dir_y = d[1], rh.ray.dir_z = d[2];
  rh.ray.tnear = tnear;
  rh.ray.tfar = tfar;
  rh.ray.mask = ~0u;
  rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  return rh;
}

RTCRayHit intersect(RTCScene scene, RTCRayHit rh, RTCIntersectContext* context = nullptr) {
  RTCIntersectContext own;
  rtcInitIntersectContext(&own);
  rtcIntersect1(scene, context ? context : &own, &rh);
  return rh;
}

bool occluded(RTCScene scene, RTCRay ray, RTCIntersectContext* context = nullptr) {
  RTCIntersectContext own;
  rtcInitIntersectContext(&own);
  rtcOccluded1(scene, context ? context : &own, &ray);
  return ray.tfar == -kFloatInf;
}

int float_ulps(float a, float b) {
  if (a == b) return 0;
  int n = 0;
  for (float x = std::min(a, b); x < std::max(a, b) && n < 1000; x = std::nextafter(x, kFloatInf)) ++n;
  return n;
}

// The library's answer on the test's own object-space ray: the nearest root
// whose float lies in (tnear, tfar).
bool reference_nearest(const TestTorus& t, const float o[3], const float d[3], float tnear, float tfar, float* out) {
  const double ow[3] = {o[0], o[1], o[2]}, dw[3] = {d[0], d[1], d[2]};
  double oo[3], dd[3], lo, hi, root;
  apply(t.xf.inv, ow, oo, true);
  apply(t.xf.inv, dw, dd, false);
  if (!toroid::float_interval_in_double(tnear, tfar, &lo, &hi)) return false;
  if (!toroid::intersect_torus_nearest(t.torus.major, t.torus.minor, oo, dd, lo, hi, &root)) return false;
  *out = static_cast<float>(root);
  return true;
}

// ------------------------------------------------------------ bounds

TEST(EmbreeBounds, ContainSurfacePointsAndTouchTheExtremes) {
  std::mt19937_64 rng(15);
  std::uniform_real_distribution<double> a(-kPi, kPi);
  int samples = 0;
  for (const TestTorus& t : random_tori(rng, 60)) {
    const RTCBounds b = toroid::embree::torus_world_bounds(t.torus);
    const float lo[3] = {b.lower_x, b.lower_y, b.lower_z}, hi[3] = {b.upper_x, b.upper_y, b.upper_z};
    for (int k = 0; k < 2000; ++k, ++samples) {
      double p[3], w[3];
      surface_point(t.torus.major, t.torus.minor, a(rng), a(rng), p);
      apply(t.xf.m, p, w, true);
      for (int i = 0; i < 3; ++i) {
        ASSERT_LE(lo[i], w[i]);
        ASSERT_GE(hi[i], w[i]);
      }
    }
    // The extreme point on each axis, by its angles: the box's face is
    // within a few float ulps of it (tight), and holds it.
    for (int i = 0; i < 3; ++i) {
      const auto& row = t.xf.m[i];
      for (int side : {-1, 1}) {
        const double ab = std::hypot(row[0], row[1]);
        const double theta = std::atan2(side * row[1], side * row[0]);
        const double phi = std::atan2(side * row[2], ab);
        double p[3], w[3];
        surface_point(t.torus.major, t.torus.minor, theta, phi, p);
        apply(t.xf.m, p, w, true);
        const float face = side > 0 ? hi[i] : lo[i];
        EXPECT_TRUE(side > 0 ? face >= w[i] : face <= w[i]) << "axis " << i;
        EXPECT_LE(float_ulps(face, static_cast<float>(w[i])), 3)
            << "axis " << i << " side " << side << " face " << face << " extreme " << w[i];
      }
    }
  }
  EXPECT_EQ(samples, 120000);
}

TEST(EmbreeBounds, SceneBoundsAreTheToriBoxes) {
  Device dev;
  std::mt19937_64 rng(3);
  const std::vector<TestTorus> tori = random_tori(rng, 5);
  Scene s(dev.device);
  const ToriGeometry g = toroid::embree::attach_tori(dev.device, s.scene, plain(tori));
  rtcCommitScene(s.scene);
  RTCBounds want{kFloatInf, kFloatInf, kFloatInf, 0, -kFloatInf, -kFloatInf, -kFloatInf, 0};
  for (const TestTorus& t : tori) {
    const RTCBounds b = toroid::embree::torus_world_bounds(t.torus);
    want.lower_x = std::min(want.lower_x, b.lower_x), want.upper_x = std::max(want.upper_x, b.upper_x);
    want.lower_y = std::min(want.lower_y, b.lower_y), want.upper_y = std::max(want.upper_y, b.upper_y);
    want.lower_z = std::min(want.lower_z, b.lower_z), want.upper_z = std::max(want.upper_z, b.upper_z);
  }
  RTCBounds got;
  rtcGetSceneBounds(s.scene, &got);
  EXPECT_EQ(got.lower_x, want.lower_x);
  EXPECT_EQ(got.lower_y, want.lower_y);
  EXPECT_EQ(got.lower_z, want.lower_z);
  EXPECT_EQ(got.upper_x, want.upper_x);
  EXPECT_EQ(got.upper_y, want.upper_y);
  EXPECT_EQ(got.upper_z, want.upper_z);
}

// ------------------------------------------------------------ hits

// Rays from random points around each torus towards random points on it (most
// hit) or beside it (many miss), against the library on the same rays.
TEST(EmbreeIntersect, AgreesWithTheLibraryOnTransformedTori) {
  Device dev;
  std::mt19937_64 rng(7);
  const std::vector<TestTorus> tori = random_tori(rng, 24);
  Scene s(dev.device);
  const ToriGeometry g = toroid::embree::attach_tori(dev.device, s.scene, plain(tori));
  rtcCommitScene(s.scene);
  std::uniform_real_distribution<double> a(-kPi, kPi), u(-1, 1);
  int hits = 0, misses = 0, exact = 0;
  for (std::size_t k = 0; k < tori.size(); ++k) {
    const TestTorus& t = tori[k];
    const double size = t.torus.major + t.torus.minor;
    for (int n = 0; n < 400; ++n) {
      double p[3], target[3], from[3], obj_from[3];
      surface_point(t.torus.major, t.torus.minor, a(rng), a(rng), p);
      if (n % 2) p[0] += 0.3 * size * u(rng), p[1] += 0.3 * size * u(rng), p[2] += 0.3 * size * u(rng);
      apply(t.xf.m, p, target, true);
      for (double& c : obj_from) c = 3 * size * u(rng);
      obj_from[2] += 3 * size;  // mostly outside the torus
      apply(t.xf.m, obj_from, from, true);
      const float o[3] = {static_cast<float>(from[0]), static_cast<float>(from[1]), static_cast<float>(from[2])};
      const float d[3] = {static_cast<float>(target[0] - o[0]), static_cast<float>(target[1] - o[1]),
                          static_cast<float>(target[2] - o[2])};
      // The nearest root over every torus is the scene's answer.
      float want = kFloatInf;
      unsigned want_prim = RTC_INVALID_GEOMETRY_ID;
      for (std::size_t j = 0; j < tori.size(); ++j) {
        float tj;
        if (reference_nearest(tori[j], o, d, 0, kFloatInf, &tj) && tj < want) want = tj, want_prim = unsigned(j);
      }
      const RTCRayHit rh = intersect(s.scene, make_ray(o, d));
      if (want_prim == RTC_INVALID_GEOMETRY_ID) {
        ++misses;
        EXPECT_EQ(rh.hit.geomID, RTC_INVALID_GEOMETRY_ID);
        EXPECT_EQ(rh.ray.tfar, kFloatInf);
        continue;
      }
      ++hits;
      ASSERT_EQ(rh.hit.geomID, g.geom_id());
      EXPECT_EQ(rh.hit.primID, want_prim);
      EXPECT_LE(float_ulps(rh.ray.tfar, want), 1) << rh.ray.tfar << " vs " << want;
      exact += rh.ray.tfar == want;
      // Ng: the library's unit normal at the hit, carried to world space.
      const TestTorus& h = tori[rh.hit.primID];
      const double ow[3] = {o[0], o[1], o[2]}, dw[3] = {d[0], d[1], d[2]};
      double oo[3], dd[3], q[3], nobj[3], nw[3];
      apply(h.xf.inv, ow, oo, true);
      apply(h.xf.inv, dw, dd, false);
      for (int i = 0; i < 3; ++i) q[i] = oo[i] + double(rh.ray.tfar) * dd[i];
      toroid::torus_unit_normal(h.torus.major, h.torus.minor, q, nobj);
      for (int i = 0; i < 3; ++i)
        nw[i] = h.xf.inv[0][i] * nobj[0] + h.xf.inv[1][i] * nobj[1] + h.xf.inv[2][i] * nobj[2];
      const double len = std::sqrt(nw[0] * nw[0] + nw[1] * nw[1] + nw[2] * nw[2]);
      const double dot = (nw[0] * rh.hit.Ng_x + nw[1] * rh.hit.Ng_y + nw[2] * rh.hit.Ng_z) / len;
      EXPECT_GT(dot, 1 - 1e-4);
      EXPECT_NEAR(std::hypot(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z), 1.0, 1e-6);
      EXPECT_GE(rh.hit.u, 0.0f);
      EXPECT_LT(rh.hit.u, 1.0f);
      EXPECT_GE(rh.hit.v, 0.0f);
      EXPECT_LT(rh.hit.v, 1.0f);
    }
  }
  EXPECT_GT(hits, 4000);
  EXPECT_GT(misses, 300);
  EXPECT_GT(exact, hits * 99 / 100);
}

// A ray along the x axis through a torus in the xy-plane meets it four
// times; the scene moves it so that none of the roots is a round number.
struct EmbreeFourRoots : ::testing::Test {
  Device dev;
  Scene s{dev.device};
  TestTorus t = make(1, 0.25, translate(rotate(Affine{}, 2, 0.0), 0.125, 0, 0));
  ToriGeometry g = toroid::embree::attach_tori(dev.device, s.scene, std::vector<EmbreeTorus>{t.torus});
  const float o[3] = {-3, 0, 0}, d[3] = {1, 0, 0};
  // Roots: x = 0.125 +- 1.25, 0.125 +- 0.75.
  const float roots[4] = {1.875f, 2.375f, 3.875f, 4.375f};
  EmbreeFourRoots() { rtcCommitScene(s.scene); }
};

TEST_F(EmbreeFourRoots, TnearAndTfarChooseTheRoot) {
  EXPECT_EQ(intersect(s.scene, make_ray(o, d)).ray.tfar, roots[0]);
  EXPECT_EQ(intersect(s.scene, make_ray(o, d, 2.0f)).ray.tfar, roots[1]);
  // The window is open: a root on tnear is not taken, nor one on tfar.
  EXPECT_EQ(intersect(s.scene, make_ray(o, d, roots[0])).ray.tfar, roots[1]);
  EXPECT_EQ(intersect(s.scene, make_ray(o, d, roots[1])).ray.tfar, roots[2]);
  EXPECT_EQ(intersect(s.scene, make_ray(o, d, 4.0f)).ray.tfar, roots[3]);
  EXPECT_EQ(intersect(s.scene, make_ray(o, d, 4.5f)).hit.geomID, RTC_INVALID_GEOMETRY_ID);
  EXPECT_EQ(intersect(s.scene, make_ray(o, d, 0, roots[0])).hit.geomID, RTC_INVALID_GEOMETRY_ID);
  const RTCRayHit window = intersect(s.scene, make_ray(o, d, 2.5f, 3.5f));
  EXPECT_EQ(window.hit.geomID, RTC_INVALID_GEOMETRY_ID);
  EXPECT_EQ(window.ray.tfar, 3.5f);
  EXPECT_EQ(intersect(s.scene, make_ray(o, d, 3.0f, 4.0f)).ray.tfar, roots[2]);
  // An empty window hits nothing (Embree itself requires tnear and tfar
  // not NaN, and asserts it in Debian's build).
  EXPECT_EQ(intersect(s.scene, make_ray(o, d, 3.0f, 2.0f)).hit.geomID, RTC_INVALID_GEOMETRY_ID);
  EXPECT_EQ(intersect(s.scene, make_ray(o, d, 3.0f, 3.0f)).hit.geomID, RTC_INVALID_GEOMETRY_ID);
  // From inside the hole, the roots behind the origin do not count (Embree
  // requires tnear >= 0).
  const float hole[3] = {-0.5f, 0, 0};
  EXPECT_EQ(intersect(s.scene, make_ray(hole, d)).ray.tfar, roots[2] - 2.5f);
}

TEST_F(EmbreeFourRoots, HitRecord) {
  const RTCRayHit rh = intersect(s.scene, make_ray(o, d));
  EXPECT_EQ(rh.hit.geomID, g.geom_id());
  EXPECT_EQ(rh.hit.primID, 0u);
  EXPECT_EQ(rh.hit.instID[0], RTC_INVALID_GEOMETRY_ID);
  // The outer equator at -x: normal -x, u = 1/2, v = 0.
  EXPECT_FLOAT_EQ(rh.hit.Ng_x, -1);
  EXPECT_FLOAT_EQ(rh.hit.Ng_y, 0);
  EXPECT_FLOAT_EQ(rh.hit.Ng_z, 0);
  EXPECT_FLOAT_EQ(rh.hit.u, 0.5f);
  EXPECT_FLOAT_EQ(rh.hit.v, 0);
  // The inner equator: normal +x, v = 1/2.
  const RTCRayHit inner = intersect(s.scene, make_ray(o, d, 2.0f));
  EXPECT_FLOAT_EQ(inner.hit.Ng_x, 1);
  EXPECT_FLOAT_EQ(inner.hit.v, 0.5f);
  // From above onto the top of the tube at +x: normal +z, u = 0, v = 1/4.
  const float top[3] = {1.125f, 0, 5}, down[3] = {0, 0, -1};
  const RTCRayHit t = intersect(s.scene, make_ray(top, down));
  EXPECT_EQ(t.ray.tfar, 4.75f);
  EXPECT_FLOAT_EQ(t.hit.Ng_z, 1);
  EXPECT_FLOAT_EQ(t.hit.u, 0);
  EXPECT_FLOAT_EQ(t.hit.v, 0.25f);
}

TEST_F(EmbreeFourRoots, OccludedHonoursTheWindow) {
  const auto ray = [&](float tnear, float tfar) { return make_ray(o, d, tnear, tfar).ray; };
  EXPECT_TRUE(occluded(s.scene, ray(0, kFloatInf)));
  EXPECT_FALSE(occluded(s.scene, ray(0, 1.8f)));
  EXPECT_FALSE(occluded(s.scene, ray(0, roots[0])));
  EXPECT_TRUE(occluded(s.scene, ray(0, std::nextafter(roots[0], kFloatInf))));
  EXPECT_FALSE(occluded(s.scene, ray(2.4f, 3.8f)));
  EXPECT_TRUE(occluded(s.scene, ray(2.4f, 3.9f)));
  EXPECT_FALSE(occluded(s.scene, ray(roots[3], kFloatInf)));
  EXPECT_FALSE(occluded(s.scene, ray(3.0f, 2.0f)));
  // rtcOccluded1 agrees with rtcIntersect1 on random windows.
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<float> w(0, 6);
  for (int k = 0; k < 2000; ++k) {
    float a = w(rng), b = w(rng);
    if (a > b) std::swap(a, b);
    const bool hit = intersect(s.scene, make_ray(o, d, a, b)).hit.geomID != RTC_INVALID_GEOMETRY_ID;
    ASSERT_EQ(occluded(s.scene, ray(a, b)), hit) << a << " " << b;
  }
}

// Embree requires finite rays (it asserts |org|, |dir| <= 1.844e18), so the
// callbacks' own check for a non-finite object-space ray is not reachable
// from here; a zero direction is a valid Embree ray and hits nothing.
TEST_F(EmbreeFourRoots, ARayWithoutADirectionHitsNothing) {
  const float zero[3] = {0, 0, 0}, tiny[3] = {1e-30f, 0, 0};
  EXPECT_EQ(intersect(s.scene, make_ray(o, zero)).hit.geomID, RTC_INVALID_GEOMETRY_ID);
  EXPECT_FALSE(occluded(s.scene, make_ray(o, zero).ray));
  // A tiny direction is a direction: t is huge, and still the root.
  EXPECT_EQ(intersect(s.scene, make_ray(o, tiny)).ray.tfar, 1.875e30f);
}

// ------------------------------------------------------------ filters

// What the filter saw, and which hits it rejects: the first `reject` calls.
struct FilterLog {
  explicit FilterLog(int r = 1) : reject(r) {}
  int reject;
  int calls = 0;
  std::vector<float> tfar;
  std::vector<unsigned> prim, geom;
};

struct LoggingContext {
  RTCIntersectContext context;  // first: Embree passes a pointer to it
  FilterLog* log;
};

void logging_filter(const RTCFilterFunctionNArguments* args) {
  if (args->valid[0] != -1) return;
  ASSERT_EQ(args->N, 1u);
  FilterLog* log = reinterpret_cast<const LoggingContext*>(args->context)->log;
  log->tfar.push_back(RTCRayN_tfar(args->ray, 1, 0));
  log->prim.push_back(RTCHitN_primID(args->hit, 1, 0));
  log->geom.push_back(RTCHitN_geomID(args->hit, 1, 0));
  if (log->calls++ < log->reject) args->valid[0] = 0;
}

TEST_F(EmbreeFourRoots, GeometryFilterRejectingTheFirstHitGivesTheSecondRoot) {
  rtcSetGeometryIntersectFilterFunction(g.geometry(), logging_filter);
  rtcSetGeometryOccludedFilterFunction(g.geometry(), logging_filter);
  rtcCommitGeometry(g.geometry());
  rtcCommitScene(s.scene);
  FilterLog log;
  LoggingContext c;
  rtcInitIntersectContext(&c.context);
  c.log = &log;
  const RTCRayHit rh = intersect(s.scene, make_ray(o, d), &c.context);
  EXPECT_EQ(rh.ray.tfar, roots[1]);
  EXPECT_EQ(rh.hit.Ng_x, 1.0f);  // the second root's record, not the first's
  ASSERT_EQ(log.tfar.size(), 2u);
  EXPECT_EQ(log.tfar[0], roots[0]);
  EXPECT_EQ(log.tfar[1], roots[1]);
  EXPECT_EQ(log.prim[0], 0u);
  EXPECT_EQ(log.geom[0], g.geom_id());

  // Rejecting three: the fourth root.
  log = FilterLog{3};
  EXPECT_EQ(intersect(s.scene, make_ray(o, d), &c.context).ray.tfar, roots[3]);
  // Rejecting all: no hit, tfar as it was.
  log = FilterLog{4};
  const RTCRayHit none = intersect(s.scene, make_ray(o, d, 0, 100), &c.context);
  EXPECT_EQ(none.hit.geomID, RTC_INVALID_GEOMETRY_ID);
  EXPECT_EQ(none.ray.tfar, 100.0f);
  EXPECT_EQ(log.calls, 4);

  // Occlusion: a rejected root lets the next one occlude.
  log = FilterLog{1};
  RTCRay ray = make_ray(o, d).ray;
  EXPECT_TRUE(occluded(s.scene, ray, &c.context));
  EXPECT_EQ(log.calls, 2);
  log = FilterLog{4};
  EXPECT_FALSE(occluded(s.scene, ray, &c.context));
  EXPECT_EQ(log.calls, 4);
  // Inside a window, only the roots inside are offered.
  log = FilterLog{1};
  EXPECT_TRUE(occluded(s.scene, make_ray(o, d, 0, 3).ray, &c.context));
  EXPECT_EQ(log.calls, 2);
  log = FilterLog{2};
  EXPECT_FALSE(occluded(s.scene, make_ray(o, d, 0, 3).ray, &c.context));
  EXPECT_EQ(log.calls, 2);
}

TEST(EmbreeFilter, ContextFilterSeesEveryCandidate) {
  Device dev;
  Scene s(dev.device, RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
  const TestTorus t = make(2, 0.5, rotate(Affine{}, 0, kPi / 2));  // ring in the xz-plane
  const ToriGeometry g = toroid::embree::attach_tori(dev.device, s.scene, std::vector<EmbreeTorus>{t.torus});
  rtcCommitScene(s.scene);
  FilterLog log{2};
  LoggingContext c;
  rtcInitIntersectContext(&c.context);
  c.context.filter = logging_filter;
  c.log = &log;
  const float o[3] = {0, 0, -10}, d[3] = {0, 0, 2};  // along z: roots at z = -2.5, -1.5, 1.5, 2.5
  const RTCRayHit rh = intersect(s.scene, make_ray(o, d), &c.context);
  EXPECT_EQ(rh.ray.tfar, 5.75f);
  EXPECT_EQ(log.calls, 3);
}

// ------------------------------------------------------------ packets, streams, instances

TEST(EmbreePackets, AgreeWithSingleRaysAndLeaveInvalidLanesAlone) {
  Device dev;
  std::mt19937_64 rng(11);
  const std::vector<TestTorus> tori = random_tori(rng, 12);
  Scene s(dev.device);
  const ToriGeometry g = toroid::embree::attach_tori(dev.device, s.scene, plain(tori));
  rtcCommitScene(s.scene);
  std::uniform_real_distribution<float> u(-25, 25);
  std::vector<RTCRayHit> rays;
  for (int k = 0; k < 16 * 64; ++k) {
    const float o[3] = {u(rng), u(rng), 40}, to[3] = {u(rng), u(rng), u(rng)};
    const float d[3] = {to[0] - o[0], to[1] - o[1], to[2] - o[2]};
    rays.push_back(make_ray(o, d, k % 5 == 0 ? 0.9f : 0.0f, k % 7 == 0 ? 1.0f : kFloatInf));
  }
  int hits = 0;
  for (int width : {4, 8, 16}) {
    // Where the CPU has no native packet of this width (16 without AVX-512),
    // Embree 3 hands the packet to its stream path, which ignores the valid
    // mask and skips a ray only when tnear > tfar: an inactive lane needs both.
    const RTCDeviceProperty native = width == 4   ? RTC_DEVICE_PROPERTY_NATIVE_RAY4_SUPPORTED
                                     : width == 8 ? RTC_DEVICE_PROPERTY_NATIVE_RAY8_SUPPORTED
                                                  : RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED;
    const bool mask_is_honoured = rtcGetDeviceProperty(dev.device, native) != 0;
    for (std::size_t base = 0; base < rays.size(); base += std::size_t(width)) {
      alignas(64) RTCRayHit16 packet{};
      alignas(64) int valid[16];
      float written_tfar[16];
      for (int i = 0; i < width; ++i) {
        const RTCRayHit& r = rays[base + std::size_t(i)];
        valid[i] = (base / std::size_t(width) + std::size_t(i)) % 3 == 0 ? 0 : -1;
        // Write the lane of a width-wide packet (its own layout: arrays of width).
        RTCRayHitN* p = reinterpret_cast<RTCRayHitN*>(&packet);
        RTCRayN* pr = RTCRayHitN_RayN(p, unsigned(width));
        RTCHitN* ph = RTCRayHitN_HitN(p, unsigned(width));
        RTCRayN_org_x(pr, width, i) = r.ray.org_x, RTCRayN_org_y(pr, width, i) = r.ray.org_y;
        RTCRayN_org_z(pr, width, i) = r.ray.org_z, RTCRayN_tnear(pr, width, i) = r.ray.tnear;
        RTCRayN_dir_x(pr, width, i) = r.ray.dir_x, RTCRayN_dir_y(pr, width, i) = r.ray.dir_y;
        RTCRayN_dir_z(pr, width, i) = r.ray.dir_z, RTCRayN_time(pr, width, i) = 0;
        RTCRayN_tfar(pr, width, i) = r.ray.tfar, RTCRayN_mask(pr, width, i) = ~0u;
        if (valid[i] == 0 && !mask_is_honoured) RTCRayN_tnear(pr, width, i) = 1, RTCRayN_tfar(pr, width, i) = 0;
        written_tfar[i] = RTCRayN_tfar(pr, width, i);
        RTCRayN_id(pr, width, i) = 0, RTCRayN_flags(pr, width, i) = 0;
        RTCHitN_geomID(ph, width, i) = RTC_INVALID_GEOMETRY_ID;
      }
      RTCRayHitN* p = reinterpret_cast<RTCRayHitN*>(&packet);
      RTCRayN* pr = RTCRayHitN_RayN(p, unsigned(width));
      RTCHitN* ph = RTCRayHitN_HitN(p, unsigned(width));
      // An occlusion packet: the same rays.
      alignas(64) RTCRay16 shadow;
      std::copy_n(reinterpret_cast<const char*>(&packet), sizeof(float) * 12 * std::size_t(width),
                  reinterpret_cast<char*>(&shadow));
      RTCRayN* sr = reinterpret_cast<RTCRayN*>(&shadow);
      RTCIntersectContext c;
      rtcInitIntersectContext(&c);
      switch (width) {
        case 4:
          rtcIntersect4(valid, s.scene, &c, reinterpret_cast<RTCRayHit4*>(&packet));
          rtcOccluded4(valid, s.scene, &c, reinterpret_cast<RTCRay4*>(&shadow));
          break;
        case 8:
          rtcIntersect8(valid, s.scene, &c, reinterpret_cast<RTCRayHit8*>(&packet));
          rtcOccluded8(valid, s.scene, &c, reinterpret_cast<RTCRay8*>(&shadow));
          break;
        default: rtcIntersect16(valid, s.scene, &c, &packet); rtcOccluded16(valid, s.scene, &c, &shadow);
      }
      for (int i = 0; i < width; ++i) {
        const RTCRayHit& r = rays[base + std::size_t(i)];
        if (valid[i] == 0) {
          EXPECT_EQ(RTCRayN_tfar(pr, width, i), written_tfar[i]);
          EXPECT_EQ(RTCHitN_geomID(ph, width, i), RTC_INVALID_GEOMETRY_ID);
          EXPECT_EQ(RTCRayN_tfar(sr, width, i), written_tfar[i]);
          continue;
        }
        const RTCRayHit one = intersect(s.scene, r);
        EXPECT_EQ(RTCRayN_tfar(pr, width, i), one.ray.tfar);
        EXPECT_EQ(RTCHitN_geomID(ph, width, i), one.hit.geomID);
        if (one.hit.geomID == RTC_INVALID_GEOMETRY_ID) {
          EXPECT_EQ(RTCRayN_tfar(sr, width, i), r.ray.tfar);
          continue;
        }
        ++hits;
        EXPECT_EQ(RTCHitN_primID(ph, width, i), one.hit.primID);
        EXPECT_EQ(RTCHitN_Ng_x(ph, width, i), one.hit.Ng_x);
        EXPECT_EQ(RTCHitN_Ng_y(ph, width, i), one.hit.Ng_y);
        EXPECT_EQ(RTCHitN_Ng_z(ph, width, i), one.hit.Ng_z);
        EXPECT_EQ(RTCHitN_u(ph, width, i), one.hit.u);
        EXPECT_EQ(RTCHitN_v(ph, width, i), one.hit.v);
        EXPECT_EQ(RTCRayN_tfar(sr, width, i), -kFloatInf);
      }
    }
  }
  EXPECT_GT(hits, 300);
}

TEST(EmbreeInstances, HitsThroughAnInstanceCarryItsId) {
  Device dev;
  Scene inner(dev.device), outer(dev.device);
  const TestTorus t = make(1, 0.25, Affine{});
  const ToriGeometry g = toroid::embree::attach_tori(dev.device, inner.scene, std::vector<EmbreeTorus>{t.torus});
  rtcCommitScene(inner.scene);
  RTCGeometry instance = rtcNewGeometry(dev.device, RTC_GEOMETRY_TYPE_INSTANCE);
  rtcSetGeometryInstancedScene(instance, inner.scene);
  // Moved to x = 10 and scaled by 2 (row-major 3x4 -> Embree's column-major).
  const float xfm[12] = {2, 0, 0, 0, 2, 0, 0, 0, 2, 10, 0, 0};
  rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm);
  rtcCommitGeometry(instance);
  const unsigned instance_id = rtcAttachGeometry(outer.scene, instance);
  rtcReleaseGeometry(instance);
  rtcCommitScene(outer.scene);
  const float o[3] = {0, 0, 0}, d[3] = {1, 0, 0};
  const RTCRayHit rh = intersect(outer.scene, make_ray(o, d));
  EXPECT_EQ(rh.hit.instID[0], instance_id);
  EXPECT_EQ(rh.hit.geomID, g.geom_id());
  EXPECT_EQ(rh.hit.primID, 0u);
  EXPECT_EQ(rh.ray.tfar, 10.0f - 2 * 1.25f);
  EXPECT_TRUE(occluded(outer.scene, make_ray(o, d).ray));
}

// ------------------------------------------------------------ bad inputs, lifetime

void expect_rejected(const EmbreeTorus& bad, const std::string& problem) {
  Device dev;
  Scene s(dev.device);
  std::vector<EmbreeTorus> tori(3);
  tori[1] = bad;
  try {
    toroid::embree::attach_tori(dev.device, s.scene, tori);
    ADD_FAILURE() << "accepted: " << problem;
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("torus 1: "), std::string::npos) << what;
    EXPECT_NE(what.find(problem), std::string::npos) << what;
  }
  EXPECT_THROW(toroid::embree::torus_world_bounds(bad), std::invalid_argument);
  // Nothing was attached: the scene is empty.
  rtcCommitScene(s.scene);
  const float o[3] = {-3, 0, 0}, d[3] = {1, 0, 0};
  EXPECT_EQ(intersect(s.scene, make_ray(o, d)).hit.geomID, RTC_INVALID_GEOMETRY_ID);
  RTCBounds b;
  rtcGetSceneBounds(s.scene, &b);
  EXPECT_GT(b.lower_x, b.upper_x);
}

TEST(EmbreeBadInput, RadiiAreChecked) {
  const double nan = std::nan(""), inf = std::numeric_limits<double>::infinity();
  for (double bad : {0.0, -1.0, nan, inf, -inf}) {
    EmbreeTorus t;
    t.major = bad;
    expect_rejected(t, "major must be finite and > 0");
    t = EmbreeTorus{};
    t.minor = bad;
    expect_rejected(t, "minor must be finite and > 0");
  }
  EmbreeTorus fat;
  fat.major = 1, fat.minor = 2.5;
  expect_rejected(fat, "minor / major = 2.5 is outside [2^-30, 2]");
  EmbreeTorus thin;
  thin.major = 1, thin.minor = 0x1p-31;
  expect_rejected(thin, "is outside [2^-30, 2]");
  // The ends of the range are accepted.
  thin.minor = 0x1p-30;
  EXPECT_NO_THROW(toroid::embree::torus_world_bounds(thin));
  fat.minor = 2;
  EXPECT_NO_THROW(toroid::embree::torus_world_bounds(fat));
}

TEST(EmbreeBadInput, TransformsAreChecked) {
  EmbreeTorus t;
  t.object_to_world[2][3] = std::nan("");
  expect_rejected(t, "object_to_world[2][3] is nan");
  t = EmbreeTorus{};
  t.object_to_world[0][1] = std::numeric_limits<double>::infinity();
  expect_rejected(t, "object_to_world[0][1] is inf");
  t = EmbreeTorus{};
  t.object_to_world[1][1] = 0;  // singular
  expect_rejected(t, "object_to_world is singular or nearly so");
  t = EmbreeTorus{};
  for (auto& row : t.object_to_world) row[0] = row[1] = row[2] = 0;  // all zero
  expect_rejected(t, "object_to_world is singular or nearly so");
  for (auto& row : t.object_to_world) row[0] = row[1] = row[2] = 1;  // rank one
  expect_rejected(t, "object_to_world is singular or nearly so");
  t = EmbreeTorus{};
  t.object_to_world[2][2] = 1e-13;  // nearly singular
  expect_rejected(t, "object_to_world is singular or nearly so");
  t = EmbreeTorus{};
  t.object_to_world[0][3] = 1e19;
  expect_rejected(t, "its world box reaches 1e+19 on axis x");
  // A flattened torus that is still well conditioned enough is accepted.
  t = EmbreeTorus{};
  t.object_to_world[2][2] = 1e-11;
  EXPECT_NO_THROW(toroid::embree::torus_world_bounds(t));
}

TEST(EmbreeBadInput, NullHandlesAndEmptyObjects) {
  Device dev;
  Scene s(dev.device);
  const std::vector<EmbreeTorus> one(1);
  try {
    ToriGeometry g(nullptr, one);
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "toroid::embree: the device is null");
  }
  try {
    toroid::embree::attach_tori(dev.device, nullptr, one);
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "toroid::embree: the scene is null");
  }
  ToriGeometry g(dev.device, one);
  ToriGeometry moved = std::move(g);
  EXPECT_EQ(g.geometry(), nullptr);  // NOLINT(bugprone-use-after-move): documented state
  EXPECT_TRUE(g.tori().empty());
  EXPECT_THROW(g.attach(s.scene), std::invalid_argument);
  EXPECT_THROW(moved.attach(nullptr), std::invalid_argument);
  EXPECT_EQ(moved.tori().size(), 1u);
  EXPECT_EQ(moved.geom_id(), RTC_INVALID_GEOMETRY_ID);
  EXPECT_EQ(moved.attach(s.scene), 0u);
  EXPECT_EQ(moved.geom_id(), 0u);
}

TEST(EmbreeBadInput, NoToriIsAnEmptyGeometry) {
  Device dev;
  Scene s(dev.device);
  const ToriGeometry g = toroid::embree::attach_tori(dev.device, s.scene, {});
  rtcCommitScene(s.scene);
  EXPECT_TRUE(g.tori().empty());
  const float o[3] = {-3, 0, 0}, d[3] = {1, 0, 0};
  EXPECT_EQ(intersect(s.scene, make_ray(o, d)).hit.geomID, RTC_INVALID_GEOMETRY_ID);
}

TEST(EmbreeLifetime, TheOwnerFreesTheDataAndAScenePastItSeesNoTori) {
  Device dev;
  Scene s(dev.device);
  const float o[3] = {-3, 0, 0}, d[3] = {1, 0, 0};
  {
    const ToriGeometry g = toroid::embree::attach_tori(dev.device, s.scene, std::vector<EmbreeTorus>(1));
    rtcCommitScene(s.scene);
    EXPECT_EQ(intersect(s.scene, make_ray(o, d)).ray.tfar, 1.75f);
  }
  // The scene still holds the geometry, whose data is gone: no hits, no
  // crash (AddressSanitizer builds check that nothing freed is read).
  EXPECT_EQ(intersect(s.scene, make_ray(o, d)).hit.geomID, RTC_INVALID_GEOMETRY_ID);
  EXPECT_FALSE(occluded(s.scene, make_ray(o, d).ray));
  // Move assignment releases what it replaces.
  ToriGeometry a(dev.device, std::vector<EmbreeTorus>(2));
  a = ToriGeometry(dev.device, std::vector<EmbreeTorus>(3));
  EXPECT_EQ(a.tori().size(), 3u);
}

}  // namespace
