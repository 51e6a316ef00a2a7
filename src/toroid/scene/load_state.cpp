// SPDX-License-Identifier: Apache-2.0
#include "toroid/scene/load_state.h"

#include <algorithm>

namespace toroid {

void count(const LoadState& state, std::size_t& counter, std::size_t limit, const YAML::Node& where,
           const std::string& what) {
  if (++counter > limit)
    state.reader.fail(where, "the scene makes more than " + std::to_string(limit) + " " + what +
                                 " (defines or YAML aliases that repeat one another multiply them)");
}

void check_nesting(const LoadState& state, std::size_t depth, const YAML::Node& where, const std::string& what) {
  if (depth > static_cast<std::size_t>(kMaxNesting))
    state.reader.fail(where, what + " nested more than " + std::to_string(kMaxNesting) + " deep");
}

void warn(LoadState& state, const YAML::Node& where, const std::string& what) {
  const YAML::Mark mark = state.reader.file_mark(where);
  std::string w = state.source + ':';
  if (mark.line >= 0) w += std::to_string(mark.line + 1) + ':' + std::to_string(mark.column + 1) + ':';
  w += " warning: " + what;
  if (std::none_of(state.warnings.begin(), state.warnings.end(), [&](const SceneWarning& x) { return x.text == w; }))
    state.warnings.push_back({mark.line, mark.column, std::move(w)});
}

std::filesystem::path resolve(const LoadState& state, const std::string& file) {
  const std::filesystem::path p(file);
  // Not lexically_normal(): "a/../b" differs from "b" when a is a symlink.
  return p.is_absolute() || state.base_dir == "." ? p : state.base_dir / p;
}

void fail_not_found(const LoadState& state, const YAML::Node& where, const std::string& kind, const std::string& file,
                    const std::filesystem::path& resolved) {
  state.reader.fail(where, kind + " file '" + file + "' not found" +
                               (resolved.string() == file ? "" : " (looked for '" + resolved.string() + "')"));
}

const Define& lookup_define(const LoadState& state, const YAML::Node& name_node, const std::string& what) {
  const std::string n = state.reader.name(name_node, what);
  auto it = state.defines.find(n);
  if (it == state.defines.end()) {
    std::vector<std::string> names;
    for (const auto& [k, _] : state.defines) names.push_back(k);
    state.reader.fail(name_node, "undefined " + what + " '" + n + "'" + suggestion(n, names));
  }
  return it->second;
}

}  // namespace toroid
