// SPDX-License-Identifier: Apache-2.0
#include "toroid/scene/yaml_params.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "toroid/scene/scene_loader.h"

namespace toroid {
namespace {

// The message ItemParams gives for `text` (one map) when `read` asks for
// the keys and the values are read after report_unused().
std::string message_of(const std::string& text, const std::function<void(ItemParams&)>& read) {
  const Defines defines;
  const SceneReader reader("item.yml", defines);
  const YAML::Node node = YAML::Load(text);
  ItemParams params(reader, reader.entries(node, "an item"), node);
  try {
    read(params);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

// Asks for `keys` in that order, then reports the others.
std::function<void(ItemParams&)> asking_for(std::vector<std::string> keys) {
  return [keys](ItemParams& p) {
    for (const std::string& k : keys) p.get(k);
    p.report_unused("a thing");
  };
}

TEST(ItemParams, TheKeysReadAreTheKeysAllowed) {
  EXPECT_EQ(message_of("{min: 1, max: 2}", asking_for({"min", "max"})), "");
  EXPECT_EQ(message_of("{min: 1, maxx: 2}", asking_for({"min", "max"})),
            "item.yml:1:10: unknown key 'maxx' in a thing (did you mean 'max'?)");
  EXPECT_EQ(message_of("{min: 1, colour: 2}", asking_for({"min", "max"})),
            "item.yml:1:10: unknown key 'colour' in a thing");
}

TEST(ItemParams, OnATieTheKeyAskedForFirstIsSuggested) {
  EXPECT_EQ(message_of("{mix: 1}", asking_for({"min", "max"})),
            "item.yml:1:2: unknown key 'mix' in a thing (did you mean 'min'?)");
  EXPECT_EQ(message_of("{mix: 1}", asking_for({"max", "min"})),
            "item.yml:1:2: unknown key 'mix' in a thing (did you mean 'max'?)");
}

TEST(ItemParams, AnUnknownKeyIsReportedBeforeABadValue) {
  auto read = [](ItemParams& p) {
    const Param min = p.get("min");
    p.report_unused("a thing");
    min.number();
  };
  EXPECT_EQ(message_of("{min: x, bogus: 1}", read), "item.yml:1:10: unknown key 'bogus' in a thing");
  EXPECT_EQ(message_of("{min: x}", read), "item.yml:1:7: expected a number, got 'x'");
}

TEST(ItemParams, HasDoesNotMarkAKeyRead) {
  auto read = [](ItemParams& p) {
    EXPECT_TRUE(p.has("define"));
    EXPECT_FALSE(p.has("add"));
    p.report_unused("a thing");
  };
  EXPECT_EQ(message_of("{define: x}", read), "item.yml:1:2: unknown key 'define' in a thing");
}

TEST(ItemParams, NeedNamesTheMissingKeyAtTheItem) {
  auto read = [](ItemParams& p) {
    const Param file = p.get("file");
    EXPECT_FALSE(file);
    file.need("an obj");
  };
  EXPECT_EQ(message_of("{other: 1}", read), "item.yml:1:1: an obj needs 'file'");
}

}  // namespace
}  // namespace toroid
