// SPDX-License-Identifier: Apache-2.0
// docs/scene-format.md cannot rot: every ```yaml block in it is a scene
// example that loads and renders. An example without a camera or a light
// gets those of the block marked `<!-- stage -->`. A block marked
// `<!-- warns: TEXT -->` must load with one warning holding TEXT, and one
// marked `<!-- fails: TEXT -->` must fail with a message holding TEXT; both
// must point into the block. Every name that a table's first column quotes
// (`key`, `torus`, `rotate-x`, ...) must appear in some example.
//
// With TOROID_DOC_EXAMPLES_DIR set, each example's picture is written there
// as line-N.png (N: the block's first line), 240 pixels wide, to look at.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "toroid/io/image_writer.h"
#include "toroid/render/camera.h"
#include "toroid/render/renderer.h"
#include "toroid/scene/scene_loader.h"

namespace toroid {
namespace {

namespace fs = std::filesystem;

const fs::path kDoc = fs::path(TOROID_SOURCE_DIR) / "docs" / "scene-format.md";
const std::string kSource = "docs/scene-format.md";

struct Example {
  enum class Kind { Renders, Warns, Fails, Stage };
  Kind kind = Kind::Renders;
  std::string expected;  // the message text for Warns and Fails
  int first_line = 0;    // of the block's body, 1-based
  int last_line = 0;     // of the body's last line
  std::string text;
};

// The text of a mark `<!-- NAME: TEXT -->` (or `<!-- NAME -->`), or nullopt.
std::optional<std::string> mark(const std::string& line, const std::string& name) {
  const std::string open = "<!-- " + name, close = " -->";
  if (line.rfind(open, 0) != 0 || line.size() < open.size() + close.size() ||
      line.compare(line.size() - close.size(), close.size(), close) != 0)
    return std::nullopt;
  std::string rest = line.substr(open.size(), line.size() - open.size() - close.size());
  if (rest.empty()) return rest;
  if (rest.rfind(": ", 0) != 0) return std::nullopt;
  return rest.substr(2);
}

struct Doc {
  std::vector<std::string> lines;
  std::vector<Example> examples;
};

Doc read_doc() {
  Doc doc;
  std::ifstream in(kDoc);
  for (std::string line; std::getline(in, line);) doc.lines.push_back(line);
  for (std::size_t i = 0; i < doc.lines.size(); ++i) {
    if (doc.lines[i] != "```yaml") continue;
    Example e;
    if (i > 0) {
      const std::string& before = doc.lines[i - 1];
      if (mark(before, "stage")) {
        e.kind = Example::Kind::Stage;
      } else if (const auto w = mark(before, "warns")) {
        e.kind = Example::Kind::Warns;
        e.expected = *w;
      } else if (const auto f = mark(before, "fails")) {
        e.kind = Example::Kind::Fails;
        e.expected = *f;
      }
    }
    e.first_line = static_cast<int>(i) + 2;
    std::size_t j = i + 1;
    for (; j < doc.lines.size() && doc.lines[j].rfind("```", 0) != 0; ++j) e.text += doc.lines[j] + "\n";
    e.last_line = static_cast<int>(j);
    doc.examples.push_back(e);
    i = j;
  }
  return doc;
}

// The top-level items of an example whose `add` is `kind`.
bool adds(const std::string& text, const std::string& kind) {
  for (const YAML::Node& item : YAML::Load(text))
    if (item.IsMap() && item["add"] && item["add"].Scalar() == kind) return true;
  return false;
}

// The stage's items of the given kind, as text.
std::string stage_item(const std::string& stage, const std::string& kind) {
  std::istringstream in(stage);
  std::string out, line;
  bool in_item = false;
  while (std::getline(in, line)) {
    if (line.rfind("- ", 0) == 0) in_item = line == "- add: " + kind;
    if (in_item) out += line + "\n";
  }
  return out;
}

// The example as a scene: blank lines first, so that messages name the
// doc's own lines, then the stage's camera and light where it has none.
std::string scene_text(const Example& e, const std::string& stage) {
  std::string text(static_cast<std::size_t>(e.first_line - 1), '\n');
  text += e.text;
  if (!adds(e.text, "camera")) text += stage_item(stage, "camera");
  if (!adds(e.text, "light")) text += stage_item(stage, "light");
  return text;
}

// The line that a "docs/scene-format.md:LINE:COLUMN: ..." message names.
int message_line(const std::string& message) {
  const std::string prefix = kSource + ":";
  if (message.rfind(prefix, 0) != 0) return 0;
  return std::atoi(message.c_str() + prefix.size());
}

// Every key and scalar of a YAML tree.
void collect_words(const YAML::Node& node, std::set<std::string>& words) {
  if (node.IsScalar()) {
    words.insert(node.Scalar());
  } else if (node.IsSequence()) {
    for (const YAML::Node& n : node) collect_words(n, words);
  } else if (node.IsMap()) {
    for (const auto& kv : node) {
      words.insert(kv.first.Scalar());
      collect_words(kv.second, words);
    }
  }
}

TEST(SceneFormatDoc, HasAStageAndExamplesOfEachKind) {
  const Doc doc = read_doc();
  int stages = 0, renders = 0, warns = 0, fails = 0;
  for (const Example& e : doc.examples) {
    stages += e.kind == Example::Kind::Stage;
    renders += e.kind == Example::Kind::Renders;
    warns += e.kind == Example::Kind::Warns;
    fails += e.kind == Example::Kind::Fails;
  }
  EXPECT_EQ(stages, 1);
  EXPECT_GE(renders, 20);
  EXPECT_GE(warns, 1);
  EXPECT_GE(fails, 1);
}

TEST(SceneFormatDoc, EveryExampleRendersOrGivesItsMessage) {
  const Doc doc = read_doc();
  std::string stage;
  for (const Example& e : doc.examples)
    if (e.kind == Example::Kind::Stage) stage = e.text;
  ASSERT_FALSE(stage.empty()) << "no <!-- stage --> block in " << kDoc;
  const char* out_dir = std::getenv("TOROID_DOC_EXAMPLES_DIR");
  for (const Example& e : doc.examples) {
    if (e.kind == Example::Kind::Stage) continue;
    SCOPED_TRACE(kSource + ":" + std::to_string(e.first_line));
    std::vector<std::string> warnings;
    SceneLoadOptions options;
    options.on_warning = [&](const std::string& w) { warnings.push_back(w); };
    const std::string text = scene_text(e, stage);
    if (e.kind == Example::Kind::Fails) {
      try {
        load_scene_from_string(text, kSource, fs::path(TOROID_SOURCE_DIR) / "scenes", options);
        ADD_FAILURE() << "loaded, but the doc says it fails with: " << e.expected;
      } catch (const SceneError& error) {
        const std::string m = error.what();
        EXPECT_NE(m.find(e.expected), std::string::npos) << m;
        const int line = message_line(m);
        EXPECT_TRUE(line >= e.first_line && line <= e.last_line) << m;
      }
      continue;
    }
    std::optional<Scene> loaded;
    try {
      loaded = load_scene_from_string(text, kSource, fs::path(TOROID_SOURCE_DIR) / "scenes", options);
    } catch (const SceneError& error) {
      ADD_FAILURE() << error.what();
      continue;
    }
    const Scene& scene = *loaded;
    if (e.kind == Example::Kind::Warns) {
      ASSERT_EQ(warnings.size(), 1u) << "the doc says it warns: " << e.expected;
      EXPECT_NE(warnings[0].find(e.expected), std::string::npos) << warnings[0];
      const int line = message_line(warnings[0]);
      EXPECT_TRUE(line >= e.first_line && line <= e.last_line) << warnings[0];
    } else {
      for (const std::string& w : warnings) ADD_FAILURE() << "unexpected warning: " << w;
    }
    EXPECT_FALSE(scene.world.objects.empty());
    // Small, in the scene camera's proportions.
    const int width = 64, height = std::max(1, 64 * scene.camera.vsize() / scene.camera.hsize());
    Camera small(width, height, scene.camera.field_of_view());
    small.set_transform(scene.camera.transform());
    const Canvas image = render(small, scene.world);
    int lit = 0;
    for (const Color& c : image.pixels()) lit += c.r + c.g + c.b > 0.05;
    EXPECT_GT(lit, width * height / 10) << "the example shows (almost) nothing";
    if (out_dir) {
      Camera view(240, 240 * height / width, scene.camera.field_of_view());
      view.set_transform(scene.camera.transform());
      const fs::path file = fs::path(out_dir) / ("line-" + std::to_string(e.first_line) + ".png");
      EXPECT_TRUE(write_image(render(view, scene.world), file.string()));
    }
  }
}

TEST(SceneFormatDoc, EveryNameInATableIsInAnExample) {
  const Doc doc = read_doc();
  std::set<std::string> used;
  for (const Example& e : doc.examples) collect_words(YAML::Load(e.text), used);
  int names = 0;
  for (std::size_t i = 0; i < doc.lines.size(); ++i) {
    const std::string& line = doc.lines[i];
    if (line.rfind("| ", 0) != 0) continue;
    const std::string first = line.substr(2, line.find(" |", 1) - 2);
    // Each `quoted` name of the first cell.
    for (std::size_t open = first.find('`'); open != std::string::npos; open = first.find('`', open)) {
      const std::size_t close = first.find('`', open + 1);
      if (close == std::string::npos) break;
      const std::string name = first.substr(open + 1, close - open - 1);
      ++names;
      EXPECT_TRUE(used.count(name)) << kSource << ":" << i + 1 << ": '" << name << "' is in no example";
      open = close + 1;
    }
  }
  EXPECT_GE(names, 60);
}

}  // namespace
}  // namespace toroid
