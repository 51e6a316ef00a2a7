// SPDX-License-Identifier: Apache-2.0
// `transform:` lists: [[translate, x, y, z], [rotate-y, a], NAME, ...].
#include <cmath>
#include <functional>
#include <numbers>
#include <set>
#include <sstream>

#include "toroid/math/transform.h"
#include "toroid/scene/load_state.h"

namespace toroid {

namespace {

// Each operation by name with how many numbers it takes, and whether they
// are angles (radians).
struct TransformOp {
  std::string name;
  std::size_t args;
  std::function<Matrix4(const std::vector<double>&)> make;
  bool angles = false;
};

const std::vector<TransformOp>& transform_ops() {
  static const std::vector<TransformOp> ops{
      {"translate", 3, [](const auto& v) { return translation(v[0], v[1], v[2]); }},
      {"scale", 3, [](const auto& v) { return scaling(v[0], v[1], v[2]); }},
      {"rotate-x", 1, [](const auto& v) { return rotation_x(v[0]); }, true},
      {"rotate-y", 1, [](const auto& v) { return rotation_y(v[0]); }, true},
      {"rotate-z", 1, [](const auto& v) { return rotation_z(v[0]); }, true},
      {"shear", 6, [](const auto& v) { return shearing(v[0], v[1], v[2], v[3], v[4], v[5]); }},
  };
  return ops;
}

// An angle beyond a full turn is almost surely in degrees (the book's
// scenes, and many a first scene, write [rotate-x, 90]): it is still a valid
// rotation, so the scene loads, but not silently.
void check_angle(LoadState& state, const std::string& kind, const YAML::Node& node, double radians) {
  if (std::abs(radians) <= 2 * std::numbers::pi) return;
  std::ostringstream meant;  // six significant digits, as %g
  meant << radians * (std::numbers::pi / 180);
  warn(state, node,
       kind + " angle " + node.Scalar() + " is more than 2 pi radians (a full turn); if it is in degrees, write " +
           meant.str() + " (angles are in radians)");
}

const TransformOp* find_op(const std::string& name) {
  for (const TransformOp& op : transform_ops())
    if (op.name == name) return &op;
  return nullptr;
}

void apply_transform_define(LoadState& state, const YAML::Node& name_node, Matrix4& m, std::set<std::string>& visiting);

// Composes a transform list onto `m` (first listed applies first).
void apply_transform_list(LoadState& state, const YAML::Node& list, Matrix4& m, std::set<std::string>& visiting) {
  const SceneReader& r = state.reader;
  if (!list.IsSequence()) r.fail(list, "transform must be a list, got " + describe(list));
  for (const YAML::Node& op : list) {
    if (op.IsScalar()) {
      if (find_op(op.Scalar()) && !state.defines.count(op.Scalar()))
        r.fail(list, "each transform operation is a list of its own: [[" + op.Scalar() + ", ...], ...]");
      apply_transform_define(state, op, m, visiting);
      continue;
    }
    if (!op.IsSequence() || op.size() == 0 || !op[0].IsScalar())
      r.fail(op, "a transform must be [operation, numbers...] or the name of a defined transform");
    const std::string kind = op[0].Scalar();
    const TransformOp* t = find_op(kind);
    if (!t) {
      std::vector<std::string> names;
      for (const TransformOp& o : transform_ops()) names.push_back(o.name);
      r.fail(op[0], "unknown transform '" + kind + "'" + suggestion(kind, names));
    }
    const std::size_t n = t->args;
    if (op.size() != n + 1)
      r.fail(op, "'" + kind + "' takes " + std::to_string(n) + " number" + (n == 1 ? "" : "s") + ", got " +
                     std::to_string(op.size() - 1));
    std::vector<double> v;
    for (std::size_t i = 1; i <= n; ++i) {
      v.push_back(r.number(op[i]));
      if (t->angles) check_angle(state, kind, op[i], v.back());
    }
    m = t->make(v) * m;
  }
}

// Each transform define is composed once and remembered: defines that list
// another twice would otherwise double the work at every level.
void apply_transform_define(LoadState& state, const YAML::Node& name_node, Matrix4& m,
                            std::set<std::string>& visiting) {
  const Define& d = lookup_define(state, name_node, "transform");
  const std::string n = name_node.Scalar();
  auto known = state.transform_defines.find(n);
  if (known == state.transform_defines.end()) {
    if (!visiting.insert(n).second) state.reader.fail(name_node, "circular define: '" + n + "' refers to itself");
    check_nesting(state, visiting.size(), name_node, "transform defines");
    if (!d.value.IsSequence()) state.reader.fail(name_node, "'" + n + "' is not a transform (its value is not a list)");
    Matrix4 composed = Matrix4::identity();
    if (d.extend) apply_transform_define(state, *d.extend, composed, visiting);
    apply_transform_list(state, d.value, composed, visiting);
    visiting.erase(n);
    known = state.transform_defines.emplace(n, composed).first;
  }
  m = known->second * m;
}

}  // namespace

Matrix4 transform_of(LoadState& state, const YAML::Node& list) {
  Matrix4 m = Matrix4::identity();
  std::set<std::string> visiting;
  apply_transform_list(state, list, m, visiting);
  const double det = determinant(m);
  if (!std::isfinite(det) || det == 0.0)
    state.reader.fail(list, "singular transform (determinant 0): it cannot be inverted");
  return m;
}

}  // namespace toroid
