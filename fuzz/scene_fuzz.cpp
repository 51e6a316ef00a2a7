// SPDX-License-Identifier: Apache-2.0
// Fuzz target: the YAML scene loader. Any input must load or throw SceneError;
// anything else (a crash, another exception, a hang) is a bug. Loaded item by
// item (the default) and as a whole document, it must give the same result:
// both load the same scene (camera, lights, each shape's kind, material and
// transform), or both fail with the same message, and with the same warnings.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <typeinfo>

#include "toroid/core/material.h"
#include "toroid/scene/scene_loader.h"
#include "toroid/shapes/shape.h"

namespace {

// What a loaded scene holds, as text: the camera, the counts of lights, and
// each top-level shape's kind, material and transform.
std::string fingerprint(const toroid::Scene& scene) {
  std::string out;
  const auto add = [&](double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%a ", v);
    out += buf;
  };
  const toroid::Camera& c = scene.camera;
  add(c.hsize()), add(c.vsize()), add(c.field_of_view());
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) add(c.transform()(i, j));
  add(static_cast<double>(scene.world.lights.size())), add(static_cast<double>(scene.world.area_lights.size()));
  for (const auto& shape : scene.world.objects) {
    const toroid::Shape& kind = *shape;
    out += typeid(kind).name();
    out += ' ';
    const toroid::Material& m = shape->material();
    for (double v : {m.color.r, m.color.g, m.color.b, m.ambient, m.diffuse, m.specular, m.shininess, m.reflective,
                     m.transparency, m.refractive_index})
      add(v);
    const toroid::Matrix4 t = shape->inverse_transform();
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) add(t(i, j));
    out += '\n';
  }
  return out;
}

// The warnings, one per line, then the message, or the scene's fingerprint
// when it loads.
std::string outcome(const std::string& text, bool whole_document) {
  toroid::SceneLoadOptions options;
  options.whole_document = whole_document;
  std::string out;
  options.on_warning = [&](const std::string& w) { out += w + "\n"; };
  try {
    // Relative OBJ names resolve into a folder that does not exist.
    out += fingerprint(toroid::load_scene_from_string(text, "fuzz.yml", "/nonexistent/toroid-fuzz", options));
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
