// SPDX-License-Identifier: Apache-2.0
// read_shape(): what every shape item has in common; the kinds are in
// shape_builders.cpp.
#include <algorithm>
#include <stdexcept>

#include "toroid/scene/shape_builders.h"
#include "toroid/shapes/csg.h"
#include "toroid/shapes/group.h"

namespace toroid {

namespace {

bool is_builtin(const std::string& kind) { return find_builder<ShapeBuild>(shape_builders(), kind) != nullptr; }

// The shape's kind and its keys, following `add: NAME` through shape
// defines (the item's keys override the define's). The defines followed are
// added to `visiting`: the caller keeps them there while it builds the
// shape's children, so that a define inside itself is caught.
void collect_shape(LoadState& state, const YAML::Node& item, std::string& kind, YAML::Node& kind_node,
                   std::vector<Entry>& out, std::set<std::string>& visiting, bool operand) {
  const SceneReader& r = state.reader;
  auto es = r.entries(item, "a shape");
  auto find = [&](const char* key) {
    const auto it = std::find_if(es.begin(), es.end(), [&](const Entry& e) { return e.key == key; });
    return it == es.end() ? nullptr : &*it;
  };
  const Entry* k = find("add");
  if (!k && operand) k = find("type");
  if (!k) r.fail(item, operand ? "a shape needs 'add' (or 'type')" : "a shape needs 'add'");
  const std::string n = r.name(k->value, "a shape kind");
  const YAML::Node knode = k->value;
  std::vector<Entry> own;
  for (const Entry& e : es)
    if (e.key_node.Scalar() != k->key) own.push_back(e);
  if (is_builtin(n)) {
    kind = n;
    kind_node = knode;
    out = own;
    return;
  }
  auto it = state.defines.find(n);
  if (it == state.defines.end() || !it->second.value.IsMap() || !it->second.value["add"]) {
    std::vector<std::string> names = builder_names<ShapeBuild>(shape_builders());
    for (const auto& [dn, d] : state.defines)
      if (d.value.IsMap() && d.value["add"]) names.push_back(dn);
    r.fail(knode, "unknown shape '" + n + "'" + suggestion(n, names));
  }
  if (!visiting.insert(n).second) r.fail(knode, "circular define: shape '" + n + "' contains itself");
  check_nesting(state, visiting.size(), knode, "shape defines");
  collect_shape(state, it->second.value, kind, kind_node, out, visiting, false);
  for (const Entry& e : own) {
    auto same = std::find_if(out.begin(), out.end(), [&](const Entry& o) { return o.key == e.key; });
    if (same != out.end())
      *same = e;
    else
      out.push_back(e);
  }
}

void set_shadow_recursive(Shape& s, bool casts) {
  s.casts_shadow = casts;
  if (auto* g = dynamic_cast<Group*>(&s))
    for (const auto& c : g->children()) set_shadow_recursive(*c, casts);
  if (auto* c = dynamic_cast<Csg*>(&s)) {
    set_shadow_recursive(*c->left(), casts);
    set_shadow_recursive(*c->right(), casts);
  }
}

void apply_material_recursive(Shape& s, const SharedMaterial& m) {
  s.set_material(m);
  if (auto* g = dynamic_cast<Group*>(&s))
    for (const auto& c : g->children()) apply_material_recursive(*c, m);
}

}  // namespace

void ShapeItem::begin(const std::function<TorusRadii()>& material_torus) {
  begun = true;
  params.report_unused("a " + kind);
  material = inherited ? *inherited : Material{};
  if (const Param m = params.get("material")) {
    material = Material{};
    const std::optional<TorusRadii> outer = state.material_torus;
    state.material_torus = material_torus ? std::optional(material_torus()) : std::nullopt;
    apply_material(state, m.value(), material, casts_shadow);
    state.material_torus = outer;
    has_material = true;
    has_shadow = !casts_shadow;
  }
  if (const Param s = params.get("shadow")) {
    casts_shadow = s.boolean();
    has_shadow = true;
  }
}

std::shared_ptr<Shape> ShapeItem::child(const YAML::Node& node, bool operand) {
  return read_shape(state, node, has_material ? &material : inherited, visiting, depth + 1, operand);
}

std::shared_ptr<Shape> read_shape(LoadState& state, const YAML::Node& item, const Material* inherited,
                                  std::set<std::string>& visiting, std::size_t depth, bool operand) {
  check_nesting(state, depth, item, "groups and CSG");
  count(state, state.shapes_made, kMaxShapes, item, "shapes");
  std::string kind;
  YAML::Node kind_node;
  std::vector<Entry> es;
  const std::set<std::string> outer_defines = visiting;
  collect_shape(state, item, kind, kind_node, es, visiting, operand);
  ItemParams params(state.reader, std::move(es), kind_node);
  for (const char* key : {"transform", "material", "shadow"}) params.get(key);
  ShapeItem shape_item(state, params, kind, kind_node, visiting, depth, inherited);
  const std::shared_ptr<Shape> s = find_builder<ShapeBuild>(shape_builders(), kind)->build(shape_item);
  if (!shape_item.begun) throw std::logic_error("the builder of '" + kind + "' did not call begin()");
  const SharedMaterial shared = shared_material(state, shape_item.material);
  s->set_material(shared);
  if (const Param t = params.get("transform")) s->set_transform(transform_of(state, t.value()));
  // Groups and CSG pass their material to the primitives below them that
  // name none; their `shadow` applies to the whole subtree.
  if (shape_item.material_to_descendants && shape_item.has_material) apply_material_recursive(*s, shared);
  if (shape_item.has_shadow) set_shadow_recursive(*s, shape_item.casts_shadow);
  visiting = outer_defines;
  return s;
}

}  // namespace toroid
