// SPDX-License-Identifier: Apache-2.0
// `pattern:` maps: one builder per `type`, and the uv patterns of `type: map`.
#include <algorithm>
#include <map>

#include "toroid/io/image_reader.h"
#include "toroid/render/texture_map.h"
#include "toroid/scene/load_state.h"
#include "toroid/scene/yaml_params.h"

namespace toroid {

namespace {

// Two colours under `colors` (stripes, checkers, uv checkers, ...).
std::pair<Color, Color> two_colors(const SceneReader& r, const Param& colors, const std::string& what) {
  const YAML::Node& cs = colors.need(what);
  if (!cs.IsSequence() || cs.size() != 2)
    r.fail(cs, "'colors' must be a list of 2 colors [r, g, b], got " +
                   (cs.IsSequence() ? std::to_string(cs.size()) + " entries" : describe(cs)));
  return {r.color(cs[0], "a color"), r.color(cs[1], "a color")};
}

// An image file, read once however many patterns name it.
std::shared_ptr<const Canvas> image(LoadState& state, const YAML::Node& file_node) {
  const std::string file = state.reader.name(file_node, "file");
  const std::filesystem::path p = resolve(state, file);
  std::error_code ec;  // when the file cannot even be looked at, read_image says why
  if (!std::filesystem::exists(p, ec) && !ec) fail_not_found(state, file_node, "image", file, p);
  const std::filesystem::path canonical = std::filesystem::canonical(p, ec);
  const std::string key = ec ? p.string() : canonical.string();
  if (auto it = state.images.find(key); it != state.images.end()) return it->second;
  try {
    return state.images[key] = std::make_shared<const Canvas>(read_image(p.string()));
  } catch (const ImageReadError& e) {
    state.reader.fail(file_node, "cannot load image '" + file + "': " + e.what());
  }
}

// The builder named by the item's `type` ("a " + `what` needs it), which it
// stores in `kind`; `hint` ends the message for an unknown type.
template <class Build>
Build builder_of_type(const SceneReader& r, ItemParams& p, std::span<const NamedBuilder<Build>> table,
                      const std::string& what, std::string& kind, const std::string& hint) {
  const Param type = p.get("type");
  kind = r.name(type.need("a " + what), what + " type");
  const auto* b = find_builder<Build>(table, kind);
  if (!b)
    r.fail(type.value(),
           "unknown " + what + " type '" + kind + "'" + suggestion(kind, builder_names<Build>(table)) + hint);
  return b->build;
}

// Uv patterns, by `type`.
using UvBuild = std::shared_ptr<const UvPattern> (*)(LoadState&, ItemParams&);

std::shared_ptr<const UvPattern> uv_checkers(LoadState& state, ItemParams& p) {
  const Param width = p.get("width"), height = p.get("height"), colors = p.get("colors");
  p.report_unused("a checkers uv pattern");
  const SceneReader& r = state.reader;
  const double w = r.positive(width.need("a checkers uv pattern"), "'width'");
  const double h = r.positive(height.need("a checkers uv pattern"), "'height'");
  const auto [a, b] = two_colors(r, colors, "a checkers uv pattern");
  return std::make_shared<UvCheckers>(w, h, a, b);
}

std::shared_ptr<const UvPattern> uv_align_check(LoadState& state, ItemParams& p) {
  const Param colors = p.get("colors");
  p.report_unused("an align_check uv pattern");
  const YAML::Node& cs = colors.need("an align_check uv pattern");
  const std::string what = "align_check 'colors'";
  ItemParams corners(state.reader, state.reader.entries(cs, what), cs);
  const Param main = corners.get("main"), ul = corners.get("ul"), ur = corners.get("ur"), bl = corners.get("bl"),
              br = corners.get("br");
  corners.report_unused(what);
  auto corner = [&](const Param& c) { return state.reader.color(c.need(what), c.key()); };
  return std::make_shared<UvAlignCheck>(corner(main), corner(ul), corner(ur), corner(bl), corner(br));
}

std::shared_ptr<const UvPattern> uv_image(LoadState& state, ItemParams& p) {
  const Param file = p.get("file");
  p.report_unused("an image uv pattern");
  return std::make_shared<UvImage>(image(state, file.need("an image uv pattern")));
}

constexpr NamedBuilder<UvBuild> kUvPatterns[] = {
    {"checkers", uv_checkers}, {"align_check", uv_align_check}, {"image", uv_image}};

std::shared_ptr<const UvPattern> uv_pattern(LoadState& state, const YAML::Node& node) {
  ItemParams p(state.reader, state.reader.entries(node, "a uv pattern"), node);
  std::string kind;
  const UvBuild build = builder_of_type<UvBuild>(state.reader, p, kUvPatterns, "uv pattern", kind,
                                                 " (use checkers, align_check or image)");
  return build(state, p);
}

// Patterns, by `type`; `kind` is the type, `depth` as in read_pattern.
using PatternBuild = std::shared_ptr<Pattern> (*)(LoadState&, ItemParams&, const std::string& kind, std::size_t depth);

template <class P>
std::shared_ptr<Pattern> two_color_pattern(LoadState& state, ItemParams& p, const std::string& kind, std::size_t) {
  const Param colors = p.get("colors");
  p.get("transform");
  p.report_unused("a pattern");
  const auto [a, b] = two_colors(state.reader, colors, "a '" + kind + "' pattern");
  return std::make_shared<P>(a, b);
}

std::shared_ptr<Pattern> blended(LoadState& state, ItemParams& p, const std::string&, std::size_t depth) {
  const Param patterns = p.get("patterns");
  p.get("transform");
  p.report_unused("a blended pattern");
  const YAML::Node& ps = patterns.need("a blended pattern");
  if (!ps.IsSequence() || ps.size() != 2) state.reader.fail(ps, "'patterns' must be a list of 2 patterns");
  return std::make_shared<BlendedPattern>(read_pattern(state, ps[0], depth + 1), read_pattern(state, ps[1], depth + 1));
}

// `type: map`: a mapping and a uv pattern, or (mapping: cube) a uv pattern
// per face. `mapping: torus` needs the torus's radii: `major`/`minor` when
// given, else those of the torus whose material this is.
std::shared_ptr<Pattern> map_pattern(LoadState& state, ItemParams& p, const std::string&, std::size_t) {
  const SceneReader& r = state.reader;
  const Param m = p.get("mapping");
  const std::string mapping = r.name(m.need("a map pattern"), "mapping");
  const std::vector<std::string> mappings{"spherical", "planar", "cylindrical", "cube", "torus"};
  if (std::find(mappings.begin(), mappings.end(), mapping) == mappings.end())
    r.fail(m.value(), "unknown mapping '" + mapping + "'" + suggestion(mapping, mappings) +
                          " (use spherical, planar, cylindrical, cube or torus)");
  if (mapping == "cube") {
    std::vector<Param> faces;
    for (const char* f : {"left", "right", "front", "back", "up", "down"}) faces.push_back(p.get(f));
    p.get("transform");
    p.report_unused("a cube map pattern");
    for (const Param& f : faces) f.need("a cube map pattern");
    // Read in file order, so that the first bad face in the file is reported.
    std::map<std::string, std::shared_ptr<const UvPattern>> uv;
    for (const Entry& e : p.entries())
      if (std::any_of(faces.begin(), faces.end(), [&](const Param& f) { return f.key() == e.key; }))
        uv[e.key] = uv_pattern(state, e.value);
    return std::make_shared<CubeMapPattern>(uv["left"], uv["front"], uv["right"], uv["back"], uv["up"], uv["down"]);
  }
  const Param uv_param = p.get("uv_pattern");
  p.get("transform");
  const Param major = mapping == "torus" ? p.get("major") : Param(p, "major", nullptr);
  const Param minor = mapping == "torus" ? p.get("minor") : Param(p, "minor", nullptr);
  p.report_unused("a '" + mapping + "' map pattern");
  auto uv = uv_pattern(state, uv_param.need("a map pattern"));
  UvMapping f;
  if (mapping == "spherical")
    f = spherical_map;
  else if (mapping == "planar")
    f = planar_map;
  else if (mapping == "cylindrical")
    f = cylindrical_map;
  else {
    if ((!major || !minor) && !state.material_torus)
      r.fail(m.value(),
             "mapping 'torus' needs the radii of the torus: use it in the material of a torus, or give "
             "'major' and 'minor'");
    const double R = major ? major.positive("'major'") : state.material_torus->major;
    const double rr = minor ? minor.positive("'minor'") : state.material_torus->minor;
    f = [R, rr](const Tuple& pt) { return toroidal_map(R, rr, pt); };
  }
  return std::make_shared<TextureMapPattern>(std::move(uv), std::move(f));
}

constexpr NamedBuilder<PatternBuild> kPatterns[] = {
    {"stripes", two_color_pattern<StripePattern>},
    {"gradient", two_color_pattern<GradientPattern>},
    {"rings", two_color_pattern<RingPattern>},
    {"checkers", two_color_pattern<CheckersPattern>},
    {"blended", blended},
    {"map", map_pattern},
};

}  // namespace

std::shared_ptr<Pattern> read_pattern(LoadState& state, const YAML::Node& node, std::size_t depth) {
  check_nesting(state, depth, node, "blended patterns");
  count(state, state.patterns_made, kMaxPatterns, node, "patterns");
  ItemParams p(state.reader, state.reader.entries(node, "a pattern"), node);
  std::string kind;
  const PatternBuild build = builder_of_type<PatternBuild>(state.reader, p, kPatterns, "pattern", kind, "");
  std::shared_ptr<Pattern> pattern = build(state, p, kind, depth);
  if (const Param t = p.get("transform")) pattern->set_transform(transform_of(state, t.value()));
  return pattern;
}

}  // namespace toroid
