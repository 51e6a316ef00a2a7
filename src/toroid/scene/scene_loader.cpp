// SPDX-License-Identifier: Apache-2.0
// The scene loader's top level: the document item by item (or whole), each
// item a define, the camera, a light or a shape. The parts live beside it:
// scene_reader.h (values and positions), yaml_params.h (an item's keys),
// load_state.h (what they share), item_builders.h (camera, lights),
// shape_builders.h, pattern_builders.cpp, scene_materials.cpp and
// scene_transforms.cpp.
#include "toroid/scene/scene_loader.h"

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <tuple>

#include "toroid/math/transform.h"
#include "toroid/scene/item_builders.h"
#include "toroid/scene/shape_builders.h"
#include "toroid/scene/yaml_items.h"
#include "toroid/shapes/csg.h"
#include "toroid/shapes/group.h"

namespace toroid {

namespace {

constexpr std::size_t kGroupBvhThreshold = 8;

// The scene items that are not shapes, by their `add:`.
constexpr NamedBuilder<ItemBuild> kItems[] = {{"camera", build_camera},
                                              {"light", build_light},
                                              {"environment", build_environment},
                                              {"integrator", build_integrator}};

// `- define: NAME`, with `value` and `extend`.
void read_define(LoadState& state, ItemParams& item) {
  const SceneReader& r = state.reader;
  const Param define = item.get("define"), value = item.get("value"), extend = item.get("extend");
  item.report_unused("a define");
  const std::string n = define.name("a define");
  if (find_builder<ShapeBuild>(shape_builders(), n) || find_builder<ItemBuild>(kItems, n))
    r.fail(define.value(), "cannot redefine the built-in '" + n + "'");
  const YAML::Node& v = value.need("a define");
  // A whole document's item stays out: assigning defines[n] would rewrite it.
  Define def{define.value(), v, std::nullopt, r.item_by_item() ? item.where() : YAML::Node(), r.item_line()};
  if (extend) {
    extend.name("'extend'");
    def.extend = extend.value();
  }
  state.defines[n] = def;
  state.transform_defines.clear();
}

// Builds the scene from its items, which `next_item` gives in order (nullopt
// after the last); `list` is the top-level list's mark.
Scene build(LoadState& state, const std::function<std::optional<YAML::Node>()>& next_item, const YAML::Mark& list) {
  const SceneReader& r = state.reader;
  SceneParts parts;
  while (const std::optional<YAML::Node> next = next_item()) {
    const YAML::Node& node = *next;
    ItemParams item(r, r.entries(node, "a scene item"), node);
    if (item.has("define")) {
      read_define(state, item);
      continue;
    }
    if (!item.has("add"))
      r.fail(node, "a scene item needs 'add' or 'define'" +
                       (item.entries().empty() ? std::string() : suggestion(item.entries()[0].key, {"add", "define"})));
    const std::string kind = item.get("add").name("'add'");
    if (const auto* b = find_builder<ItemBuild>(kItems, kind)) {
      b->build(state, parts, item);
      continue;
    }
    std::set<std::string> visiting;
    auto s = read_shape(state, node, nullptr, visiting, 1);
    if (dynamic_cast<Group*>(s.get()) || dynamic_cast<Csg*>(s.get())) s->divide(kGroupBvhThreshold);
    parts.world.objects.push_back(std::move(s));
  }
  if (!parts.camera) r.fail(list, "the scene has no camera (add one with '- add: camera')");
  const CameraParams& c = *parts.camera;
  Camera camera(c.width, c.height, c.fov);
  camera.set_transform(view_transform(c.from, c.to, c.up));
  // The list grew by doubling; it holds 16 bytes per shape from here on.
  parts.world.objects.shrink_to_fit();
  index_objects(parts.world);
  return Scene{std::move(parts.world), camera, parts.integrator};
}

// The whole document's node tree.
Scene load_whole(LoadState& state, const YAML::Node& root) {
  if (!root || root.IsNull())
    state.reader.fail(YAML::Mark{}, "empty scene: expected a list of items ('- add: camera', ...)");
  if (!root.IsSequence())
    state.reader.fail(root, "a scene must be a list of items ('- add: ...' or '- define: ...'), got " + describe(root));
  auto it = root.begin();
  return build(
      state,
      [&]() -> std::optional<YAML::Node> {
        if (it == root.end()) return std::nullopt;
        return *it++;
      },
      root.Mark());
}

// Item by item (yaml_items.h); nullopt when an item does not load alone:
// then load the whole document, which gives the same scene or message.
std::optional<Scene> load_items(LoadState& state, const YamlItems& items) {
  struct NeedsWholeDocument {};
  std::size_t next = 0;
  try {
    return build(
        state,
        [&]() -> std::optional<YAML::Node> {
          if (next == items.items.size()) return std::nullopt;
          const YamlItemText& text = items.items[next++];
          std::optional<YAML::Node> item = load_item(text);
          if (!item) throw NeedsWholeDocument{};
          state.reader.start_item(*item, text.first_line);
          return item;
        },
        items.list);
  } catch (const NeedsWholeDocument&) {
    return std::nullopt;
  } catch (const YAML::Exception&) {
    return std::nullopt;  // the whole document's load reports it with its own mark
  }
}

std::string format_yaml_error(const std::string& source, const YAML::Exception& e) {
  std::ostringstream os;
  os << source << ':';
  if (e.mark.line >= 0)
    os << e.mark.line + 1 << ':' << e.mark.column + 1 << ": ";
  else
    os << ' ';
  // yaml-cpp's depth guard says "bad file"; say what it means.
  if (dynamic_cast<const YAML::DeepRecursion*>(&e))
    os << "YAML syntax error: lists or maps nested too deeply";
  else
    os << "YAML syntax error: " << e.msg;
  return os.str();
}

// Hands a finished load's warnings to options.on_warning, or prints them,
// in the order of the file (a group's transform is read after its children).
void report_warnings(LoadState& state) {
  std::stable_sort(state.warnings.begin(), state.warnings.end(), [](const SceneWarning& a, const SceneWarning& b) {
    return std::tie(a.line, a.column) < std::tie(b.line, b.column);
  });
  for (const SceneWarning& w : state.warnings)
    if (state.options.on_warning)
      state.options.on_warning(w.text);
    else
      std::cerr << w.text << '\n';
}

// A carriage return that does not end a line (old Mac line endings):
// yaml-cpp neither breaks the line there nor reads it as a blank, and may
// drop the rest of the file, so the scene is refused with its position.
void refuse_lone_carriage_returns(const std::string& text, const std::string& source) {
  std::size_t line_start = 0;
  int line = 1;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      line_start = i + 1;
    } else if (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n')) {
      throw SceneError(
          source + ':' + std::to_string(line) + ':' + std::to_string(i - line_start + 1) +
          ": a carriage return that does not end a line (save the file with Unix or Windows line endings)");
    }
  }
}

// The document's node tree; text after its list is refused with its
// position (YAML::Load would drop it).
YAML::Node load_document(const std::string& text, const std::string& source) {
  try {
    YAML::Node root = YAML::Load(text);
    if (const std::optional<YAML::Mark> m = second_document(text))
      throw SceneError(source + ':' + std::to_string(m->line + 1) + ':' + std::to_string(m->column + 1) +
                       ": the scene's list ends before this (a scene is one YAML document: a list of items, each "
                       "'- ' at the list's column)");
    return root;
  } catch (const YAML::Exception& e) {
    throw SceneError(format_yaml_error(source, e));
  }
}

}  // namespace

Scene load_scene_from_string(const std::string& text, const std::string& source, const std::filesystem::path& base_dir,
                             const SceneLoadOptions& options) {
  refuse_lone_carriage_returns(text, source);
  if (!options.whole_document) {
    if (const std::optional<YamlItems> items = split_items(text)) {
      // When the items do not load alone, or an item is wrong, the whole
      // document's load below decides: a syntax error anywhere in the file
      // comes before an item's mistake, as YAML::Load reports it first. It
      // finds the same warnings again: these are dropped.
      LoadState state(source, base_dir, options);
      std::optional<Scene> scene;
      try {
        scene = load_items(state, *items);
      } catch (const SceneError&) {
        // left to the whole document's load below
      }
      if (scene) {
        report_warnings(state);
        return std::move(*scene);
      }
    }
  }
  const YAML::Node root = load_document(text, source);
  LoadState state(source, base_dir, options);
  try {
    Scene scene = load_whole(state, root);
    report_warnings(state);
    return scene;
  } catch (const SceneError&) {
    report_warnings(state);
    throw;
  } catch (const YAML::Exception& e) {
    report_warnings(state);
    throw SceneError(format_yaml_error(source, e));
  }
}

Scene load_scene(const std::string& path, const SceneLoadOptions& options) {
  std::error_code ec;
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
    throw SceneError("cannot read scene '" + path + "': not a regular file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError("cannot read scene '" + path + "': " + std::strerror(errno));
  // Into one string of the file's size: a stringstream and its str() would
  // hold the text two or three times over at the peak.
  std::string text;
  if (const auto size = std::filesystem::file_size(path, ec); !ec) text.reserve(size);
  char chunk[1 << 16];
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) text.append(chunk, static_cast<std::size_t>(in.gcount()));
  if (in.bad()) throw SceneError("cannot read scene '" + path + "': read error");
  const auto dir = std::filesystem::path(path).parent_path();
  return load_scene_from_string(text, path, dir.empty() ? std::filesystem::path(".") : dir, options);
}

}  // namespace toroid
