// SPDX-License-Identifier: Apache-2.0
// Fuzz target: the YAML scene loader. Any input must load or throw SceneError;
// anything else (a crash, another exception, a hang) is a bug. Loaded item by
// item (the default) and as a whole document, it must give the same result:
// both load, or both fail with the same message, and with the same warnings.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "toroid/scene/scene_loader.h"

namespace {

// The warnings, one per line, then the message ("" when the scene loads).
std::string outcome(const std::string& text, bool whole_document) {
  toroid::SceneLoadOptions options;
  options.whole_document = whole_document;
  std::string out;
  options.on_warning = [&](const std::string& w) { out += w + "\n"; };
  try {
    // Relative OBJ names resolve into a folder that does not exist.
    toroid::load_scene_from_string(text, "fuzz.yml", "/nonexistent/toroid-fuzz", options);
  } catch (const toroid::SceneError& e) {
    out += e.what();
  }
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::string by_item = outcome(text, false);
  const std::string whole = outcome(text, true);
  if (by_item != whole) {
    std::fprintf(stderr, "item by item: '%s'\nwhole document: '%s'\n", by_item.c_str(), whole.c_str());
    std::abort();
  }
  return 0;
}
