// SPDX-License-Identifier: Apache-2.0
#include "toroid/embree_tori.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "toroid/torus/checked.h"
#include "toroid/torus/float_api.h"
#include "toroid/torus/intersect.h"
#include "toroid/torus/surface.h"

namespace toroid::embree {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr float kFloatInf = std::numeric_limits<float>::infinity();

// The shortest text that reads back as x.
std::string number(double x) {
  char buf[32];
  const auto end = std::to_chars(buf, buf + sizeof buf, x).ptr;
  return std::string(buf, end);
}

// The linear part's inverse by cofactors; all NaN or infinite when singular.
void invert3(const double m[3][4], double inv[3][3]) {
  const double c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1];
  const double c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2];
  const double c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
  const double det = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
  inv[0][0] = c00 / det;
  inv[1][0] = c01 / det;
  inv[2][0] = c02 / det;
  inv[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) / det;
  inv[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) / det;
  inv[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) / det;
  inv[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) / det;
  inv[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) / det;
  inv[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) / det;
}

// Frobenius norm, scaled first so that no square overflows or underflows;
// NaN when an entry is (the inverse of a singular matrix).
double frobenius(const double (&a)[3][3]) {
  double big = 0;
  for (const auto& row : a)
    for (double x : row)
      if (!(std::abs(x) <= big)) big = std::abs(x);
  if (!(big > 0) || !std::isfinite(big)) return big;
  double sum = 0;
  for (const auto& row : a)
    for (double x : row) sum += (x / big) * (x / big);
  return big * std::sqrt(sum);
}

// The box in double, before the rounding to float: centre d, half-width h.
struct Extent {
  double d[3], h[3];
};

Extent world_extent(const EmbreeTorus& t) {
  Extent e;
  const auto& m = t.object_to_world;
  for (int i = 0; i < 3; ++i) {
    const double ring = std::hypot(m[i][0], m[i][1]);
    const double ball = std::hypot(m[i][0], m[i][1], m[i][2]);
    e.d[i] = m[i][3];
    // hypot, the products and their sum are each within an ulp or so: the
    // margin keeps h above its exact value.
    const double h = t.major * ring + t.minor * ball;
    e.h[i] = h * (1 + 16 * std::numeric_limits<double>::epsilon());
  }
  return e;
}

// The float at or below (lo) or at or above (hi) a double.
float float_down(double x) {
  const float f = static_cast<float>(x);
  return static_cast<double>(f) > x ? std::nextafter(f, -kFloatInf) : f;
}
float float_up(double x) {
  const float f = static_cast<float>(x);
  return static_cast<double>(f) < x ? std::nextafter(f, kFloatInf) : f;
}

RTCBounds bounds_of(const Extent& e) {
  // d - h and d + h round once each (half an ulp of the result): one double
  // step outwards covers that, and the float rounding goes outwards too.
  RTCBounds b{};
  float lo[3], hi[3];
  for (int i = 0; i < 3; ++i) {
    lo[i] = float_down(std::nextafter(e.d[i] - e.h[i], -kInf));
    hi[i] = float_up(std::nextafter(e.d[i] + e.h[i], kInf));
  }
  b.lower_x = lo[0], b.lower_y = lo[1], b.lower_z = lo[2];
  b.upper_x = hi[0], b.upper_y = hi[1], b.upper_z = hi[2];
  return b;
}

// Empty string when the torus is accepted, else what is wrong with it.
std::string torus_problem(const EmbreeTorus& t) {
  for (const auto& [value, name] : {std::pair{t.major, "major"}, std::pair{t.minor, "minor"}})
    if (!std::isfinite(value) || !(value > 0))
      return std::string(name) + " must be finite and > 0, got " + number(value);
  const double aspect = t.minor / t.major;
  if (!(aspect >= 1 / kTorusAspectLimit && aspect <= kTorusFattestSpindle))
    return "minor / major = " + number(aspect) +
           " is outside [2^-30, 2], the range over which the roots' accuracy is stated";
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j)
      if (!std::isfinite(t.object_to_world[i][j]))
        return "object_to_world[" + std::to_string(i) + "][" + std::to_string(j) + "] is " +
               number(t.object_to_world[i][j]) + " (every entry must be finite)";
  double inv[3][3], lin[3][3];
  invert3(t.object_to_world, inv);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) lin[i][j] = t.object_to_world[i][j];
  const double condition = frobenius(lin) * frobenius(inv);
  if (!(condition <= kMaxCondition))
    return "object_to_world is singular or nearly so (condition number of its 3x3 part " + number(condition) +
           ", above 1e12)";
  const Extent e = world_extent(t);
  for (int i = 0; i < 3; ++i)
    if (!(std::abs(e.d[i]) + e.h[i] < kMaxCoordinate))
      return std::string("its world box reaches ") + number(std::abs(e.d[i]) + e.h[i]) + " on axis " + "xyz"[i] +
             ", beyond Embree's +-1.844e18";
  return {};
}

// One torus as the callbacks use it.
struct Prepared {
  double major, minor;
  double m[3][4];    // object to world
  double inv[3][3];  // world to object, linear part
};

Prepared prepare(const EmbreeTorus& t) {
  Prepared p{};
  p.major = t.major;
  p.minor = t.minor;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) p.m[i][j] = t.object_to_world[i][j];
  invert3(t.object_to_world, p.inv);
  return p;
}

// The geometry's user data: the tori as given and as the callbacks use them.
struct ToriData {
  std::vector<EmbreeTorus> tori;
  std::vector<Prepared> prepared;
};

// A world ray (float) in the torus's object space (double, direction not
// normalised).
struct ObjectRay {
  double o[3], d[3];
};

ObjectRay to_object(const Prepared& p, const float org[3], const float dir[3]) {
  const double q[3] = {static_cast<double>(org[0]) - p.m[0][3], static_cast<double>(org[1]) - p.m[1][3],
                       static_cast<double>(org[2]) - p.m[2][3]};
  ObjectRay r;
  for (int i = 0; i < 3; ++i) {
    r.o[i] = p.inv[i][0] * q[0] + p.inv[i][1] * q[1] + p.inv[i][2] * q[2];
    r.d[i] = p.inv[i][0] * dir[0] + p.inv[i][1] * dir[1] + p.inv[i][2] * dir[2];
  }
  return r;
}

// The roots of the ray whose floats lie strictly inside (tnear, tfar),
// ascending. Returns their count.
int roots_in_window(const Prepared& p, const ObjectRay& r, float tnear, float tfar, double roots[4]) {
  double lo, hi;
  if (!float_interval_in_double(tnear, tfar, &lo, &hi)) return 0;
  if (!torus_ray_valid(r.o, r.d)) return 0;
  double all[4];
  const int n = intersect_torus(p.major, p.minor, r.o, r.d, all);
  int kept = 0;
  for (int i = 0; i < n; ++i)
    if (all[i] > lo && all[i] < hi) roots[kept++] = all[i];
  return kept;
}

// Wraps a fraction of a turn into [0, 1) in float.
float turns(double angle) {
  double f = angle / (2 * std::numbers::pi);
  f -= std::floor(f);
  const float u = static_cast<float>(f);
  return u < 1.0f ? u : std::nextafter(1.0f, 0.0f);
}

// The hit record of root t: world normal, surface parameters, ids.
RTCHit make_hit(const Prepared& p, const ObjectRay& r, double t, unsigned prim_id, unsigned geom_id,
                const RTCIntersectContext* context) {
  const double q[3] = {r.o[0] + t * r.d[0], r.o[1] + t * r.d[1], r.o[2] + t * r.d[2]};
  double n[3], w[3];
  torus_normal(p.major, p.minor, q, n);
  for (int i = 0; i < 3; ++i) w[i] = p.inv[0][i] * n[0] + p.inv[1][i] * n[1] + p.inv[2][i] * n[2];
  // Unit length, scaled first by the largest component (no overflow in
  // float, whatever the transform's scale).
  const double big = std::max({std::abs(w[0]), std::abs(w[1]), std::abs(w[2])});
  if (big > 0 && std::isfinite(big)) {
    for (double& x : w) x /= big;
    const double len = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    for (double& x : w) x /= len;
  }
  double theta, phi;
  torus_angles(p.major, p.minor, q, &theta, &phi);
  RTCHit h{};
  h.Ng_x = static_cast<float>(w[0]);
  h.Ng_y = static_cast<float>(w[1]);
  h.Ng_z = static_cast<float>(w[2]);
  h.u = turns(theta);
  h.v = turns(phi);
  h.primID = prim_id;
  h.geomID = geom_id;
  for (unsigned l = 0; l < RTC_MAX_INSTANCE_LEVEL_COUNT; ++l) h.instID[l] = RTC_INVALID_GEOMETRY_ID;
  if (context) {
#if RTC_MAX_INSTANCE_LEVEL_COUNT > 1
    for (unsigned l = 0; l < RTC_MAX_INSTANCE_LEVEL_COUNT && l < context->instStackSize; ++l)
      h.instID[l] = context->instID[l];
#else
    h.instID[0] = context->instID[0];
#endif
  }
  return h;
}

void bounds_callback(const RTCBoundsFunctionArguments* args) {
  const auto* data = static_cast<const ToriData*>(args->geometryUserPtr);
  if (!data || args->primID >= data->tori.size()) {
    // No data (the owner is gone): an empty box, which Embree leaves out.
    *args->bounds_o = RTCBounds{kFloatInf, kFloatInf, kFloatInf, 0, -kFloatInf, -kFloatInf, -kFloatInf, 0};
    return;
  }
  *args->bounds_o = bounds_of(world_extent(data->tori[args->primID]));
}

// Ray i of a callback's N: its roots inside its (tnear, tfar), nearest
// first, each as a hit record, offered to `accept` with the single ray's copy
// whose tfar is that root (what the filters are given) until it accepts one.
template <class Accept>
void offer_roots(const Prepared& p, RTCRayN* rays, unsigned n, unsigned i, unsigned prim_id, unsigned geom_id,
                 const RTCIntersectContext* context, Accept accept) {
  RTCRayHit single{};
  single.ray = rtcGetRayFromRayN(rays, n, i);
  const float org[3] = {single.ray.org_x, single.ray.org_y, single.ray.org_z};
  const float dir[3] = {single.ray.dir_x, single.ray.dir_y, single.ray.dir_z};
  const ObjectRay r = to_object(p, org, dir);
  double roots[4];
  const int count = roots_in_window(p, r, single.ray.tnear, single.ray.tfar, roots);
  for (int k = 0; k < count; ++k) {
    RTCHit hit = make_hit(p, r, roots[k], prim_id, geom_id, context);
    single.ray.tfar = static_cast<float>(roots[k]);
    if (accept(single, hit)) return;
  }
}

// Runs the geometry's and the context's filters on one candidate hit, as
// Embree's protocol asks of user geometry; false when a filter rejects it.
template <typename Arguments>
bool passes_filter(const Arguments* args, RTCRayHit& single, RTCHit& hit,
                   void (*filter_function)(const Arguments*, const RTCFilterFunctionNArguments*)) {
  int valid = -1;
  if (args->context) {
    const RTCFilterFunctionNArguments filter{&valid,
                                             args->geometryUserPtr,
                                             args->context,
                                             reinterpret_cast<RTCRayN*>(&single),
                                             reinterpret_cast<RTCHitN*>(&hit),
                                             1};
    filter_function(args, &filter);
  }
  return valid == -1;
}

void intersect_callback(const RTCIntersectFunctionNArguments* args) {
  const auto* data = static_cast<const ToriData*>(args->geometryUserPtr);
  if (!data || args->primID >= data->prepared.size()) return;
  const unsigned n = args->N;
  RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, n);
  RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, n);
  for (unsigned i = 0; i < n; ++i) {
    if (args->valid[i] != -1) continue;
    offer_roots(data->prepared[args->primID], rays, n, i, args->primID, args->geomID, args->context,
                [&](RTCRayHit& single, RTCHit& hit) {
                  // A filter may change the hit record, which is kept, but not t.
                  const float t = single.ray.tfar;
                  if (!passes_filter(args, single, hit, rtcFilterIntersection)) return false;
                  RTCRayN_tfar(rays, n, i) = t;
                  rtcCopyHitToHitN(hits, &hit, n, i);
                  return true;
                });
  }
}

void occluded_callback(const RTCOccludedFunctionNArguments* args) {
  const auto* data = static_cast<const ToriData*>(args->geometryUserPtr);
  if (!data || args->primID >= data->prepared.size()) return;
  const unsigned n = args->N;
  RTCRayN* rays = args->ray;
  for (unsigned i = 0; i < n; ++i) {
    if (args->valid[i] != -1) continue;
    offer_roots(data->prepared[args->primID], rays, n, i, args->primID, args->geomID, args->context,
                [&](RTCRayHit& single, RTCHit& hit) {
                  if (!passes_filter(args, single, hit, rtcFilterOcclusion)) return false;
                  RTCRayN_tfar(rays, n, i) = -kFloatInf;
                  return true;
                });
  }
}

std::string error_text(RTCDevice device) {
  switch (rtcGetDeviceError(device)) {
    case RTC_ERROR_NONE: return "no error code";
    case RTC_ERROR_UNKNOWN: return "RTC_ERROR_UNKNOWN";
    case RTC_ERROR_INVALID_ARGUMENT: return "RTC_ERROR_INVALID_ARGUMENT";
    case RTC_ERROR_INVALID_OPERATION: return "RTC_ERROR_INVALID_OPERATION";
    case RTC_ERROR_OUT_OF_MEMORY: return "RTC_ERROR_OUT_OF_MEMORY";
    case RTC_ERROR_UNSUPPORTED_CPU: return "RTC_ERROR_UNSUPPORTED_CPU";
    case RTC_ERROR_CANCELLED: return "RTC_ERROR_CANCELLED";
  }
  return "an unknown error code";
}

}  // namespace

struct ToriGeometry::Data : ToriData {};

RTCBounds torus_world_bounds(const EmbreeTorus& torus) {
  if (const std::string problem = torus_problem(torus); !problem.empty())
    throw std::invalid_argument("toroid::embree: torus: " + problem);
  return bounds_of(world_extent(torus));
}

ToriGeometry::ToriGeometry() noexcept = default;

ToriGeometry::ToriGeometry(RTCDevice device, std::span<const EmbreeTorus> tori) {
  if (!device) throw std::invalid_argument("toroid::embree: the device is null");
  if (tori.size() > std::numeric_limits<unsigned>::max())
    throw std::invalid_argument("toroid::embree: " + std::to_string(tori.size()) +
                                " tori are more than an unsigned primID can count");
  for (std::size_t i = 0; i < tori.size(); ++i)
    if (const std::string problem = torus_problem(tori[i]); !problem.empty())
      throw std::invalid_argument("toroid::embree: torus " + std::to_string(i) + ": " + problem);
  auto data = std::make_unique<Data>();
  data->tori.assign(tori.begin(), tori.end());
  data->prepared.reserve(tori.size());
  for (const EmbreeTorus& t : tori) data->prepared.push_back(prepare(t));

  RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
  if (!g) throw std::runtime_error("toroid::embree: rtcNewGeometry failed (" + error_text(device) + ")");
  rtcSetGeometryUserPrimitiveCount(g, static_cast<unsigned>(tori.size()));
  rtcSetGeometryUserData(g, static_cast<ToriData*>(data.get()));
  rtcSetGeometryBoundsFunction(g, bounds_callback, nullptr);
  rtcSetGeometryIntersectFunction(g, intersect_callback);
  rtcSetGeometryOccludedFunction(g, occluded_callback);
  rtcCommitGeometry(g);
  data_ = std::move(data);
  geometry_ = g;
}

ToriGeometry::ToriGeometry(ToriGeometry&& other) noexcept
    : data_(std::move(other.data_)),
      geometry_(std::exchange(other.geometry_, nullptr)),
      geom_id_(std::exchange(other.geom_id_, RTC_INVALID_GEOMETRY_ID)) {}

ToriGeometry& ToriGeometry::operator=(ToriGeometry&& other) noexcept {
  if (this != &other) {
    ToriGeometry old(std::move(*this));
    data_ = std::move(other.data_);
    geometry_ = std::exchange(other.geometry_, nullptr);
    geom_id_ = std::exchange(other.geom_id_, RTC_INVALID_GEOMETRY_ID);
  }
  return *this;
}

ToriGeometry::~ToriGeometry() {
  if (geometry_) {
    // A scene that still holds the geometry then sees no tori (the
    // callbacks find no data) rather than freed memory.
    rtcSetGeometryUserData(geometry_, nullptr);
    rtcReleaseGeometry(geometry_);
  }
}

RTCGeometry ToriGeometry::geometry() const noexcept { return geometry_; }

std::span<const EmbreeTorus> ToriGeometry::tori() const noexcept {
  if (!data_) return {};
  return data_->tori;
}

unsigned ToriGeometry::attach(RTCScene scene) {
  if (!scene) throw std::invalid_argument("toroid::embree: the scene is null");
  if (!geometry_) throw std::invalid_argument("toroid::embree: attach on an empty ToriGeometry");
  const unsigned id = rtcAttachGeometry(scene, geometry_);
  if (id == RTC_INVALID_GEOMETRY_ID)
    throw std::runtime_error("toroid::embree: rtcAttachGeometry failed (is the scene from another device?)");
  geom_id_ = id;
  return id;
}

ToriGeometry attach_tori(RTCDevice device, RTCScene scene, std::span<const EmbreeTorus> tori) {
  if (!scene) throw std::invalid_argument("toroid::embree: the scene is null");
  ToriGeometry g(device, tori);
  g.attach(scene);
  return g;
}

}  // namespace toroid::embree
