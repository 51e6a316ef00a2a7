// SPDX-License-Identifier: Apache-2.0
// `material:` maps and material defines, and the table of shared materials.
#include <set>

#include "toroid/scene/load_state.h"
#include "toroid/scene/yaml_params.h"

namespace toroid {

namespace {

// The keys of a material: each with how it sets its field.
struct MaterialKey {
  const char* key;
  void (*read)(LoadState& state, const Param& p, Material& m, bool& casts_shadow);
};

constexpr MaterialKey kMaterialKeys[] = {
    {"color", [](LoadState&, const Param& p, Material& m, bool&) { m.color = p.color("color"); }},
    {"ambient", [](LoadState&, const Param& p, Material& m, bool&) { m.ambient = p.number(); }},
    {"diffuse", [](LoadState&, const Param& p, Material& m, bool&) { m.diffuse = p.number(); }},
    {"specular", [](LoadState&, const Param& p, Material& m, bool&) { m.specular = p.number(); }},
    {"shininess", [](LoadState&, const Param& p, Material& m, bool&) { m.shininess = p.number(); }},
    {"reflective", [](LoadState&, const Param& p, Material& m, bool&) { m.reflective = p.number(); }},
    {"transparency", [](LoadState&, const Param& p, Material& m, bool&) { m.transparency = p.number(); }},
    {"refractive-index",
     [](LoadState&, const Param& p, Material& m, bool&) { m.refractive_index = p.positive("refractive-index"); }},
    {"emissive",
     [](LoadState& s, const Param& p, Material& m, bool&) {
       m.emissive = p.color("emissive");
       if (m.emissive.r < 0 || m.emissive.g < 0 || m.emissive.b < 0)
         s.reader.fail(p.value(), "emissive must not be negative");
     }},
    {"pattern", [](LoadState& s, const Param& p, Material& m, bool&) { m.pattern = read_pattern(s, p.value()); }},
    {"shadow", [](LoadState&, const Param& p, Material&, bool& casts_shadow) { casts_shadow = p.boolean(); }},
};

// Sets the fields in the order the file gives them, so that the first bad
// value in the file is the one reported.
void apply_material_map(LoadState& state, const YAML::Node& node, Material& m, bool& casts_shadow) {
  ItemParams params(state.reader, state.reader.entries(node, "a material"), node);
  for (const MaterialKey& k : kMaterialKeys) params.get(k.key);
  params.report_unused("a material");
  for (const Entry& e : params.entries())
    for (const MaterialKey& k : kMaterialKeys)
      if (e.key == k.key) k.read(state, params.get(e.key), m, casts_shadow);
}

void apply_material_define(LoadState& state, const YAML::Node& name_node, Material& m, bool& casts_shadow,
                           std::set<std::string>& visiting) {
  const Define& d = lookup_define(state, name_node, "material");
  const std::string n = name_node.Scalar();
  if (!visiting.insert(n).second) state.reader.fail(name_node, "circular define: '" + n + "' refers to itself");
  check_nesting(state, visiting.size(), name_node, "material defines");
  if (!d.value.IsMap() || d.value["add"]) state.reader.fail(name_node, "'" + n + "' is not a material");
  if (d.extend) apply_material_define(state, *d.extend, m, casts_shadow, visiting);
  apply_material_map(state, d.value, m, casts_shadow);
  visiting.erase(n);
}

}  // namespace

void apply_material(LoadState& state, const YAML::Node& node, Material& m, bool& casts_shadow) {
  if (node.IsScalar()) {
    std::set<std::string> visiting;
    apply_material_define(state, node, m, casts_shadow, visiting);
  } else {
    apply_material_map(state, node, m, casts_shadow);
  }
}

SharedMaterial shared_material(LoadState& state, const Material& m) {
  auto it = state.materials.find(m);
  if (it == state.materials.end()) it = state.materials.insert(SharedMaterial(m)).first;
  return *it;
}

}  // namespace toroid
