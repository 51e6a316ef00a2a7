// SPDX-License-Identifier: Apache-2.0
// Wavefront OBJ meshes (RTC chapter 15), read with tinyobjloader: vertices,
// polygon faces (fan-triangulated as in the book), vertex normals (faces that
// give them become smooth triangles) and named groups ("g" / "o").
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "toroid/math/tuple.h"
#include "toroid/shapes/group.h"

namespace toroid {

// A file that cannot be read or parsed. what() starts with "source:line: "
// where the line is known.
struct ObjError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct ObjFile {
  // OBJ numbers records from 1: the book's vertices[1] is vertices[0] here.
  std::vector<Tuple> vertices;
  std::vector<Tuple> normals;
  // Triangles from faces outside any named group.
  std::shared_ptr<Group> default_group = std::make_shared<Group>();
  // Named groups in the order they first appear; faces under the same name
  // join the same group.
  std::vector<std::pair<std::string, std::shared_ptr<Group>>> groups;

  // The named group, or nullptr.
  std::shared_ptr<Group> group(std::string_view name) const;
};

// Parses OBJ text; `source` names it in error messages. Lines that are not
// OBJ records are ignored. Texture coordinates and their indices are ignored
// too (not even validated: the book's own fixtures use index 0).
ObjFile parse_obj(std::string_view text, const std::string& source = "<obj>");
ObjFile parse_obj_file(const std::filesystem::path& path);

// One group holding the default group (when it has triangles) and the named
// groups, which become its children.
std::shared_ptr<Group> obj_to_group(const ObjFile& obj);

// Leaf size of the BVH built over loaded meshes.
inline constexpr std::size_t kObjBvhThreshold = 4;

// parse_obj_file, obj_to_group, then divide into a bounding volume hierarchy.
std::shared_ptr<Group> load_obj(const std::filesystem::path& path, std::size_t bvh_threshold = kObjBvhThreshold);

}  // namespace toroid
