// SPDX-License-Identifier: Apache-2.0
// The torus's `caps` key: closes a partial torus, changes nothing on a
// whole one, and is refused on a partial spindle torus.
#include <gtest/gtest.h>

#include <string>

#include "toroid/scene/scene_files_test_fixture.h"
#include "toroid/scene/scene_loader.h"
#include "toroid/shapes/torus.h"

namespace toroid {
namespace {

TEST_F(SceneFiles, LoadsCappedTori) {
  const Scene s = load_scene(write("c.yml", kCamera + "- add: torus\n"
                                                      "  theta-max: 4.4\n"
                                                      "  caps: true\n"
                                                      "- add: torus\n"
                                                      "  phi-min: 0\n"
                                                      "  phi-max: 3.14159\n"
                                                      "  caps: true\n"
                                                      "- add: torus\n"
                                                      "  caps: true\n"
                                                      "- add: torus\n"
                                                      "  theta-max: 4.4\n"
                                                      "  caps: false\n"
                                                      "- add: torus\n"
                                                      "  minor: 2\n"
                                                      "  caps: true\n"
                                                      "- add: torus\n"
                                                      "  major: 1\n"
                                                      "  minor: 1\n"
                                                      "  theta-max: 3\n"
                                                      "  caps: true\n"));
  ASSERT_EQ(s.world.objects.size(), 6u);
  const auto torus = [&](std::size_t i) { return dynamic_cast<const Torus*>(s.world.objects[i].get()); };
  for (std::size_t i = 0; i < 6; ++i) ASSERT_NE(torus(i), nullptr);
  EXPECT_TRUE(torus(0)->capped());
  EXPECT_TRUE(torus(1)->capped());
  // A whole torus is closed already: caps change nothing (a whole spindle too).
  EXPECT_TRUE(torus(2)->caps());
  EXPECT_FALSE(torus(2)->capped());
  EXPECT_FALSE(torus(3)->caps());
  EXPECT_FALSE(torus(3)->capped());
  EXPECT_FALSE(torus(4)->capped());
  // A horn torus (minor = major) is capped.
  EXPECT_TRUE(torus(5)->capped());
}

TEST_F(SceneFiles, CapsErrors) {
  expect_error(kCamera + "- add: torus\n  theta-max: 3\n  caps: yes please\n",
               "13:9: expected true or false, got 'yes please'");
  expect_error(kCamera + "- add: torus\n  minor: 1.5\n  theta-max: 3\n  caps: true\n",
               "14:9: torus 'caps' needs minor <= major on a partial torus (minor 1.5 > major 1): a spindle "
               "torus's cut faces cross its axis");
  expect_error(kCamera + "- add: torus\n  minor: 1.5\n  phi-min: 0\n  caps: true\n", "14:9: torus 'caps' needs minor");
  expect_error(kCamera + "- add: torus\n  cap: true\n", "12:3: unknown key 'cap' in a torus (did you mean 'caps'?)");
  expect_error(kCamera + "- add: sphere\n  caps: true\n", "12:3: unknown key 'caps' in a sphere");
}

}  // namespace
}  // namespace toroid
