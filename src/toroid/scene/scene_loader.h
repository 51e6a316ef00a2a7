// SPDX-License-Identifier: Apache-2.0
// Scenes in the YAML format of "The Ray Tracer Challenge" (camera, lights,
// defines, shapes, groups, CSG, OBJ meshes) plus `add: torus`.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

#include "toroid/render/camera.h"
#include "toroid/render/renderer.h"
#include "toroid/render/world.h"
#include "toroid/torus/solver.h"

namespace toroid {

// Anything wrong with a scene file. what() is "FILE:LINE:COLUMN: what is
// wrong" (1-based line and column) whenever a position is known.
struct SceneError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Scene {
  World world;
  Camera camera;
  // The scene's `- add: integrator` choice, when it makes one (the command
  // line's --integrator overrides it).
  std::optional<Integrator> integrator;
};

struct SceneLoadOptions {
  // When set, every torus uses this solver (its own `solver:` key is ignored).
  std::optional<TorusSolver> solver;
  // Build yaml-cpp's node tree of the whole document at once rather than of
  // one top-level item at a time: the same scene or error, more memory
  // (for tests that compare the two).
  bool whole_document = false;
  // Receives each warning, "FILE:LINE:COLUMN: warning: what", in the order
  // of the file, once the scene has loaded or failed to (before the
  // SceneError is thrown). A warning is a value that is allowed but almost
  // surely a mistake, such as a rotation in degrees. Unset: each is printed
  // to std::cerr on a line of its own.
  std::function<void(const std::string&)> on_warning;
};

// Reads and builds the scene. Throws SceneError.
Scene load_scene(const std::string& path, const SceneLoadOptions& options = {});

// The same from text; `source` names the text in messages and `base_dir`
// resolves relative file names (OBJ meshes).
Scene load_scene_from_string(const std::string& text, const std::string& source, const std::filesystem::path& base_dir,
                             const SceneLoadOptions& options = {});

// Levenshtein distance (for "did you mean" suggestions).
int edit_distance(const std::string& a, const std::string& b);

}  // namespace toroid
