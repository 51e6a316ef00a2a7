// SPDX-License-Identifier: Apache-2.0
// `add: environment` (what rays that hit nothing see) and `add: integrator`
// (the book's renderer or the path tracer): at most one of each.
#include <string>

#include "toroid/scene/item_builders.h"

namespace toroid {

namespace {

// Fails at `add` when an item of this kind came before, at line `first`;
// else records this one's line.
void once(const LoadState& state, const Param& add, std::optional<int>& first, const std::string& what) {
  if (first)
    state.reader.fail(add.value(), "a second " + what + " (the first is at line " + std::to_string(*first) + ")");
  first = state.reader.file_mark(add.value()).line + 1;
}

Color non_negative_color(const SceneReader& r, const YAML::Node& node, const std::string& what) {
  const Color c = r.color(node, what);
  if (c.r < 0 || c.g < 0 || c.b < 0) r.fail(node, what + " must not be negative");
  return c;
}

}  // namespace

void build_environment(LoadState& state, SceneParts& parts, ItemParams& item) {
  const Param add = item.get("add"), color = item.get("color"), zenith = item.get("zenith");
  item.report_unused("an environment");
  once(state, add, parts.environment_line, "environment");
  const SceneReader& r = state.reader;
  Environment env;
  env.color = non_negative_color(r, color.need("an environment"), "color");
  if (zenith) env.zenith = non_negative_color(r, zenith.value(), "zenith");
  parts.world.environment = env;
}

void build_integrator(LoadState& state, SceneParts& parts, ItemParams& item) {
  const Param add = item.get("add"), type = item.get("type");
  item.report_unused("an integrator");
  once(state, add, parts.integrator_line, "integrator");
  const SceneReader& r = state.reader;
  const std::string t = r.name(type.need("an integrator"), "type");
  if (t == "whitted")
    parts.integrator = Integrator::whitted;
  else if (t == "path")
    parts.integrator = Integrator::path;
  else
    r.fail(type.value(),
           "unknown integrator type '" + t + "'" + suggestion(t, {"whitted", "path"}) + " (use whitted or path)");
}

}  // namespace toroid
