// SPDX-License-Identifier: Apache-2.0
// Shapes from scene items: read_shape() follows `add:` through shape
// defines and hands the item to the builder of its kind, found by name in
// shape_builders() (shape_builders.cpp).
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <span>
#include <string>

#include "toroid/scene/load_state.h"
#include "toroid/scene/yaml_params.h"

namespace toroid {

// One shape item as its builder sees it. The keys every shape has
// (`transform`, `material`, `shadow`) are asked for already; a builder asks
// for its own, then calls begin(), then reads their values and makes the
// shape. read_shape() applies the material and transform after.
struct ShapeItem {
  ShapeItem(LoadState& st, ItemParams& p, const std::string& k, const YAML::Node& kn, std::set<std::string>& v,
            std::size_t d, const Material* inh)
      : state(st), params(p), kind(k), kind_node(kn), visiting(v), depth(d), inherited(inh) {}

  LoadState& state;
  ItemParams& params;
  const std::string& kind;
  const YAML::Node& kind_node;      // the `add:` value ("needs" messages point here)
  std::set<std::string>& visiting;  // shape defines being followed (see collect_shape)
  std::size_t depth;                // 1 for a scene item, one more inside each group or CSG
  const Material* inherited;        // a group's or CSG's material, if any

  // Filled by begin().
  Material material;
  bool casts_shadow = true;
  bool has_material = false, has_shadow = false;
  bool begun = false;
  // An OBJ mesh's material goes to every triangle of it.
  bool material_to_descendants = false;

  // Reports unknown keys, then reads `material` and `shadow`. A torus gives
  // its radii, which `mapping: torus` in its material uses.
  void begin(const std::function<TorusRadii()>& material_torus = {});
  // A child (group) or operand (CSG) shape, taking this shape's material.
  std::shared_ptr<Shape> child(const YAML::Node& node, bool operand);
};

using ShapeBuild = std::shared_ptr<Shape> (*)(ShapeItem&);

// The built-in shape kinds, in the order "did you mean" prefers them.
std::span<const NamedBuilder<ShapeBuild>> shape_builders();

// The shape of a scene item, a group's child or (operand) a CSG's operand,
// which may give its kind as `type:`. `visiting` holds the shape defines
// being followed, to catch a define inside itself.
std::shared_ptr<Shape> read_shape(LoadState& state, const YAML::Node& item, const Material* inherited,
                                  std::set<std::string>& visiting, std::size_t depth, bool operand = false);

}  // namespace toroid
