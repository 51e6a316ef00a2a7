// SPDX-License-Identifier: Apache-2.0
// What the scene loader's parts share while one scene loads: the defines,
// the reader that reports errors, counters that limit the work, and caches.
// The parts are functions of a LoadState& (transforms, materials, patterns,
// shapes, the camera and lights); scene_loader.cpp runs them item by item.
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "toroid/core/canvas.h"
#include "toroid/core/material.h"
#include "toroid/core/shared_material.h"
#include "toroid/math/matrix.h"
#include "toroid/render/pattern.h"
#include "toroid/scene/scene_loader.h"
#include "toroid/scene/scene_reader.h"
#include "toroid/shapes/shape.h"

namespace toroid {

// Orders materials by value, every field and the pattern's address, for the
// table of shared materials; finds a block by a Material.
struct MaterialOrder {
  using is_transparent = void;
  static auto key(const Material& m) {
    return std::tie(m.color.r, m.color.g, m.color.b, m.ambient, m.diffuse, m.specular, m.shininess, m.reflective,
                    m.transparency, m.refractive_index, m.emissive.r, m.emissive.g, m.emissive.b, m.pattern);
  }
  static const Material& value(const Material& m) { return m; }
  static const Material& value(const SharedMaterial& m) { return *m; }
  bool operator()(const auto& a, const auto& b) const { return key(value(a)) < key(value(b)); }
};

// "FILE:LINE:COLUMN: warning: ..." and where it points (0-based, as
// YAML::Mark), for sorting.
struct SceneWarning {
  int line, column;
  std::string text;
};

struct TorusRadii {
  double major, minor;
};

struct LoadState {
  LoadState(std::string source_name, std::filesystem::path base, const SceneLoadOptions& opts)
      : source(std::move(source_name)), reader(source, defines), base_dir(std::move(base)), options(opts) {}
  LoadState(const LoadState&) = delete;  // the reader refers to defines
  LoadState& operator=(const LoadState&) = delete;

  std::string source;  // the file's name in messages
  Defines defines;
  SceneReader reader;
  std::filesystem::path base_dir;  // relative file names are relative to it
  SceneLoadOptions options;
  std::size_t shapes_made = 0, patterns_made = 0;  // see count()
  // Composed transform defines by name (cleared whenever a define is added).
  std::map<std::string, Matrix4> transform_defines;
  // The radii of the torus whose material is being read, for `mapping: torus`.
  std::optional<TorusRadii> material_torus;
  std::map<std::string, std::shared_ptr<const Canvas>> images;  // by canonical path
  // Equal materials share one block: a scene may give thousands of shapes
  // the same material (a define), and a shape holds only a pointer to it.
  std::set<SharedMaterial, MaterialOrder> materials;
  // Each once (see warn); scene_loader.cpp hands them to
  // SceneLoadOptions::on_warning in the order of the file.
  std::vector<SceneWarning> warnings;
};

// Limits that keep a mistaken (or hostile) scene from exhausting the stack,
// memory or time; docs/errors.md lists them. Defines and YAML aliases can
// repeat a group or a pattern inside itself, which multiplies the work.
constexpr int kMaxNesting = 64;              // groups and CSG inside each other; defines extending defines
constexpr std::size_t kMaxShapes = 100'000;  // shapes made from YAML (meshes belong in OBJ files: not counted)
constexpr std::size_t kMaxPatterns = 100'000;

// Counts one more of something limited; fails at `where` past the limit.
void count(const LoadState& state, std::size_t& counter, std::size_t limit, const YAML::Node& where,
           const std::string& what);
void check_nesting(const LoadState& state, std::size_t depth, const YAML::Node& where, const std::string& what);

// Records a warning at `where` unless the same one (text and position) is
// already recorded: a define's nodes are read again at each use, and the
// warning belongs where the value is written.
void warn(LoadState& state, const YAML::Node& where, const std::string& what);

// A file named in the scene: relative names are relative to the scene's directory.
std::filesystem::path resolve(const LoadState& state, const std::string& file);
[[noreturn]] void fail_not_found(const LoadState& state, const YAML::Node& where, const std::string& kind,
                                 const std::string& file, const std::filesystem::path& resolved);

// The define named by `name_node`; fails "undefined WHAT 'NAME'" otherwise.
const Define& lookup_define(const LoadState& state, const YAML::Node& name_node, const std::string& what);

// The shared block of a material equal to `m` (scene_materials.cpp).
SharedMaterial shared_material(LoadState& state, const Material& m);

// A transform list (first listed applies first), checked invertible
// (scene_transforms.cpp).
Matrix4 transform_of(LoadState& state, const YAML::Node& list);

// A `material:` value, a map or a define's name, applied onto `m`
// (scene_materials.cpp); `shadow:` in it sets `casts_shadow`.
void apply_material(LoadState& state, const YAML::Node& node, Material& m, bool& casts_shadow);

// A `pattern:` map; `depth` counts blended patterns inside each other
// (pattern_builders.cpp).
std::shared_ptr<Pattern> read_pattern(LoadState& state, const YAML::Node& node, std::size_t depth = 1);

}  // namespace toroid
