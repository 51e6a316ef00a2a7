// SPDX-License-Identifier: Apache-2.0
// Tori in an Embree 3 scene: one RTC_GEOMETRY_TYPE_USER geometry with one
// primitive per torus, each torus with its own affine transform, intersected
// exactly by the toroid library (toroid/torus/intersect.h) in double.
//
//   std::vector<toroid::embree::EmbreeTorus> tori = ...;
//   toroid::embree::ToriGeometry geometry = toroid::embree::attach_tori(device, scene, tori);
//   rtcCommitScene(scene);
//   ... rtcIntersect1 / rtcOccluded1 (or the 4-, 8-, 16-wide and stream calls) ...
//   rtcReleaseScene(scene);  // before `geometry` goes out of scope
//
// A torus is, in its own object space, the one of toroid/torus/intersect.h:
// ring in the xy-plane, axis z, centred at the origin,
// (sqrt(x^2 + y^2) - major)^2 + z^2 = minor^2, spindle tori (minor > major)
// with their whole quartic surface. object_to_world places it in the scene.
//
// What a hit reports (RTCRayHit):
//   - tfar: the root's t, rounded to float; the roots taken are those whose
//     float lies strictly inside the ray's (tnear, tfar), nearest first. The
//     ray goes to object space in double without normalising its direction,
//     so t is the same in both spaces.
//   - Ng: the torus's outward normal in world space (the inverse transpose of
//     the linear part times the object-space normal, torus_normal), scaled to
//     unit length. Outward under any transform, mirroring ones included.
//   - u, v: the surface parameters in turns, each in [0, 1): u the angle
//     around the axis from +x towards +y (RenderMan's theta / 2 pi), v the
//     angle around the tube from the outer equator over +z (phi / 2 pi,
//     wrapped). The same as the toroid renderer's toroidal uv map.
//   - primID: the torus's index in the span given; geomID; instID from the
//     intersect context (Embree's instancing fills it).
// Each candidate root goes through the intersection (occlusion) filter, the
// geometry's and the context's, as Embree's protocol requires: a rejected
// root lets the next one be tried; a filter may change the hit record (it is
// kept) but not t. An occluded ray gets tfar = -inf.
//
// Rays are Embree's to check: it requires finite origins and directions
// (|component| <= 1.844e18) and tnear >= 0, and Debian's build asserts it.
// Beyond that, a ray with a zero direction hits nothing, so does one whose
// (tnear, tfar) holds no float, and so does one that is not finite in a
// torus's object space. The callbacks only read the data, so any number of
// threads may trace at once.
//
// The roots' accuracy is the library's (toroid/torus/intersect.h); the only
// limit left inside the radii accepted here is the one for rays that pass
// within 2^-20 torus sizes of the axis of a nearly horn torus.
#pragma once

#include <embree3/rtcore.h>

#include <cstddef>
#include <memory>
#include <span>

namespace toroid::embree {

struct EmbreeTorus {
  double major = 1.0;   // R: centre of the tube to the axis
  double minor = 0.25;  // r: the tube's radius
  // Object to world, affine, row-major: world = M[:, 0..2] * object + M[:, 3].
  double object_to_world[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
};

// The inputs accepted (anything else is rejected with std::invalid_argument,
// whose message names the torus's index and the problem):
//   - major and minor finite and > 0, with minor / major in [2^-30, 2]: the
//     range over which the library states the roots' accuracy
//     (kTorusAspectLimit, kTorusFattestSpindle);
//   - object_to_world finite, with a linear part whose condition number
//     (Frobenius norms, |A| |A^-1|) is at most kMaxCondition: a singular or
//     nearly singular transform is rejected;
//   - the world box within +-kMaxCoordinate on every axis, the range in
//     which Embree keeps a primitive's box (it drops any box beyond it).
inline constexpr double kMaxCondition = 1e12;
inline constexpr double kMaxCoordinate = 1.844e18;

// The exact world-space box of the torus, rounded outwards to float: on
// world axis i, with row i of the linear part (a, b, c) and translation d,
// d +- (major |(a, b)| + minor |(a, b, c)|) (the torus is a circle of
// radius major swept by a ball of radius minor). Throws std::invalid_argument
// for a torus that the rules above reject.
RTCBounds torus_world_bounds(const EmbreeTorus& torus);

// A user geometry holding copies of the tori, its callbacks set and the
// geometry committed; the object owns the copies and one reference to the
// geometry. Embree 3 has no hook to free a user geometry's data along with
// it, so this object is that owner: keep it alive as long as any scene that
// holds the geometry is built or traced (release the scene, or detach the
// geometry and commit the scene, first). Move-only.
//
// To add an intersection filter or a mask: call rtcSetGeometryIntersectFilterFunction
// (etc.) on geometry() and rtcCommitGeometry again, before committing the
// scene. Filters get, as geometryUserPtr, the adapter's own data (not
// settable): tell tori apart by primID, and carry your own data in the
// context (a struct that begins with RTCIntersectContext).
class ToriGeometry {
 public:
  // Throws std::invalid_argument for a null device, more tori than an
  // unsigned primID can count, or a torus rejected above (the first one);
  // std::runtime_error if Embree fails to create the geometry (its error
  // code in the message). Nothing is created then. An empty span gives a
  // geometry with no primitives.
  ToriGeometry(RTCDevice device, std::span<const EmbreeTorus> tori);
  ToriGeometry() noexcept;
  ToriGeometry(ToriGeometry&& other) noexcept;
  ToriGeometry& operator=(ToriGeometry&& other) noexcept;
  ToriGeometry(const ToriGeometry&) = delete;
  ToriGeometry& operator=(const ToriGeometry&) = delete;
  ~ToriGeometry();

  // The Embree geometry (nullptr for a default-constructed or moved-from
  // object). The object keeps its reference; retain it to keep it longer.
  RTCGeometry geometry() const noexcept;
  // rtcAttachGeometry; returns the geomID. Throws std::invalid_argument for
  // a null scene or an empty (moved-from) object, std::runtime_error when
  // Embree refuses (e.g. a scene of another device); nothing is attached then.
  unsigned attach(RTCScene scene);
  // The geomID of the last attach, RTC_INVALID_GEOMETRY_ID before.
  unsigned geom_id() const noexcept { return geom_id_; }
  // The tori as copied (primID i is tori()[i]).
  std::span<const EmbreeTorus> tori() const noexcept;

 private:
  struct Data;
  std::unique_ptr<Data> data_;
  RTCGeometry geometry_ = nullptr;
  unsigned geom_id_ = RTC_INVALID_GEOMETRY_ID;
};

// ToriGeometry(device, tori), then attach(scene): the returned object has
// the geomID. Throws as they do; nothing is attached then.
ToriGeometry attach_tori(RTCDevice device, RTCScene scene, std::span<const EmbreeTorus> tori);

}  // namespace toroid::embree
