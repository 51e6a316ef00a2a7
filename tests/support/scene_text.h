// SPDX-License-Identifier: Apache-2.0
// Scene text that loader tests start from. Their expected messages name
// lines: the camera takes lines 1-7, the light the next three.
#pragma once

#include <string>

namespace toroid::testing {

inline const std::string kSceneCamera =
    "- add: camera\n"
    "  width: 40\n"
    "  height: 30\n"
    "  field-of-view: 0.8\n"
    "  from: [0, 2, -5]\n"
    "  to: [0, 0, 0]\n"
    "  up: [0, 1, 0]\n";

inline const std::string kSceneLight =
    "- add: light\n"
    "  at: [-10, 10, -10]\n"
    "  intensity: [1, 1, 1]\n";

}  // namespace toroid::testing
