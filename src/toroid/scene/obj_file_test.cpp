// SPDX-License-Identifier: Apache-2.0
// obj_file.feature, plus the loader's errors and its BVH.
#include "toroid/scene/obj_file.h"

#include <gtest/gtest.h>

#include "support/shared_dir.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/approx.h"
#include "toroid/shapes/smooth_triangle.h"
#include "toroid/shapes/triangle.h"

namespace toroid {
namespace {

std::filesystem::path data(const char* name) { return std::filesystem::path(TOROID_SOURCE_DIR) / "tests/data" / name; }

const Triangle& triangle(const std::shared_ptr<Group>& g, std::size_t i) {
  const auto* t = dynamic_cast<const Triangle*>(g->children().at(i).get());
  if (t == nullptr) throw std::runtime_error("child is not a triangle");
  return *t;
}

// The book numbers vertices from 1; ObjFile::vertices from 0.
const Tuple& vertex(const ObjFile& obj, std::size_t book_index) { return obj.vertices.at(book_index - 1); }
const Tuple& normal(const ObjFile& obj, std::size_t book_index) { return obj.normals.at(book_index - 1); }

// "t.p1 = parser.vertices[a]", and so on for p2 and p3.
template <typename T>
void expect_corners(const T& t, const ObjFile& parser, std::size_t a, std::size_t b, std::size_t c) {
  EXPECT_APPROX(t.p1(), vertex(parser, a));
  EXPECT_APPROX(t.p2(), vertex(parser, b));
  EXPECT_APPROX(t.p3(), vertex(parser, c));
}

TEST(ObjFileParser, IgnoringUnrecognizedLines) {
  // tinyobjloader does not count the lines it ignores; what can be observed
  // is that all five are ignored without error and yield nothing.
  const ObjFile parser = parse_obj_file(data("gibberish.obj"));
  EXPECT_TRUE(parser.vertices.empty());
  EXPECT_TRUE(parser.normals.empty());
  EXPECT_TRUE(parser.default_group->empty());
  EXPECT_TRUE(parser.groups.empty());
}

TEST(ObjFileParser, VertexRecords) {
  const ObjFile parser = parse_obj_file(data("vertex_records.obj"));
  ASSERT_EQ(parser.vertices.size(), 4u);
  EXPECT_APPROX(vertex(parser, 1), point(-1, 1, 0));
  EXPECT_APPROX(vertex(parser, 2), point(-1, 0.5, 0));
  EXPECT_APPROX(vertex(parser, 3), point(1, 0, 0));
  EXPECT_APPROX(vertex(parser, 4), point(1, 1, 0));
}

TEST(ObjFileParser, ParsingTriangleFaces) {
  const ObjFile parser = parse_obj_file(data("triangle_faces.obj"));
  const auto& g = parser.default_group;
  ASSERT_EQ(g->size(), 2u);
  const Triangle& t1 = triangle(g, 0);
  const Triangle& t2 = triangle(g, 1);
  expect_corners(t1, parser, 1, 2, 3);
  expect_corners(t2, parser, 1, 3, 4);
}

TEST(ObjFileParser, TriangulatingPolygons) {
  const ObjFile parser = parse_obj_file(data("polygons.obj"));
  const auto& g = parser.default_group;
  ASSERT_EQ(g->size(), 3u);
  const Triangle& t1 = triangle(g, 0);
  const Triangle& t2 = triangle(g, 1);
  const Triangle& t3 = triangle(g, 2);
  expect_corners(t1, parser, 1, 2, 3);
  expect_corners(t2, parser, 1, 3, 4);
  expect_corners(t3, parser, 1, 4, 5);
}

TEST(ObjFileParser, TrianglesInGroups) {
  TOROID_REQUIRE_SHARED_DIR();
  const ObjFile parser = parse_obj_file(TOROID_SHARED_DIR "/rtc-features/triangles.obj");
  const auto g1 = parser.group("FirstGroup");
  const auto g2 = parser.group("SecondGroup");
  ASSERT_NE(g1, nullptr);
  ASSERT_NE(g2, nullptr);
  const Triangle& t1 = triangle(g1, 0);
  const Triangle& t2 = triangle(g2, 0);
  expect_corners(t1, parser, 1, 2, 3);
  expect_corners(t2, parser, 1, 3, 4);
}

TEST(ObjFileParser, ConvertingAnObjFileToAGroup) {
  TOROID_REQUIRE_SHARED_DIR();
  const ObjFile parser = parse_obj_file(TOROID_SHARED_DIR "/rtc-features/triangles.obj");
  const auto g = obj_to_group(parser);
  const auto first = parser.group("FirstGroup");
  const auto second = parser.group("SecondGroup");
  ASSERT_NE(first, nullptr);
  ASSERT_NE(second, nullptr);
  EXPECT_TRUE(g->includes(first.get()));
  EXPECT_TRUE(g->includes(second.get()));
  EXPECT_EQ(g->size(), 2u);  // the default group is empty and left out
}

TEST(ObjFileParser, VertexNormalRecords) {
  const ObjFile parser = parse_obj_file(data("vertex_normals.obj"));
  ASSERT_EQ(parser.normals.size(), 3u);
  EXPECT_APPROX(normal(parser, 1), vector(0, 0, 1));
  EXPECT_APPROX(normal(parser, 2), vector(0.707, 0, -0.707));
  EXPECT_APPROX(normal(parser, 3), vector(1, 2, 3));
}

TEST(ObjFileParser, FacesWithNormals) {
  const ObjFile parser = parse_obj_file(data("faces_with_normals.obj"));
  const auto& g = parser.default_group;
  ASSERT_EQ(g->size(), 2u);
  const auto* t1 = dynamic_cast<const SmoothTriangle*>(g->children()[0].get());
  const auto* t2 = dynamic_cast<const SmoothTriangle*>(g->children()[1].get());
  ASSERT_NE(t1, nullptr);
  ASSERT_NE(t2, nullptr);
  expect_corners(*t1, parser, 1, 2, 3);
  EXPECT_APPROX(t1->n1(), normal(parser, 3));
  EXPECT_APPROX(t1->n2(), normal(parser, 1));
  EXPECT_APPROX(t1->n3(), normal(parser, 2));
  // "t2 = t1": same corners and normals.
  EXPECT_APPROX(t2->p1(), t1->p1());
  EXPECT_APPROX(t2->p2(), t1->p2());
  EXPECT_APPROX(t2->p3(), t1->p3());
  EXPECT_APPROX(t2->n1(), t1->n1());
  EXPECT_APPROX(t2->n2(), t1->n2());
  EXPECT_APPROX(t2->n3(), t1->n3());
}

// --- not in obj_file.feature ----------------------------------------------

std::string error_of(const std::filesystem::path& path) {
  try {
    parse_obj_file(path);
  } catch (const ObjError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(ObjFileParser, AMissingFileIsAClearError) {
  const std::string message = error_of(data("no_such_file.obj"));
  EXPECT_NE(message.find("no_such_file.obj"), std::string::npos) << message;
  EXPECT_NE(message.find("cannot open"), std::string::npos) << message;
}

TEST(ObjFileParser, AMalformedFaceNamesFileAndLine) {
  const std::string message = error_of(data("zero_index.obj"));
  EXPECT_NE(message.find("zero_index.obj:6:"), std::string::npos) << message;
}

TEST(ObjFileParser, AFaceBeyondTheVerticesIsAnError) {
  const std::string message = error_of(data("out_of_range.obj"));
  EXPECT_NE(message.find("out_of_range.obj"), std::string::npos) << message;
  EXPECT_NE(message.find("vertex 9"), std::string::npos) << message;
}

std::string parse_error(std::string_view text) {
  try {
    parse_obj(text, "m.obj");
  } catch (const ObjError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(ObjFileParser, NegativeIndicesSignsAndCommentsAreRead) {
  const ObjFile obj = parse_obj("v +1 0 0 # a comment\nv 0 1 0\nv 0 0 1\nvn 0 0 1\nf -3//1 -2//-1 -1//1\n");
  ASSERT_EQ(obj.default_group->size(), 1u);
  EXPECT_DOUBLE_EQ(obj.vertices[0].x, 1);
}

TEST(ObjFileParser, BadRecordsNameLineAndColumn) {
  EXPECT_EQ(parse_error("v 0 0 0\nv 1 zero 0\n"), "m.obj:2:5: not a number: 'zero'");
  EXPECT_EQ(parse_error("v 0 0 0\nv 1e400 0 0\n"), "m.obj:2:3: number out of range: '1e400'");
  EXPECT_EQ(parse_error("v nan 0 0\n"), "m.obj:1:3: not a finite number: 'nan'");
  EXPECT_EQ(parse_error("v 0 0\n"), "m.obj:1:1: a vertex needs 3 to 6 numbers (x y z [w | r g b]), got 2");
  EXPECT_EQ(parse_error("vn 0 0 1 0\n"), "m.obj:1:1: a normal needs 3 numbers (x y z), got 4");
  EXPECT_EQ(parse_error("v 0 0 0\nv 1 0 0\nf 1 2\n"), "m.obj:3:1: a face needs at least 3 vertices, got 2");
  EXPECT_EQ(parse_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n"), "m.obj:4:7: not a vertex index: 'x'");
  EXPECT_EQ(parse_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1  0 2\n"), "m.obj:4:6: vertex indices start at 1, got 0");
  EXPECT_EQ(parse_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n"),
            "m.obj:4:7: face refers to vertex 4, but 3 vertices are defined");
  EXPECT_EQ(parse_error("v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 0 1 0\n"),
            "m.obj:3:9: face refers to vertex -3, but 2 vertices are defined before it");
  EXPECT_EQ(parse_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1/5/1 2//2 3//1\n"),
            "m.obj:5:12: face refers to normal 2, but 1 normals are defined");
}

TEST(ObjFileParser, AFolderIsNotAnObjFile) {
  const std::string message = error_of(std::filesystem::temp_directory_path());
  EXPECT_NE(message.find(": not a regular file"), std::string::npos) << message;
}

TEST(ObjFileParser, ObjectNamesAndRepeatedGroupsJoinOneGroup) {
  const ObjFile obj = parse_obj(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
      "o Thing\nf 1 2 3\ng Other\nf 2 4 3\ng Thing\nf 1 2 4\n");
  ASSERT_EQ(obj.groups.size(), 2u);
  EXPECT_EQ(obj.groups[0].first, "Thing");
  EXPECT_EQ(obj.groups[1].first, "Other");
  EXPECT_EQ(obj.group("Thing")->size(), 2u);
  EXPECT_EQ(obj.group("Other")->size(), 1u);
  EXPECT_TRUE(obj.default_group->empty());
}

// A 40 x 40 grid of quads (3200 triangles) in the z = 0 plane.
std::filesystem::path write_grid(int n) {
  const auto path = std::filesystem::temp_directory_path() / "toroid_obj_grid_test.obj";
  std::ofstream out(path);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) out << "v " << i << ' ' << j << " 0\n";
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i + 1;
      out << "f " << a << ' ' << a + 1 << ' ' << a + n + 2 << ' ' << a + n + 1 << '\n';
    }
  return path;
}

std::size_t depth(const Shape& s) {
  const auto* g = dynamic_cast<const Group*>(&s);
  if (g == nullptr) return 0;
  std::size_t d = 0;
  for (const auto& c : g->children()) d = std::max(d, depth(*c));
  return d + 1;
}

// The most primitives any group in the hierarchy holds directly.
std::size_t widest_leaf(const Group& g) {
  std::size_t direct = 0, widest = 0;
  for (const auto& c : g.children()) {
    if (const auto* sub = dynamic_cast<const Group*>(c.get())) {
      widest = std::max(widest, widest_leaf(*sub));
    } else {
      ++direct;
    }
  }
  return std::max(widest, direct);
}

TEST(ObjFileParser, LoadingALargeMeshBuildsABoundingVolumeHierarchy) {
  constexpr int kN = 40;
  const auto path = write_grid(kN);
  const auto flat = obj_to_group(parse_obj_file(path));
  const auto bvh = load_obj(path);
  std::filesystem::remove(path);
  ASSERT_EQ(flat->size(), 1u);
  EXPECT_EQ(flat->children()[0]->bounds().max.x, kN);
  EXPECT_EQ(static_cast<const Group&>(*flat->children()[0]).size(), 2u * kN * kN);
  EXPECT_GE(depth(*bvh), 8u);  // log2(3200 / 4) ~ 10 levels
  // Triangles straddling a split are gathered into subgroups of their own,
  // so no group keeps a long list of them (the book's divide leaves dozens).
  EXPECT_LT(widest_leaf(*bvh), kObjBvhThreshold);
  // Same hits with and without the hierarchy.
  for (double x : {0.25, 7.5, 19.9, 33.3}) {
    const Ray r{point(x, x / 2 + 0.1, -5), vector(0, 0, 1)};
    Intersections a, b;
    flat->intersect(r, a);
    bvh->intersect(r, b);
    ASSERT_EQ(a.size(), 1u);
    ASSERT_EQ(b.size(), 1u);
    EXPECT_EQ(a[0].t, b[0].t);
  }
}

}  // namespace
}  // namespace toroid
