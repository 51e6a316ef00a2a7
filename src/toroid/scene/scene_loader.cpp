#include "toroid/scene/scene_loader.h"

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <functional>
#include <numbers>
#include <optional>
#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <tuple>
#include <utility>
#include <vector>

#include "toroid/io/image_reader.h"
#include "toroid/math/transform.h"
#include "toroid/render/image_limits.h"
#include "toroid/render/pattern.h"
#include "toroid/core/shared_material.h"
#include "toroid/render/texture_map.h"
#include "toroid/scene/obj_file.h"
#include "toroid/scene/yaml_items.h"
#include "toroid/shapes/cone.h"
#include "toroid/shapes/csg.h"
#include "toroid/shapes/cube.h"
#include "toroid/shapes/cylinder.h"
#include "toroid/shapes/group.h"
#include "toroid/shapes/plane.h"
#include "toroid/shapes/sphere.h"
#include "toroid/shapes/torus.h"

namespace toroid {

int edit_distance(const std::string& a, const std::string& b) {
  std::vector<int> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = static_cast<int>(j);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = static_cast<int>(i);
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const int sub = prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, sub});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

namespace {

constexpr std::size_t kGroupBvhThreshold = 8;

// Limits that keep a mistaken (or hostile) scene from exhausting the stack,
// memory or time; docs/errors.md lists them. Defines and YAML aliases can
// repeat a group or a pattern inside itself, which multiplies the work.
constexpr int kMaxNesting = 64;  // groups and CSG inside each other; defines extending defines
constexpr std::size_t kMaxShapes = 100'000;  // shapes made from YAML (meshes belong in OBJ files: not counted)
constexpr std::size_t kMaxPatterns = 100'000;

// " (did you mean 'x'?)" for the nearest candidate, if near enough.
std::string suggestion(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  int best_d = 1 << 30;
  for (const auto& c : candidates) {
    const int d = edit_distance(word, c);
    if (d < best_d) best_d = d, best = c;
  }
  const int limit = std::max<int>(2, static_cast<int>(word.size()) / 3);
  if (best.empty() || best_d > limit) return {};
  return " (did you mean '" + best + "'?)";
}

// Orders materials by value, every field and the pattern's address, for the
// loader's table of shared materials; finds a block by a Material.
struct MaterialOrder {
  using is_transparent = void;
  static auto key(const Material& m) {
    return std::tie(m.color.r, m.color.g, m.color.b, m.ambient, m.diffuse, m.specular, m.shininess, m.reflective,
                    m.transparency, m.refractive_index, m.pattern);
  }
  static const Material& value(const Material& m) { return m; }
  static const Material& value(const SharedMaterial& m) { return *m; }
  bool operator()(const auto& a, const auto& b) const { return key(value(a)) < key(value(b)); }
};

// The key/value pairs of a YAML map, in order, keeping nodes for positions.
struct Entry {
  std::string key;
  YAML::Node key_node;
  YAML::Node value;
};

class Loader {
 public:
  Loader(std::string source, std::filesystem::path base_dir, const SceneLoadOptions& options)
      : source_(std::move(source)), base_dir_(std::move(base_dir)), options_(options) {}

  // The whole document's node tree.
  Scene load(const YAML::Node& root);
  // Item by item (yaml_items.h); nullopt when an item does not load alone:
  // then load the whole document, which gives the same scene or message.
  std::optional<Scene> load(const YamlItems& items);

 private:
  struct Define {
    YAML::Node name_node;
    YAML::Node value;
    std::optional<YAML::Node> extend;
    YAML::Node item;  // the scene item that defines it (see file_mark)
    int item_line = 0;
  };
  struct CameraParams {
    int width = 0, height = 0;
    double fov = 0;
    Tuple from, to, up;
  };

  [[noreturn]] void fail(const YAML::Mark& mark, const std::string& what) const {
    std::ostringstream os;
    os << source_ << ':';
    if (mark.line >= 0) os << mark.line + 1 << ':' << mark.column + 1 << ": ";
    else os << ' ';
    os << what;
    throw SceneError(os.str());
  }
  [[noreturn]] void fail(const YAML::Node& node, const std::string& what) const { fail(file_mark(node), what); }

  // Loaded item by item, a node's mark counts lines from its item's first
  // line: the current item's or, for a define's node, the define's. Only
  // errors need it, so the item is found by searching.
  YAML::Mark file_mark(const YAML::Node& node) const {
    YAML::Mark mark = node.Mark();
    if (!item_by_item_ || mark.is_null()) return mark;
    int line = item_line_;
    if (!(item_ && contains(*item_, node)))
      for (const auto& [_, d] : defines_)
        if (contains(d.item, node)) line = d.item_line;
    mark.line += line;
    return mark;
  }
  static bool contains(const YAML::Node& tree, const YAML::Node& node) {
    if (tree.is(node)) return true;
    if (tree.IsSequence())
      for (const YAML::Node& child : tree)
        if (contains(child, node)) return true;
    if (tree.IsMap())
      for (const auto& entry : tree)
        if (contains(entry.first, node) || contains(entry.second, node)) return true;
    return false;
  }
  // Builds the scene from its items, which `next_item` gives in order
  // (nullopt after the last); `list` is the top-level list's mark.
  Scene build(const std::function<std::optional<YAML::Node>()>& next_item, const YAML::Mark& list);

  static std::string describe(const YAML::Node& n) {
    switch (n.Type()) {
      case YAML::NodeType::Scalar: return "'" + n.Scalar() + "'";
      case YAML::NodeType::Sequence: return "a list";
      case YAML::NodeType::Map: return "a map";
      case YAML::NodeType::Null: return "nothing";
      default: return "nothing";
    }
  }

  std::vector<Entry> entries(const YAML::Node& map, const std::string& what) const {
    if (!map.IsMap()) fail(map, what + " must be a map, got " + describe(map));
    std::vector<Entry> out;
    std::set<std::string> seen;
    for (auto it = map.begin(); it != map.end(); ++it) {
      if (!it->first.IsScalar()) fail(it->first, "keys must be plain names");
      const std::string key = it->first.Scalar();
      if (!seen.insert(key).second) fail(it->first, "duplicate key '" + key + "'");
      out.push_back({key, it->first, it->second});
    }
    return out;
  }

  void check_keys(const std::vector<Entry>& es, const std::vector<std::string>& allowed, const std::string& what) const {
    for (const auto& e : es)
      if (std::find(allowed.begin(), allowed.end(), e.key) == allowed.end())
        fail(e.key_node, "unknown key '" + e.key + "' in " + what + suggestion(e.key, allowed));
  }

  static const Entry* find(const std::vector<Entry>& es, const std::string& key) {
    for (const auto& e : es)
      if (e.key == key) return &e;
    return nullptr;
  }

  const Entry& require(const std::vector<Entry>& es, const std::string& key, const YAML::Node& where,
                       const std::string& what) const {
    const Entry* e = find(es, key);
    if (!e) fail(where, what + " needs '" + key + "'");
    return *e;
  }

  double number(const YAML::Node& n) const {
    if (!n.IsScalar()) fail(n, "expected a number, got " + describe(n));
    double v = 0;
    if (!YAML::convert<double>::decode(n, v)) {
      const char* text = n.Scalar().c_str();
      char* end = nullptr;
      errno = 0;
      std::strtod(text, &end);
      if (errno == ERANGE && end != text && *end == '\0') fail(n, "number out of range: '" + n.Scalar() + "'");
      fail(n, "expected a number, got '" + n.Scalar() + "'");
    }
    if (!std::isfinite(v)) fail(n, "expected a finite number, got '" + n.Scalar() + "'");
    return v;
  }
  double positive(const YAML::Node& n, const std::string& what) const {
    const double v = number(n);
    if (v <= 0) fail(n, what + " must be > 0, got " + n.Scalar());
    return v;
  }
  int integer(const YAML::Node& n) const {
    if (!n.IsScalar()) fail(n, "expected an integer, got " + describe(n));
    long long v = 0;
    if (!YAML::convert<long long>::decode(n, v)) fail(n, "expected an integer, got '" + n.Scalar() + "'");
    if (v < -(1LL << 30) || v > (1LL << 30)) fail(n, "integer out of range: " + n.Scalar());
    return static_cast<int>(v);
  }
  bool boolean(const YAML::Node& n) const {
    bool b = false;
    if (!n.IsScalar() || !YAML::convert<bool>::decode(n, b)) fail(n, "expected true or false, got " + describe(n));
    return b;
  }
  std::string name(const YAML::Node& n, const std::string& what) const {
    if (!n.IsScalar() || n.Scalar().empty()) fail(n, what + " must be a name, got " + describe(n));
    return n.Scalar();
  }
  std::vector<double> numbers(const YAML::Node& n, std::size_t count, const std::string& what) const {
    if (!n.IsSequence()) fail(n, what + " must be a list of " + std::to_string(count) + " numbers, got " + describe(n));
    if (n.size() != count)
      fail(n, what + " must have " + std::to_string(count) + " numbers, got " + std::to_string(n.size()));
    std::vector<double> v;
    for (std::size_t i = 0; i < count; ++i) v.push_back(number(n[i]));
    return v;
  }
  Color color(const YAML::Node& n, const std::string& what) const {
    const auto v = numbers(n, 3, what);
    return Color{v[0], v[1], v[2]};
  }
  Tuple point3(const YAML::Node& n, const std::string& what) const {
    const auto v = numbers(n, 3, what);
    return point(v[0], v[1], v[2]);
  }
  Tuple vector3(const YAML::Node& n, const std::string& what) const {
    const auto v = numbers(n, 3, what);
    return vector(v[0], v[1], v[2]);
  }

  // Counts one more of something limited; fails at `where` past the limit.
  void count(std::size_t& counter, std::size_t limit, const YAML::Node& where, const std::string& what) const {
    if (++counter > limit)
      fail(where, "the scene makes more than " + std::to_string(limit) + " " + what +
                      " (defines or YAML aliases that repeat one another multiply them)");
  }
  void check_nesting(std::size_t depth, const YAML::Node& where, const std::string& what) const {
    if (depth > static_cast<std::size_t>(kMaxNesting))
      fail(where, what + " nested more than " + std::to_string(kMaxNesting) + " deep");
  }

  [[noreturn]] void fail_not_found(const YAML::Node& where, const std::string& kind, const std::string& file,
                                   const std::filesystem::path& resolved) const {
    fail(where, kind + " file '" + file + "' not found" +
                    (resolved.string() == file ? "" : " (looked for '" + resolved.string() + "')"));
  }

  // A file named in the scene: relative names are relative to the scene's directory.
  std::filesystem::path resolve(const std::string& file) const {
    const std::filesystem::path p(file);
    // Not lexically_normal(): "a/../b" differs from "b" when a is a symlink.
    return p.is_absolute() || base_dir_ == "." ? p : base_dir_ / p;
  }

  const Define& lookup_define(const YAML::Node& name_node, const std::string& what) const {
    const std::string n = name(name_node, what);
    auto it = defines_.find(n);
    if (it == defines_.end()) {
      std::vector<std::string> names;
      for (const auto& [k, _] : defines_) names.push_back(k);
      fail(name_node, "undefined " + what + " '" + n + "'" + suggestion(n, names));
    }
    return it->second;
  }

  // Transforms ---------------------------------------------------------------
  void check_invertible(const Matrix4& m, const YAML::Node& where) const {
    const double det = determinant(m);
    if (!std::isfinite(det) || det == 0.0) fail(where, "singular transform (determinant 0): it cannot be inverted");
  }

  static const std::vector<std::string>& transform_kinds() {
    static const std::vector<std::string> k{"translate", "scale", "rotate-x", "rotate-y", "rotate-z", "shear"};
    return k;
  }
  static bool is_transform_kind(const std::string& k) {
    return std::find(transform_kinds().begin(), transform_kinds().end(), k) != transform_kinds().end();
  }

  // Composes a transform list onto `m` (first listed applies first).
  void apply_transform_list(const YAML::Node& list, Matrix4& m, std::set<std::string>& visiting) const {
    if (!list.IsSequence()) fail(list, "transform must be a list, got " + describe(list));
    for (const YAML::Node& op : list) {
      if (op.IsScalar()) {
        if (is_transform_kind(op.Scalar()) && !defines_.count(op.Scalar()))
          fail(list, "each transform operation is a list of its own: [[" + op.Scalar() + ", ...], ...]");
        apply_transform_define(op, m, visiting);
        continue;
      }
      if (!op.IsSequence() || op.size() == 0 || !op[0].IsScalar())
        fail(op, "a transform must be [operation, numbers...] or the name of a defined transform");
      const std::string kind = op[0].Scalar();
      auto args = [&](std::size_t n) {
        if (op.size() != n + 1)
          fail(op, "'" + kind + "' takes " + std::to_string(n) + " number" + (n == 1 ? "" : "s") + ", got " +
                       std::to_string(op.size() - 1));
        std::vector<double> v;
        for (std::size_t i = 1; i <= n; ++i) v.push_back(number(op[i]));
        return v;
      };
      Matrix4 t;
      if (kind == "translate") {
        const auto v = args(3);
        t = translation(v[0], v[1], v[2]);
      } else if (kind == "scale") {
        const auto v = args(3);
        t = scaling(v[0], v[1], v[2]);
      } else if (kind == "rotate-x") {
        t = rotation_x(args(1)[0]);
      } else if (kind == "rotate-y") {
        t = rotation_y(args(1)[0]);
      } else if (kind == "rotate-z") {
        t = rotation_z(args(1)[0]);
      } else if (kind == "shear") {
        const auto v = args(6);
        t = shearing(v[0], v[1], v[2], v[3], v[4], v[5]);
      } else {
        fail(op[0], "unknown transform '" + kind + "'" + suggestion(kind, transform_kinds()));
      }
      m = t * m;
    }
  }

  // Each transform define is composed once and remembered: defines that
  // list another twice would otherwise double the work at every level.
  void apply_transform_define(const YAML::Node& name_node, Matrix4& m, std::set<std::string>& visiting) const {
    const Define& d = lookup_define(name_node, "transform");
    const std::string n = name_node.Scalar();
    auto known = transform_defines_.find(n);
    if (known == transform_defines_.end()) {
      if (!visiting.insert(n).second) fail(name_node, "circular define: '" + n + "' refers to itself");
      check_nesting(visiting.size(), name_node, "transform defines");
      if (!d.value.IsSequence()) fail(name_node, "'" + n + "' is not a transform (its value is not a list)");
      Matrix4 composed = Matrix4::identity();
      if (d.extend) apply_transform_define(*d.extend, composed, visiting);
      apply_transform_list(d.value, composed, visiting);
      visiting.erase(n);
      known = transform_defines_.emplace(n, composed).first;
    }
    m = known->second * m;
  }

  Matrix4 transform_of(const YAML::Node& list) const {
    Matrix4 m = Matrix4::identity();
    std::set<std::string> visiting;
    apply_transform_list(list, m, visiting);
    check_invertible(m, list);
    return m;
  }

  // Patterns and materials ---------------------------------------------------
  // Two colours under `colors` (stripes, checkers, uv checkers, ...).
  std::pair<Color, Color> two_colors(const std::vector<Entry>& es, const YAML::Node& node, const std::string& what) const {
    const Entry& cs = require(es, "colors", node, what);
    if (!cs.value.IsSequence() || cs.value.size() != 2)
      fail(cs.value, "'colors' must be a list of 2 colors [r, g, b], got " +
                         (cs.value.IsSequence() ? std::to_string(cs.value.size()) + " entries" : describe(cs.value)));
    return {color(cs.value[0], "a color"), color(cs.value[1], "a color")};
  }

  // Texture mapping (RTC bonus chapter) ---------------------------------------
  // An image file, read once however many patterns name it.
  std::shared_ptr<const Canvas> image(const YAML::Node& file_node) const {
    const std::string file = name(file_node, "file");
    const std::filesystem::path p = resolve(file);
    std::error_code ec;  // when the file cannot even be looked at, read_image says why
    if (!std::filesystem::exists(p, ec) && !ec)
      fail_not_found(file_node, "image", file, p);
    const std::filesystem::path canonical = std::filesystem::canonical(p, ec);
    const std::string key = ec ? p.string() : canonical.string();
    if (auto it = images_.find(key); it != images_.end()) return it->second;
    try {
      return images_[key] = std::make_shared<const Canvas>(read_image(p.string()));
    } catch (const ImageReadError& e) {
      fail(file_node, "cannot load image '" + file + "': " + e.what());
    }
  }

  std::shared_ptr<const UvPattern> uv_pattern(const YAML::Node& node) const {
    const auto es = entries(node, "a uv pattern");
    const Entry& type = require(es, "type", node, "a uv pattern");
    const std::string kind = name(type.value, "uv pattern type");
    if (kind == "checkers") {
      check_keys(es, {"type", "width", "height", "colors"}, "a checkers uv pattern");
      const double w = positive(require(es, "width", node, "a checkers uv pattern").value, "'width'");
      const double h = positive(require(es, "height", node, "a checkers uv pattern").value, "'height'");
      const auto [a, b] = two_colors(es, node, "a checkers uv pattern");
      return std::make_shared<UvCheckers>(w, h, a, b);
    }
    if (kind == "align_check") {
      check_keys(es, {"type", "colors"}, "an align_check uv pattern");
      const Entry& cs = require(es, "colors", node, "an align_check uv pattern");
      const auto ces = entries(cs.value, "align_check 'colors'");
      check_keys(ces, {"main", "ul", "ur", "bl", "br"}, "align_check 'colors'");
      auto corner = [&](const char* k) { return color(require(ces, k, cs.value, "align_check 'colors'").value, k); };
      return std::make_shared<UvAlignCheck>(corner("main"), corner("ul"), corner("ur"), corner("bl"), corner("br"));
    }
    if (kind == "image") {
      check_keys(es, {"type", "file"}, "an image uv pattern");
      return std::make_shared<UvImage>(image(require(es, "file", node, "an image uv pattern").value));
    }
    fail(type.value, "unknown uv pattern type '" + kind + "'" + suggestion(kind, {"checkers", "align_check", "image"}) +
                         " (use checkers, align_check or image)");
  }

  // `type: map`: a mapping and a uv pattern, or (mapping: cube) a uv pattern
  // per face. `mapping: torus` needs the torus's radii: `major`/`minor` when
  // given, else those of the torus whose material this is.
  std::shared_ptr<Pattern> map_pattern(const YAML::Node& node, const std::vector<Entry>& es) const {
    const Entry& m = require(es, "mapping", node, "a map pattern");
    const std::string mapping = name(m.value, "mapping");
    const std::vector<std::string> mappings{"spherical", "planar", "cylindrical", "cube", "torus"};
    if (std::find(mappings.begin(), mappings.end(), mapping) == mappings.end())
      fail(m.value, "unknown mapping '" + mapping + "'" + suggestion(mapping, mappings) +
                        " (use spherical, planar, cylindrical, cube or torus)");
    if (mapping == "cube") {
      check_keys(es, {"type", "mapping", "left", "right", "front", "back", "up", "down", "transform"},
                 "a cube map pattern");
      const std::vector<std::string> faces{"left", "right", "front", "back", "up", "down"};
      for (const std::string& f : faces) require(es, f, node, "a cube map pattern");
      // Read in file order, so that the first bad face in the file is reported.
      std::map<std::string, std::shared_ptr<const UvPattern>> uv;
      for (const Entry& e : es)
        if (std::find(faces.begin(), faces.end(), e.key) != faces.end()) uv[e.key] = uv_pattern(e.value);
      return std::make_shared<CubeMapPattern>(uv["left"], uv["front"], uv["right"], uv["back"], uv["up"], uv["down"]);
    }
    std::vector<std::string> keys{"type", "mapping", "uv_pattern", "transform"};
    if (mapping == "torus") keys.insert(keys.end(), {"major", "minor"});
    check_keys(es, keys, "a '" + mapping + "' map pattern");
    auto uv = uv_pattern(require(es, "uv_pattern", node, "a map pattern").value);
    UvMapping f;
    if (mapping == "spherical") f = spherical_map;
    else if (mapping == "planar") f = planar_map;
    else if (mapping == "cylindrical") f = cylindrical_map;
    else {
      const Entry* major = find(es, "major");
      const Entry* minor = find(es, "minor");
      if ((!major || !minor) && !material_torus_)
        fail(m.value, "mapping 'torus' needs the radii of the torus: use it in the material of a torus, or give "
                      "'major' and 'minor'");
      const double R = major ? positive(major->value, "'major'") : material_torus_->major;
      const double r = minor ? positive(minor->value, "'minor'") : material_torus_->minor;
      f = [R, r](const Tuple& p) { return toroidal_map(R, r, p); };
    }
    return std::make_shared<TextureMapPattern>(std::move(uv), std::move(f));
  }

  std::shared_ptr<Pattern> pattern(const YAML::Node& node, std::size_t depth = 1) const {
    check_nesting(depth, node, "blended patterns");
    count(patterns_made_, kMaxPatterns, node, "patterns");
    const auto es = entries(node, "a pattern");
    const Entry& type = require(es, "type", node, "a pattern");
    const std::string kind = name(type.value, "pattern type");
    std::shared_ptr<Pattern> p;
    if (kind == "map") {
      p = map_pattern(node, es);
    } else if (kind == "blended") {
      check_keys(es, {"type", "patterns", "transform"}, "a blended pattern");
      const Entry& ps = require(es, "patterns", node, "a blended pattern");
      if (!ps.value.IsSequence() || ps.value.size() != 2) fail(ps.value, "'patterns' must be a list of 2 patterns");
      p = std::make_shared<BlendedPattern>(pattern(ps.value[0], depth + 1), pattern(ps.value[1], depth + 1));
    } else {
      const std::vector<std::string> kinds{"stripes", "gradient", "rings", "checkers", "blended", "map"};
      if (std::find(kinds.begin(), kinds.end(), kind) == kinds.end())
        fail(type.value, "unknown pattern type '" + kind + "'" + suggestion(kind, kinds));
      check_keys(es, {"type", "colors", "transform"}, "a pattern");
      const auto [a, b] = two_colors(es, node, "a '" + kind + "' pattern");
      if (kind == "stripes") p = std::make_shared<StripePattern>(a, b);
      else if (kind == "gradient") p = std::make_shared<GradientPattern>(a, b);
      else if (kind == "rings") p = std::make_shared<RingPattern>(a, b);
      else p = std::make_shared<CheckersPattern>(a, b);
    }
    if (const Entry* t = find(es, "transform")) p->set_transform(transform_of(t->value));
    return p;
  }

  void apply_material_map(const YAML::Node& node, Material& m, bool& casts_shadow) const {
    const auto es = entries(node, "a material");
    check_keys(es,
               {"color", "ambient", "diffuse", "specular", "shininess", "reflective", "transparency",
                "refractive-index", "pattern", "shadow"},
               "a material");
    for (const Entry& e : es) {
      if (e.key == "color") m.color = color(e.value, "color");
      else if (e.key == "ambient") m.ambient = number(e.value);
      else if (e.key == "diffuse") m.diffuse = number(e.value);
      else if (e.key == "specular") m.specular = number(e.value);
      else if (e.key == "shininess") m.shininess = number(e.value);
      else if (e.key == "reflective") m.reflective = number(e.value);
      else if (e.key == "transparency") m.transparency = number(e.value);
      else if (e.key == "refractive-index") m.refractive_index = positive(e.value, "refractive-index");
      else if (e.key == "pattern") m.pattern = pattern(e.value);
      else if (e.key == "shadow") casts_shadow = boolean(e.value);
    }
  }

  void apply_material_define(const YAML::Node& name_node, Material& m, bool& casts_shadow,
                             std::set<std::string>& visiting) const {
    const Define& d = lookup_define(name_node, "material");
    const std::string n = name_node.Scalar();
    if (!visiting.insert(n).second) fail(name_node, "circular define: '" + n + "' refers to itself");
    check_nesting(visiting.size(), name_node, "material defines");
    if (!d.value.IsMap() || d.value["add"]) fail(name_node, "'" + n + "' is not a material");
    if (d.extend) apply_material_define(*d.extend, m, casts_shadow, visiting);
    apply_material_map(d.value, m, casts_shadow);
    visiting.erase(n);
  }

  void apply_material(const YAML::Node& node, Material& m, bool& casts_shadow) const {
    if (node.IsScalar()) {
      std::set<std::string> visiting;
      apply_material_define(node, m, casts_shadow, visiting);
    } else {
      apply_material_map(node, m, casts_shadow);
    }
  }

  // Shapes -------------------------------------------------------------------
  static const std::vector<std::string>& builtin_kinds() {
    static const std::vector<std::string> k{"sphere", "plane", "cube", "cylinder", "cone",
                                            "group",  "csg",   "obj",  "torus"};
    return k;
  }
  static bool is_builtin(const std::string& k) {
    const auto& b = builtin_kinds();
    return std::find(b.begin(), b.end(), k) != b.end();
  }

  // The shape's kind and its keys, following `add: NAME` through shape
  // defines (the item's keys override the define's). The defines followed
  // are added to `visiting`: the caller keeps them there while it builds the
  // shape's children, so that a define inside itself is caught.
  void collect_shape(const YAML::Node& item, std::string& kind, YAML::Node& kind_node, std::vector<Entry>& out,
                     std::set<std::string>& visiting, bool operand) const {
    auto es = entries(item, "a shape");
    const Entry* k = find(es, "add");
    if (!k && operand) k = find(es, "type");
    if (!k) fail(item, operand ? "a shape needs 'add' (or 'type')" : "a shape needs 'add'");
    const std::string n = name(k->value, "a shape kind");
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
    auto it = defines_.find(n);
    if (it == defines_.end() || !it->second.value.IsMap() || !it->second.value["add"]) {
      std::vector<std::string> names = builtin_kinds();
      for (const auto& [dn, d] : defines_)
        if (d.value.IsMap() && d.value["add"]) names.push_back(dn);
      fail(knode, "unknown shape '" + n + "'" + suggestion(n, names));
    }
    if (!visiting.insert(n).second) fail(knode, "circular define: shape '" + n + "' contains itself");
    check_nesting(visiting.size(), knode, "shape defines");
    collect_shape(it->second.value, kind, kind_node, out, visiting, false);
    for (const Entry& e : own) {
      auto same = std::find_if(out.begin(), out.end(), [&](const Entry& o) { return o.key == e.key; });
      if (same != out.end()) *same = e;
      else out.push_back(e);
    }
  }

  // RenderMan's partial torus: `theta-max` in (0, 2 pi], `phi-min` <
  // `phi-max` within [-2 pi, 2 pi] and at most 2 pi apart (radians). Values
  // within 1e-4 beyond a limit (6.2832 for 2 pi) are taken as the limit.
  TorusSweep torus_sweep(const std::vector<Entry>& es) const {
    constexpr double kTwoPi = TorusSweep::kTwoPi, kSlack = 1e-4;
    TorusSweep sw;
    if (const Entry* e = find(es, "theta-max")) {
      sw.theta_max = number(e->value);
      if (!(sw.theta_max > 0 && sw.theta_max <= kTwoPi + kSlack))
        fail(e->value, "torus 'theta-max' must be in (0, 2 pi] radians, got " + e->value.Scalar());
      sw.theta_max = std::min(sw.theta_max, kTwoPi);
    }
    const Entry* lo = find(es, "phi-min");
    const Entry* hi = find(es, "phi-max");
    for (const Entry* e : {lo, hi}) {
      if (!e) continue;
      const double v = number(e->value);
      if (std::abs(v) > kTwoPi + kSlack)
        fail(e->value, "torus '" + e->key + "' must be in [-2 pi, 2 pi] radians, got " + e->value.Scalar());
      (e == lo ? sw.phi_min : sw.phi_max) = std::clamp(v, -kTwoPi, kTwoPi);
    }
    const YAML::Node where = hi ? hi->value : lo ? lo->value : YAML::Node();
    if (!(sw.phi_min < sw.phi_max))
      fail(where, "torus 'phi-max' must be greater than 'phi-min' (" + std::to_string(sw.phi_max) +
                      " <= " + std::to_string(sw.phi_min) + ")");
    if (sw.phi_max - sw.phi_min > kTwoPi + kSlack)
      fail(where, "torus 'phi-max' - 'phi-min' must be at most 2 pi radians");
    sw.phi_max = std::min(sw.phi_max, sw.phi_min + kTwoPi);
    return sw;
  }

  static void set_shadow_recursive(Shape& s, bool casts) {
    s.casts_shadow = casts;
    if (auto* g = dynamic_cast<Group*>(&s))
      for (const auto& c : g->children()) set_shadow_recursive(*c, casts);
    if (auto* c = dynamic_cast<Csg*>(&s)) {
      set_shadow_recursive(*c->left(), casts);
      set_shadow_recursive(*c->right(), casts);
    }
  }

  struct Inherited {
    const Material* material = nullptr;
  };

  struct TorusRadii {
    double major, minor;
  };
  TorusRadii torus_radii(const std::vector<Entry>& es) const {
    const Torus defaults;
    const Entry* major = find(es, "major");
    const Entry* minor = find(es, "minor");
    return {major ? positive(major->value, "torus 'major'") : defaults.major(),
            minor ? positive(minor->value, "torus 'minor'") : defaults.minor()};
  }
  // While a torus's own material is read, a torus mapping in it takes the
  // torus's radii (map_pattern).
  class MaterialTorus {
   public:
    MaterialTorus(const Loader& loader, std::optional<TorusRadii> radii)
        : loader_(loader), saved_(std::exchange(loader.material_torus_, radii)) {}
    ~MaterialTorus() { loader_.material_torus_ = saved_; }
    MaterialTorus(const MaterialTorus&) = delete;
    MaterialTorus& operator=(const MaterialTorus&) = delete;

   private:
    const Loader& loader_;
    std::optional<TorusRadii> saved_;
  };


  // `depth`: 1 for a scene item, one more inside each group or CSG.
  std::shared_ptr<Shape> shape(const YAML::Node& item, const Inherited& inh, std::set<std::string>& visiting,
                               std::size_t depth, bool operand = false) const {
    check_nesting(depth, item, "groups and CSG");
    count(shapes_made_, kMaxShapes, item, "shapes");
    std::string kind;
    YAML::Node kind_node;
    std::vector<Entry> es;
    const std::set<std::string> outer_defines = visiting;
    collect_shape(item, kind, kind_node, es, visiting, operand);
    std::vector<std::string> allowed{"transform", "material", "shadow"};
    if (kind == "cylinder" || kind == "cone") allowed.insert(allowed.end(), {"min", "max", "closed"});
    else if (kind == "group") allowed.push_back("children");
    else if (kind == "csg") allowed.insert(allowed.end(), {"operation", "left", "right"});
    else if (kind == "obj") allowed.push_back("file");
    else if (kind == "torus")
      allowed.insert(allowed.end(), {"major", "minor", "solver", "theta-max", "phi-min", "phi-max", "spindle"});
    check_keys(es, allowed, "a " + kind);

    Material material = inh.material ? *inh.material : Material{};
    bool casts_shadow = true;
    bool has_material = false, has_shadow = false;
    if (const Entry* m = find(es, "material")) {
      material = Material{};
      const MaterialTorus on_torus(*this, kind == "torus" ? std::optional(torus_radii(es)) : std::nullopt);
      apply_material(m->value, material, casts_shadow);
      has_material = true;
      has_shadow = !casts_shadow;
    }
    if (const Entry* s = find(es, "shadow")) {
      casts_shadow = boolean(s->value);
      has_shadow = true;
    }
    Inherited child_inh{has_material ? &material : inh.material};

    std::shared_ptr<Shape> s;
    if (kind == "sphere") s = std::make_shared<Sphere>();
    else if (kind == "plane") s = std::make_shared<Plane>();
    else if (kind == "cube") s = std::make_shared<Cube>();
    else if (kind == "cylinder" || kind == "cone") {
      double lo = -BoundingBox::kInf, hi = BoundingBox::kInf;
      bool closed = false;
      const Entry* mn = find(es, "min");
      const Entry* mx = find(es, "max");
      if (mn) lo = number(mn->value);
      if (mx) hi = number(mx->value);
      if (const Entry* c = find(es, "closed")) closed = boolean(c->value);
      if (mn && mx && !(lo < hi)) fail(mx->value, "'max' must be greater than 'min'");
      if (kind == "cylinder") {
        auto c = std::make_shared<Cylinder>();
        c->minimum = lo, c->maximum = hi, c->closed = closed;
        s = c;
      } else {
        auto c = std::make_shared<Cone>();
        c->minimum = lo, c->maximum = hi, c->closed = closed;
        s = c;
      }
    } else if (kind == "torus") {
      const TorusRadii radii = torus_radii(es);
      auto t = std::make_shared<Torus>(radii.major, radii.minor);
      if (const Entry* e = find(es, "solver")) {
        const auto sv = solver_from_name(name(e->value, "solver"));
        if (!sv)
          fail(e->value, "unknown solver '" + e->value.Scalar() + "' (use default, ferrari or tianheng)" +
                             suggestion(e->value.Scalar(), {"default", "ferrari", "tianheng"}));
        t->set_solver(*sv);
      }
      if (options_.solver) t->set_solver(*options_.solver);
      t->set_sweep(torus_sweep(es));
      if (const Entry* e = find(es, "spindle")) {
        const std::string v = name(e->value, "spindle");
        if (v != "whole" && v != "outer")
          fail(e->value, "unknown spindle surface '" + v + "' (use whole or outer)" + suggestion(v, {"whole", "outer"}));
        t->set_spindle(v == "outer" ? SpindleSurface::Outer : SpindleSurface::Whole);
      }
      s = t;
    } else if (kind == "group") {
      auto g = std::make_shared<Group>();
      if (const Entry* c = find(es, "children")) {
        if (!c->value.IsSequence()) fail(c->value, "'children' must be a list of shapes, got " + describe(c->value));
        for (const YAML::Node& child : c->value) g->add_child(shape(child, child_inh, visiting, depth + 1));
      }
      s = g;
    } else if (kind == "csg") {
      const Entry& op = require(es, "operation", kind_node, "a csg");
      const std::string o = name(op.value, "operation");
      CsgOp cop;
      if (o == "union") cop = CsgOp::Union;
      else if (o == "intersection") cop = CsgOp::Intersection;
      else if (o == "difference") cop = CsgOp::Difference;
      else
        fail(op.value, "unknown csg operation '" + o + "'" + suggestion(o, {"union", "intersection", "difference"}) +
                           " (use union, intersection or difference)");
      const Entry* l = find(es, "left");
      const Entry* r = find(es, "right");
      if (!l || !r) fail(kind_node, std::string("a csg needs both 'left' and 'right' operands (missing '") +
                                        (!l ? "left" : "right") + "')");
      auto left = shape(l->value, child_inh, visiting, depth + 1, true);
      auto right = shape(r->value, child_inh, visiting, depth + 1, true);
      s = std::make_shared<Csg>(cop, std::move(left), std::move(right));
    } else if (kind == "obj") {
      const Entry& f = require(es, "file", kind_node, "an obj");
      const std::string file = name(f.value, "file");
      const std::filesystem::path p = resolve(file);
      if (!std::filesystem::exists(p))
        fail_not_found(f.value, "OBJ", file, p);
      try {
        s = load_obj(p);
      } catch (const std::exception& e) {
        fail(f.value, "cannot load OBJ file '" + file + "': " + e.what());
      }
    }
    const SharedMaterial shared = shared_material(material);
    s->set_material(shared);
    if (const Entry* t = find(es, "transform")) s->set_transform(transform_of(t->value));
    // Groups and CSG pass their material to the primitives below them that
    // name none; their `shadow` applies to the whole subtree.
    if (kind == "obj" && has_material) apply_material_recursive(*s, shared);
    if (has_shadow) set_shadow_recursive(*s, casts_shadow);
    visiting = outer_defines;
    return s;
  }

  static void apply_material_recursive(Shape& s, const SharedMaterial& m) {
    s.set_material(m);
    if (auto* g = dynamic_cast<Group*>(&s))
      for (const auto& c : g->children()) apply_material_recursive(*c, m);
  }

  // Equal materials share one block: a scene may give thousands of shapes
  // the same material (a define), and a shape holds only a pointer to it.
  SharedMaterial shared_material(const Material& m) const {
    auto it = materials_.find(m);
    if (it == materials_.end()) it = materials_.insert(SharedMaterial(m)).first;
    return *it;
  }

  std::string source_;
  bool item_by_item_ = false;
  std::optional<YAML::Node> item_;  // item by item: the current item and its first line
  int item_line_ = 0;
  std::filesystem::path base_dir_;
  SceneLoadOptions options_;
  std::map<std::string, Define> defines_;
  mutable std::size_t shapes_made_ = 0, patterns_made_ = 0;
  // Composed transform defines by name (cleared whenever a define is added).
  mutable std::map<std::string, Matrix4> transform_defines_;
  mutable std::optional<TorusRadii> material_torus_;                      // see MaterialTorus
  mutable std::map<std::string, std::shared_ptr<const Canvas>> images_;  // by canonical path
  mutable std::set<SharedMaterial, MaterialOrder> materials_;
};

Scene Loader::load(const YAML::Node& root) {
  if (!root || root.IsNull()) fail(YAML::Mark{}, "empty scene: expected a list of items ('- add: camera', ...)");
  if (!root.IsSequence()) fail(root, "a scene must be a list of items ('- add: ...' or '- define: ...'), got " + describe(root));
  auto it = root.begin();
  return build([&]() -> std::optional<YAML::Node> {
    if (it == root.end()) return std::nullopt;
    return *it++;
  }, root.Mark());
}

std::optional<Scene> Loader::load(const YamlItems& items) {
  struct NeedsWholeDocument {};
  item_by_item_ = true;
  std::size_t next = 0;
  try {
    return build([&]() -> std::optional<YAML::Node> {
      if (next == items.items.size()) return std::nullopt;
      const YamlItemText& text = items.items[next++];
      std::optional<YAML::Node> item = load_item(text);
      if (!item) throw NeedsWholeDocument{};
      item_.emplace(*item);  // not operator=: a YAML::Node assigned to rewrites the node it held
      item_line_ = text.first_line;
      return item;
    }, items.list);
  } catch (const NeedsWholeDocument&) {
    return std::nullopt;
  } catch (const YAML::Exception&) {
    return std::nullopt;  // the whole document's load reports it with its own mark
  }
}

Scene Loader::build(const std::function<std::optional<YAML::Node>()>& next_item, const YAML::Mark& list) {
  World world;
  std::optional<CameraParams> cam;
  YAML::Node cam_node;
  while (const std::optional<YAML::Node> next = next_item()) {
    const YAML::Node& item = *next;
    const auto es = entries(item, "a scene item");
    if (const Entry* d = find(es, "define")) {
      check_keys(es, {"define", "value", "extend"}, "a define");
      const std::string n = name(d->value, "a define");
      if (is_builtin(n) || n == "camera" || n == "light") fail(d->value, "cannot redefine the built-in '" + n + "'");
      const Entry& v = require(es, "value", item, "a define");
      // A whole document's item stays out: assigning defines_[n] would rewrite it.
      Define def{d->value, v.value, std::nullopt, item_by_item_ ? item : YAML::Node(), item_line_};
      if (const Entry* e = find(es, "extend")) {
        name(e->value, "'extend'");
        def.extend = e->value;
      }
      defines_[n] = def;
      transform_defines_.clear();
      continue;
    }
    const Entry* add = find(es, "add");
    if (!add) {
      std::vector<std::string> ks{"add", "define"};
      fail(item, "a scene item needs 'add' or 'define'" + (es.empty() ? std::string() : suggestion(es[0].key, ks)));
    }
    const std::string kind = name(add->value, "'add'");
    if (kind == "camera") {
      check_keys(es, {"add", "width", "height", "field-of-view", "from", "to", "up"}, "a camera");
      if (cam) fail(add->value, "a second camera (only one is allowed)");
      CameraParams c;
      const Entry& w = require(es, "width", item, "a camera");
      const Entry& h = require(es, "height", item, "a camera");
      c.width = integer(w.value);
      c.height = integer(h.value);
      if (const std::string e = image_size_error(c.width, c.height); !e.empty())
        fail(c.width < 1 || c.width > kMaxImageSide ? w.value : h.value, "camera " + e);
      const Entry& f = require(es, "field-of-view", item, "a camera");
      c.fov = number(f.value);
      if (!(c.fov > 0 && c.fov < std::numbers::pi)) fail(f.value, "field-of-view must be between 0 and pi radians, got " + f.value.Scalar());
      c.from = point3(require(es, "from", item, "a camera").value, "from");
      const Entry& to = require(es, "to", item, "a camera");
      c.to = point3(to.value, "to");
      const Entry& up = require(es, "up", item, "a camera");
      c.up = vector3(up.value, "up");
      const Tuple fwd = c.to - c.from;
      if (magnitude(fwd) == 0) fail(to.value, "camera 'to' equals 'from'");
      if (magnitude(cross(fwd, c.up)) <= 1e-12 * magnitude(fwd) * magnitude(c.up))
        fail(up.value, "camera 'up' is zero or parallel to the view direction");
      cam = c;
      cam_node = add->value;
    } else if (kind == "light") {
      check_keys(es, {"add", "at", "intensity", "corner", "uvec", "vvec", "usteps", "vsteps", "jitter"}, "a light");
      const Color intensity = color(require(es, "intensity", item, "a light").value, "intensity");
      if (const Entry* corner = find(es, "corner")) {
        // Area light (soft shadows bonus chapter).
        const Tuple c0 = point3(corner->value, "corner");
        const Tuple u = vector3(require(es, "uvec", item, "an area light").value, "uvec");
        const Tuple v = vector3(require(es, "vvec", item, "an area light").value, "vvec");
        const Entry& us = require(es, "usteps", item, "an area light");
        const Entry& vs = require(es, "vsteps", item, "an area light");
        const int nu = integer(us.value), nv = integer(vs.value);
        if (nu <= 0 || nu > 64) fail(us.value, "usteps must be in 1..64");
        if (nv <= 0 || nv > 64) fail(vs.value, "vsteps must be in 1..64");
        bool jitter = false;
        if (const Entry* j = find(es, "jitter")) jitter = boolean(j->value);
        world.area_lights.emplace_back(c0, u, nu, v, nv, intensity, jitter);
      } else {
        for (const char* k : {"uvec", "vvec", "usteps", "vsteps", "jitter"})
          if (const Entry* e = find(es, k)) fail(e->key_node, std::string("'") + k + "' needs 'corner' (area light)");
        world.lights.push_back(PointLight{point3(require(es, "at", item, "a light").value, "at"), intensity});
      }
    } else {
      std::set<std::string> visiting;
      auto s = shape(item, Inherited{}, visiting, 1);
      if (dynamic_cast<Group*>(s.get()) || dynamic_cast<Csg*>(s.get())) s->divide(kGroupBvhThreshold);
      world.objects.push_back(std::move(s));
    }
  }
  if (!cam) fail(list, "the scene has no camera (add one with '- add: camera')");
  Camera camera(cam->width, cam->height, cam->fov);
  camera.set_transform(view_transform(cam->from, cam->to, cam->up));
  // The list grew by doubling; it holds 16 bytes per shape from here on.
  world.objects.shrink_to_fit();
  index_objects(world);
  return Scene{std::move(world), camera};
}

std::string format_yaml_error(const std::string& source, const YAML::Exception& e) {
  std::ostringstream os;
  os << source << ':';
  if (e.mark.line >= 0) os << e.mark.line + 1 << ':' << e.mark.column + 1 << ": ";
  else os << ' ';
  // yaml-cpp's depth guard says "bad file"; say what it means.
  if (dynamic_cast<const YAML::DeepRecursion*>(&e)) os << "YAML syntax error: lists or maps nested too deeply";
  else os << "YAML syntax error: " << e.msg;
  return os.str();
}

}  // namespace

Scene load_scene_from_string(const std::string& text, const std::string& source, const std::filesystem::path& base_dir,
                             const SceneLoadOptions& options) {
  if (!options.whole_document) {
    std::optional<YamlItems> items;
    try {
      items = split_items(text);
    } catch (const YAML::Exception& e) {
      throw SceneError(format_yaml_error(source, e));
    }
    if (items)
      if (std::optional<Scene> scene = Loader(source, base_dir, options).load(*items)) return std::move(*scene);
  }
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw SceneError(format_yaml_error(source, e));
  }
  try {
    return Loader(source, base_dir, options).load(root);
  } catch (const YAML::Exception& e) {
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
  // hold the text two or three times over at the peak (issue 6).
  std::string text;
  if (const auto size = std::filesystem::file_size(path, ec); !ec) text.reserve(size);
  char chunk[1 << 16];
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) text.append(chunk, static_cast<std::size_t>(in.gcount()));
  if (in.bad()) throw SceneError("cannot read scene '" + path + "': read error");
  const auto dir = std::filesystem::path(path).parent_path();
  return load_scene_from_string(text, path, dir.empty() ? std::filesystem::path(".") : dir, options);
}

}  // namespace toroid
