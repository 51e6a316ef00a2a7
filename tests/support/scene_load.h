// SPDX-License-Identifier: Apache-2.0
// Loading a scene's text as the loader tests do, item by item (the default)
// or as one whole YAML document: what it warned, and the message of the
// SceneError that stopped it.
#pragma once

#include <string>
#include <vector>

#include "toroid/scene/scene_loader.h"

namespace toroid::testing {

struct LoadedText {
  std::vector<std::string> warnings;
  std::string error;  // the SceneError's message, "" when the scene loads
};

// `file` is the name that the messages give; the base folder is ".".
inline LoadedText load_text(const std::string& text, const std::string& file, bool whole_document) {
  LoadedText out;
  SceneLoadOptions options;
  options.whole_document = whole_document;
  options.on_warning = [&](const std::string& w) { out.warnings.push_back(w); };
  try {
    load_scene_from_string(text, file, ".", options);
  } catch (const SceneError& e) {
    out.error = e.what();
  }
  return out;
}

}  // namespace toroid::testing
