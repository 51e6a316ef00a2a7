// SPDX-License-Identifier: Apache-2.0
// The scene items that are not shapes, `add: camera`, `add: light`,
// `add: environment` and `add: integrator`, each with its builder
// (camera_builder.cpp, light_builders.cpp, settings_builders.cpp).
#pragma once

#include <optional>

#include "toroid/render/renderer.h"
#include "toroid/render/world.h"
#include "toroid/scene/load_state.h"
#include "toroid/scene/yaml_params.h"

namespace toroid {

struct CameraParams {
  int width = 0, height = 0;
  double fov = 0;
  Tuple from, to, up;
};

// What the items read so far have made of the scene.
struct SceneParts {
  World world;
  std::optional<CameraParams> camera;
  // The 1-based lines of the `add: environment` and `add: integrator` items
  // read so far (each may appear once), and the integrator's choice.
  std::optional<int> environment_line, integrator_line;
  std::optional<Integrator> integrator;
};

// Builds one item into `parts`; its `add` key is read already.
using ItemBuild = void (*)(LoadState& state, SceneParts& parts, ItemParams& item);

void build_camera(LoadState& state, SceneParts& parts, ItemParams& item);
void build_light(LoadState& state, SceneParts& parts, ItemParams& item);
void build_environment(LoadState& state, SceneParts& parts, ItemParams& item);
void build_integrator(LoadState& state, SceneParts& parts, ItemParams& item);

}  // namespace toroid
