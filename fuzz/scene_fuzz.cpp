// Fuzz target: the YAML scene loader. Any input must load or throw SceneError;
// anything else (a crash, another exception, a hang) is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "toroid/scene/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    // Relative OBJ names resolve into a folder that does not exist.
    toroid::load_scene_from_string(text, "fuzz.yml", "/nonexistent/toroid-fuzz");
  } catch (const toroid::SceneError&) {
  }
  return 0;
}
