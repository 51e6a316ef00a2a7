// SPDX-License-Identifier: Apache-2.0
// `add: light`: a point light (`at`) or, with `corner`, an area light (soft
// shadows bonus chapter).
#include "toroid/scene/item_builders.h"

namespace toroid {

namespace {

void area_light(LoadState& state, SceneParts& parts, const Color& intensity, const Param& corner, const Param& uvec,
                const Param& vvec, const Param& usteps, const Param& vsteps, const Param& jitter) {
  const SceneReader& r = state.reader;
  const Tuple c0 = corner.point3("corner");
  const Tuple u = r.vector3(uvec.need("an area light"), "uvec");
  const Tuple v = r.vector3(vvec.need("an area light"), "vvec");
  const YAML::Node& us = usteps.need("an area light");
  const YAML::Node& vs = vsteps.need("an area light");
  const int nu = r.integer(us), nv = r.integer(vs);
  if (nu <= 0 || nu > 64) r.fail(us, "usteps must be in 1..64");
  if (nv <= 0 || nv > 64) r.fail(vs, "vsteps must be in 1..64");
  const bool jittered = jitter && jitter.boolean();
  parts.world.area_lights.emplace_back(c0, u, nu, v, nv, intensity, jittered);
}

}  // namespace

void build_light(LoadState& state, SceneParts& parts, ItemParams& item) {
  item.get("add");
  const Param at = item.get("at"), intensity = item.get("intensity"), corner = item.get("corner");
  const Param uvec = item.get("uvec"), vvec = item.get("vvec"), usteps = item.get("usteps"),
              vsteps = item.get("vsteps"), jitter = item.get("jitter");
  item.report_unused("a light");
  const SceneReader& r = state.reader;
  const Color color = r.color(intensity.need("a light"), "intensity");
  if (corner) return area_light(state, parts, color, corner, uvec, vvec, usteps, vsteps, jitter);
  for (const Param* p : {&uvec, &vvec, &usteps, &vsteps, &jitter})
    if (*p) r.fail(p->key_node(), "'" + p->key() + "' needs 'corner' (area light)");
  parts.world.lights.push_back(PointLight{r.point3(at.need("a light"), "at"), color});
}

}  // namespace toroid
