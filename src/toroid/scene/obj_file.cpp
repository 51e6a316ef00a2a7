// SPDX-License-Identifier: Apache-2.0
#include "toroid/scene/obj_file.h"

#include <tiny_obj_loader.h>

#include <charconv>
#include <fstream>
#include <regex>
#include <sstream>

#include "toroid/io/number_text.h"
#include "toroid/shapes/smooth_triangle.h"
#include "toroid/shapes/triangle.h"

namespace toroid {

namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

struct Token {
  std::string_view text;
  std::size_t column;  // 1-based
};

// The blank-separated words of a line, up to a '#' comment.
std::vector<Token> tokens_of(std::string_view line) {
  std::vector<Token> out;
  std::size_t i = 0;
  while (i < line.size()) {
    if (is_blank(line[i])) {
      ++i;
      continue;
    }
    if (line[i] == '#') break;
    std::size_t j = i;
    while (j < line.size() && !is_blank(line[j])) ++j;
    out.push_back({line.substr(i, j - i), i + 1});
    i = j;
  }
  return out;
}

// Reads the whole token as an integer; false if it is not one.
bool read_integer(std::string_view text, long long& value) {
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  return ec == std::errc() && ptr == end;
}

// The counts of "v" and "vn" records (faces may refer ahead to them).
void count_records(std::string_view text, std::size_t& vertices, std::size_t& normals) {
  vertices = normals = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::size_t i = pos;
    while (i < end && is_blank(text[i])) ++i;
    if (i + 1 < end && text[i] == 'v' && is_blank(text[i + 1])) ++vertices;
    if (i + 2 < end && text[i] == 'v' && text[i + 1] == 'n' && is_blank(text[i + 2])) ++normals;
    pos = end + 1;
  }
}

// Checks the records toroid uses ("v", "vn", "f"), naming source:line:column
// of what is wrong, and rewrites the vertex references of faces without their
// texture index ("v/t/n" -> "v//n", "v/t" -> "v"): toroid has no use for
// texture coordinates, and tinyobjloader rejects an index of 0, which the
// book's fixtures use. Keeps one output line per input line, so line numbers
// in tinyobjloader's messages stay right.
std::string checked_obj_text(std::string_view text, const std::string& source) {
  std::size_t total_vertices = 0, total_normals = 0;
  count_records(text, total_vertices, total_normals);
  std::size_t vertices = 0, normals = 0;  // so far: negative indices count back from here
  std::string out;
  out.reserve(text.size());
  std::size_t pos = 0;
  long line_no = 0;
  while (pos < text.size()) {
    ++line_no;
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(pos, end - pos);
    auto fail = [&](std::size_t column, const std::string& what) {
      throw ObjError(source + ":" + std::to_string(line_no) + ":" + std::to_string(column) + ": " + what);
    };
    const std::vector<Token> tokens = tokens_of(line);
    const std::string_view keyword = tokens.empty() ? std::string_view{} : tokens[0].text;
    if (keyword == "v" || keyword == "vn") {
      const bool vertex = keyword == "v";
      // "v x y z [w]" or "v x y z r g b"; "vn x y z".
      const std::size_t lo = 3, hi = vertex ? 6 : 3;
      if (tokens.size() - 1 < lo || tokens.size() - 1 > hi)
        fail(tokens[0].column, std::string(vertex ? "a vertex" : "a normal") + " needs " +
                                   (vertex ? "3 to 6 numbers (x y z [w | r g b])" : "3 numbers (x y z)") + ", got " +
                                   std::to_string(tokens.size() - 1));
      for (std::size_t k = 1; k < tokens.size(); ++k) {
        double v = 0;
        if (const NumberText r = read_finite_double(tokens[k].text, v); r != NumberText::Ok)
          fail(tokens[k].column, describe(r, tokens[k].text));
      }
      ++(vertex ? vertices : normals);
      out.append(line);
    } else if (keyword == "f") {
      if (tokens.size() < 4)
        fail(tokens[0].column, "a face needs at least 3 vertices, got " + std::to_string(tokens.size() - 1));
      // Index i (1-based; negative counts back from the records so far) of
      // `what` must name one of the `total` records.
      auto check_index = [&](std::string_view t, std::size_t column, std::size_t so_far, std::size_t total,
                             const char* what, const char* plural) {
        long long i = 0;
        if (!read_integer(t, i)) fail(column, std::string("not a ") + what + " index: '" + std::string(t) + "'");
        const long long resolved = i < 0 ? static_cast<long long>(so_far) + i + 1 : i;
        if (i == 0) fail(column, std::string(what) + " indices start at 1, got 0");
        if (resolved < 1 || resolved > static_cast<long long>(total))
          fail(column, std::string("face refers to ") + what + " " + std::string(t) + ", but " +
                           std::to_string(i < 0 ? so_far : total) + " " + plural + " are defined" +
                           (i < 0 ? " before it" : ""));
      };
      out.append(line.substr(0, tokens[1].column - 1));
      for (std::size_t k = 1; k < tokens.size(); ++k) {
        const std::string_view ref = tokens[k].text;
        const std::size_t s1 = ref.find('/');
        check_index(ref.substr(0, s1), tokens[k].column, vertices, total_vertices, "vertex", "vertices");
        out.append(ref.substr(0, s1));
        if (s1 != std::string_view::npos) {
          const std::size_t s2 = ref.find('/', s1 + 1);
          if (s2 != std::string_view::npos) {
            const std::string_view n = ref.substr(s2 + 1);
            check_index(n, tokens[k].column + s2 + 1, normals, total_normals, "normal", "normals");
            out.append("//").append(n);
          }
        }
        out.push_back(' ');
      }
    } else {
      out.append(line);
    }
    if (end < text.size()) out.push_back('\n');
    pos = end + 1;
  }
  return out;
}

// "source:line: message" when tinyobjloader's message names a line.
[[noreturn]] void throw_parse_error(const std::string& source, std::string message) {
  while (!message.empty() && (message.back() == '\n' || message.back() == '\r')) message.pop_back();
  std::smatch m;
  static const std::regex kLine(R"(line (\d+))");
  std::string where = source;
  if (std::regex_search(message, m, kLine)) where.append(1, ':').append(m[1].first, m[1].second);
  throw ObjError(where + ": " + message);
}

Tuple fetch(const std::vector<tinyobj::real_t>& xyz, int index) {
  const auto i = static_cast<std::size_t>(index) * 3;
  return {static_cast<double>(xyz[i]), static_cast<double>(xyz[i + 1]), static_cast<double>(xyz[i + 2]), 0.0};
}

}  // namespace

std::shared_ptr<Group> ObjFile::group(std::string_view name) const {
  for (const auto& [n, g] : groups)
    if (n == name) return g;
  return nullptr;
}

ObjFile parse_obj(std::string_view text, const std::string& source) {
  tinyobj::ObjReaderConfig config;
  config.triangulate = false;  // the book's fan order, below
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromString(checked_obj_text(text, source), "", config))
    throw_parse_error(source, reader.Error().empty() ? "cannot parse OBJ" : reader.Error());

  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  ObjFile obj;
  const std::size_t nv = attrib.vertices.size() / 3;
  const std::size_t nn = attrib.normals.size() / 3;
  obj.vertices.reserve(nv);
  for (std::size_t i = 0; i < nv; ++i) {
    Tuple p = fetch(attrib.vertices, static_cast<int>(i));
    p.w = 1.0;
    obj.vertices.push_back(p);
  }
  obj.normals.reserve(nn);
  for (std::size_t i = 0; i < nn; ++i) obj.normals.push_back(fetch(attrib.normals, static_cast<int>(i)));

  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    std::shared_ptr<Group> group;
    if (shape.name.empty()) {
      group = obj.default_group;
    } else {
      group = obj.group(shape.name);
      if (!group) {
        group = std::make_shared<Group>();
        obj.groups.emplace_back(shape.name, group);
      }
    }
    const auto& indices = shape.mesh.indices;
    std::size_t base = 0;
    for (const unsigned int n : shape.mesh.num_face_vertices) {
      for (std::size_t k = 0; k < n; ++k) {
        const tinyobj::index_t& idx = indices[base + k];
        if (idx.vertex_index < 0 || static_cast<std::size_t>(idx.vertex_index) >= nv)
          throw ObjError(source + ": face refers to vertex " + std::to_string(idx.vertex_index + 1) + ", but " +
                         std::to_string(nv) + " vertices are defined");
        if (idx.normal_index >= 0 && static_cast<std::size_t>(idx.normal_index) >= nn)
          throw ObjError(source + ": face refers to normal " + std::to_string(idx.normal_index + 1) + ", but " +
                         std::to_string(nn) + " normals are defined");
      }
      // Fan from the first vertex: (1, 2, 3), (1, 3, 4), ...
      for (std::size_t k = 1; k + 1 < n; ++k) {
        const tinyobj::index_t& a = indices[base];
        const tinyobj::index_t& b = indices[base + k];
        const tinyobj::index_t& c = indices[base + k + 1];
        const Tuple& p1 = obj.vertices[static_cast<std::size_t>(a.vertex_index)];
        const Tuple& p2 = obj.vertices[static_cast<std::size_t>(b.vertex_index)];
        const Tuple& p3 = obj.vertices[static_cast<std::size_t>(c.vertex_index)];
        if (a.normal_index >= 0 && b.normal_index >= 0 && c.normal_index >= 0) {
          group->add_child(std::make_shared<SmoothTriangle>(p1, p2, p3,
                                                            obj.normals[static_cast<std::size_t>(a.normal_index)],
                                                            obj.normals[static_cast<std::size_t>(b.normal_index)],
                                                            obj.normals[static_cast<std::size_t>(c.normal_index)]));
        } else {
          group->add_child(std::make_shared<Triangle>(p1, p2, p3));
        }
      }
      base += n;
    }
  }
  return obj;
}

ObjFile parse_obj_file(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
    throw ObjError(path.string() + ": not a regular file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ObjError(path.string() + ": cannot open OBJ file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw ObjError(path.string() + ": cannot read OBJ file");
  return parse_obj(text.str(), path.string());
}

std::shared_ptr<Group> obj_to_group(const ObjFile& obj) {
  auto root = std::make_shared<Group>();
  if (!obj.default_group->empty()) root->add_child(obj.default_group);
  for (const auto& [name, group] : obj.groups) root->add_child(group);
  return root;
}

std::shared_ptr<Group> load_obj(const std::filesystem::path& path, std::size_t bvh_threshold) {
  auto root = obj_to_group(parse_obj_file(path));
  root->divide(bvh_threshold);
  return root;
}

}  // namespace toroid
