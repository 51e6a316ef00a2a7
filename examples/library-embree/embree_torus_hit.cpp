// SPDX-License-Identifier: Apache-2.0
// Tori in an Embree 3 scene: one ray, its hit and a shadow ray. Exits 1 when
// an answer is not the one expected.
#include <embree3/rtcore.h>
#include <toroid/embree_tori.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

int main() {
  RTCDevice device = rtcNewDevice(nullptr);
  RTCScene scene = rtcNewScene(device);
  int failures = 0;
  {
    // Two tori: a ring of radii 1 and 0.25 at the origin, and the same ring
    // moved 10 along x and stood up (its axis along y).
    std::vector<toroid::embree::EmbreeTorus> tori(2);
    tori[1].object_to_world[0][3] = 10;
    tori[1].object_to_world[1][1] = 0, tori[1].object_to_world[1][2] = -1;
    tori[1].object_to_world[2][1] = 1, tori[1].object_to_world[2][2] = 0;
    const toroid::embree::ToriGeometry geometry = toroid::embree::attach_tori(device, scene, tori);
    rtcCommitScene(scene);

    // A ray along x from x = -2 meets the first ring's tube at t = 0.75.
    RTCRayHit rh{};
    rh.ray.org_x = -2, rh.ray.dir_x = 1;
    rh.ray.tnear = 0, rh.ray.tfar = std::numeric_limits<float>::infinity();
    rh.ray.mask = ~0u;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcIntersect1(scene, &context, &rh);
    std::printf("hit: geomID %u primID %u t %g Ng (%g, %g, %g)\n", rh.hit.geomID, rh.hit.primID, rh.ray.tfar,
                rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
    failures += rh.hit.geomID != geometry.geom_id() || rh.hit.primID != 0 || rh.ray.tfar != 0.75f;
    failures += !(std::abs(rh.hit.Ng_x + 1) < 1e-6f);

    // A shadow ray from above the second ring straight down through its tube.
    RTCRay shadow{};
    shadow.org_x = 11, shadow.org_z = 5, shadow.dir_z = -1;
    shadow.tnear = 0, shadow.tfar = 100;
    shadow.mask = ~0u;
    rtcInitIntersectContext(&context);
    rtcOccluded1(scene, &context, &shadow);
    std::printf("shadow ray blocked: %s\n", shadow.tfar < 0 ? "yes" : "no");
    failures += !(shadow.tfar < 0);
    rtcReleaseScene(scene);  // before the geometry's owner goes
  }
  rtcReleaseDevice(device);
  std::printf(failures == 0 ? "ok\n" : "FAILED: %d checks\n", failures);
  return failures == 0 ? 0 : 1;
}
