// SPDX-License-Identifier: Apache-2.0
// Scene files the loader rejects, and the message and position it gives.
#include <gtest/gtest.h>

#include <string>

#include "toroid/scene/scene_files_test_fixture.h"
#include "toroid/scene/scene_loader.h"

namespace toroid {
namespace {

TEST_F(SceneFiles, PartialTorusErrors) {
  expect_error(kCamera + "- add: torus\n  theta-max: 0\n", "12:14: torus 'theta-max' must be in (0, 2 pi]");
  expect_error(kCamera + "- add: torus\n  theta-max: 7\n", "12:14: torus 'theta-max' must be in (0, 2 pi]");
  expect_error(kCamera + "- add: torus\n  theta-max: .nan\n", "12:14: expected a finite number");
  expect_error(kCamera + "- add: torus\n  phi-min: [1]\n", "12:12: expected a number, got a list");
  expect_error(kCamera + "- add: torus\n  phi-max: 7\n", "12:12: torus 'phi-max' must be in [-2 pi, 2 pi]");
  expect_error(kCamera + "- add: torus\n  phi-min: 1\n  phi-max: 0.5\n",
               "13:12: torus 'phi-max' must be greater than 'phi-min'");
  expect_error(kCamera + "- add: torus\n  phi-min: 3.5\n", "12:12: torus 'phi-max' must be greater than 'phi-min'");
  expect_error(kCamera + "- add: torus\n  phi-min: -4\n  phi-max: 4\n",
               "13:12: torus 'phi-max' - 'phi-min' must be at most 2 pi");
  expect_error(kCamera + "- add: torus\n  spindle: inner\n",
               "12:12: unknown spindle surface 'inner' (use whole or outer)");
  expect_error(kCamera + "- add: torus\n  spindel: outer\n",
               "12:3: unknown key 'spindel' in a torus (did you mean 'spindle'?)");
  expect_error(kCamera + "- add: sphere\n  theta-max: 1\n", "12:3: unknown key 'theta-max' in a sphere");
}

TEST_F(SceneFiles, Errors) {
  expect_error(kCamera + "- add: sphere\n  material:\n    colr: [1, 0, 0]\n",
               "13:5: unknown key 'colr' in a material (did you mean 'color'?)");
  expect_error(kCamera + "- add: spher\n", "11:8: unknown shape 'spher' (did you mean 'sphere'?)");
  expect_error(kCamera + "- add: torus\n  minor: 0\n", "12:10: torus 'minor' must be > 0");
  expect_error(kCamera + "- add: torus\n  major: -1\n", "12:10: torus 'major' must be > 0");
  expect_error(kCamera + "- add: torus\n  major: .inf\n", "12:10: expected a finite number");
  expect_error(kCamera + "- add: torus\n  major: abc\n", "12:10: expected a number, got 'abc'");
  expect_error(kCamera + "- add: sphere\n  transform:\n    - [scale, 1, 0, 1]\n", "13:5: singular transform");
  expect_error(kCamera + "- add: sphere\n  transform:\n    - [translate, 1, 2]\n",
               "13:7: 'translate' takes 3 numbers, got 2");
  expect_error(kCamera + "- add: sphere\n  material:\n    color: [1, 0]\n", "13:12: color must have 3 numbers, got 2");
  expect_error(kCamera + "- add: sphere\n  material: nothing\n", "12:13: undefined material 'nothing'");
  expect_error(kCamera +
                   "- define: a\n  extend: b\n  value: {color: [1, 1, 1]}\n- define: b\n  extend: a\n"
                   "  value: {ambient: 1}\n- add: sphere\n  material: a\n",
               "15:11: circular define: 'a' refers to itself");
  expect_error(kCamera + "- add: csg\n  operation: union\n  left: {add: sphere}\n",
               "11:8: a csg needs both 'left' and 'right' operands (missing 'right')");
  expect_error(kCamera + "- add: csg\n  operation: unoin\n  left: {add: sphere}\n  right: {add: cube}\n",
               "12:14: unknown csg operation 'unoin' (did you mean 'union'?)");
  expect_error(
      "- add: camera\n  width: 0\n  height: 30\n  field-of-view: 0.8\n  from: [0, 2, -5]\n"
      "  to: [0, 0, 0]\n  up: [0, 1, 0]\n",
      "2:10: camera width must be in 1..16384");
  expect_error(
      "- add: camera\n  width: 10\n  height: 20000\n  field-of-view: 0.8\n  from: [0, 2, -5]\n"
      "  to: [0, 0, 0]\n  up: [0, 1, 0]\n",
      "3:11: camera height must be in 1..16384");
  expect_error(kCamera + "- add: sphere\n  material: {color: [1, 0, 0]\n", "13:1: YAML syntax error");
  expect_error(kCamera + "- add: obj\n  file: missing.obj\n", "12:9: OBJ file 'missing.obj' not found");
  expect_error(kCamera + "- add: torus\n  solver: bogus\n", "12:11: unknown solver 'bogus'");
  expect_error(kCamera + "- add: sphere\n  transform: [translate, 1, 2, 3]\n",
               "12:14: each transform operation is a list of its own");
  expect_error(kCamera + "- add: cube\n  transform:\n    - [scale, 1e999, 1, 1]\n",
               "13:15: number out of range: '1e999'");
  expect_error(kCamera + "- add: sphere\n  material:\n    refractive-index: -1\n",
               "13:23: refractive-index must be > 0");
  expect_error(kCamera + "- add: sphere\n  transform: " + std::string(1000, '[') + std::string(1000, ']') + "\n",
               "12:2014: YAML syntax error: lists or maps nested too deeply");
  expect_error(
      "- add: camera\n  width: 16384\n  height: 8192\n  field-of-view: 0.8\n  from: [0, 2, -5]\n"
      "  to: [0, 0, 0]\n  up: [0, 1, 0]\n",
      "3:11: camera 16384x8192 is 134217728 pixels, more than the limit of 67108864 (8192x8192)");
}

TEST_F(SceneFiles, DefinesInsideThemselvesAreCaughtThroughGroups) {
  expect_error(kCamera + "- define: nest\n  value:\n    add: group\n    children:\n      - add: nest\n- add: nest\n",
               "15:14: circular define: shape 'nest' contains itself");
}

TEST_F(SceneFiles, GroupsNestSixtyFourDeep) {
  auto nested = [](int depth) {
    std::string s, indent;
    for (int i = 0; i < depth - 1; ++i, indent += "    ") s += indent + "- add: group\n" + indent + "  children:\n";
    return s + indent + "- add: sphere\n";
  };
  EXPECT_EQ(error_of(kCamera + nested(64)), "");
  EXPECT_NE(error_of(kCamera + nested(65)).find("groups and CSG nested more than 64 deep"), std::string::npos);
}

TEST_F(SceneFiles, DefinesThatMultiplyShapesStopAtTheLimit) {
  // Each define holds two of the one before: 2^17 spheres > 100000.
  std::string text = kCamera + "- define: s0\n  value:\n    add: sphere\n";
  for (int i = 1; i <= 17; ++i)
    text += "- define: s" + std::to_string(i) + "\n  value:\n    add: group\n    children: [{add: s" +
            std::to_string(i - 1) + "}, {add: s" + std::to_string(i - 1) + "}]\n";
  text += "- add: s17\n";
  EXPECT_NE(error_of(text).find("the scene makes more than 100000 shapes"), std::string::npos);
}

TEST_F(SceneFiles, AFolderIsNotAScene) {
  const std::string d = dir_.string();
  try {
    load_scene(d);
    ADD_FAILURE();
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), "cannot read scene '" + d + "': not a regular file");
  }
}

}  // namespace
}  // namespace toroid
