// SPDX-License-Identifier: Apache-2.0
// One builder per shape kind (`add: sphere`, ...); see ShapeItem for the
// order a builder follows.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>

#include "toroid/scene/obj_file.h"
#include "toroid/scene/shape_builders.h"
#include "toroid/shapes/cone.h"
#include "toroid/shapes/csg.h"
#include "toroid/shapes/cube.h"
#include "toroid/shapes/cylinder.h"
#include "toroid/shapes/group.h"
#include "toroid/shapes/plane.h"
#include "toroid/shapes/sphere.h"
#include "toroid/shapes/torus.h"

namespace toroid {

namespace {

// A shape without keys of its own.
template <class S>
std::shared_ptr<Shape> plain(ShapeItem& item) {
  item.begin();
  return std::make_shared<S>();
}

// Cylinders and cones: `min`/`max` truncate, `closed` caps.
template <class S>
std::shared_ptr<Shape> truncated(ShapeItem& item) {
  const Param min = item.params.get("min"), max = item.params.get("max"), closed = item.params.get("closed");
  item.begin();
  auto s = std::make_shared<S>();
  if (min) s->minimum = min.number();
  if (max) s->maximum = max.number();
  if (closed) s->closed = closed.boolean();
  if (min && max && !(s->minimum < s->maximum)) item.state.reader.fail(max.value(), "'max' must be greater than 'min'");
  return s;
}

// The shortest text that reads back as v.
std::string shortest(double v) {
  char buf[32];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, res.ptr);
}

TorusRadii torus_radii(const Param& major, const Param& minor) {
  const Torus defaults;
  return {major ? major.positive("torus 'major'") : defaults.major(),
          minor ? minor.positive("torus 'minor'") : defaults.minor()};
}

// RenderMan's partial torus: `theta-max` in (0, 2 pi], `phi-min` < `phi-max`
// within [-2 pi, 2 pi] and at most 2 pi apart (radians). Values within 1e-4
// beyond a limit (6.2832 for 2 pi) are taken as the limit.
TorusSweep torus_sweep(const SceneReader& r, const Param& theta_max, const Param& lo, const Param& hi) {
  constexpr double kTwoPi = TorusSweep::kTwoPi, kSlack = 1e-4;
  TorusSweep sw;
  if (theta_max) {
    sw.theta_max = theta_max.number();
    if (!(sw.theta_max > 0 && sw.theta_max <= kTwoPi + kSlack))
      r.fail(theta_max.value(), "torus 'theta-max' must be in (0, 2 pi] radians, got " + theta_max.value().Scalar());
    sw.theta_max = std::min(sw.theta_max, kTwoPi);
  }
  for (const Param* e : {&lo, &hi}) {
    if (!*e) continue;
    const double v = e->number();
    if (std::abs(v) > kTwoPi + kSlack)
      r.fail(e->value(), "torus '" + e->key() + "' must be in [-2 pi, 2 pi] radians, got " + e->value().Scalar());
    (e == &lo ? sw.phi_min : sw.phi_max) = std::clamp(v, -kTwoPi, kTwoPi);
  }
  const YAML::Node where = hi ? hi.value() : lo ? lo.value() : YAML::Node();
  if (!(sw.phi_min < sw.phi_max))
    r.fail(where, "torus 'phi-max' must be greater than 'phi-min' (" + std::to_string(sw.phi_max) +
                      " <= " + std::to_string(sw.phi_min) + ")");
  if (sw.phi_max - sw.phi_min > kTwoPi + kSlack)
    r.fail(where, "torus 'phi-max' - 'phi-min' must be at most 2 pi radians");
  sw.phi_max = std::min(sw.phi_max, sw.phi_min + kTwoPi);
  return sw;
}

std::shared_ptr<Shape> torus(ShapeItem& item) {
  ItemParams& p = item.params;
  const Param major = p.get("major"), minor = p.get("minor"), solver = p.get("solver");
  const Param theta_max = p.get("theta-max"), phi_min = p.get("phi-min"), phi_max = p.get("phi-max");
  const Param spindle = p.get("spindle"), caps = p.get("caps");
  item.begin([&] { return torus_radii(major, minor); });
  const SceneReader& r = item.state.reader;
  const TorusRadii radii = torus_radii(major, minor);
  auto t = std::make_shared<Torus>(radii.major, radii.minor);
  if (solver) {
    const std::string name = solver.name("solver");
    const auto sv = solver_from_name(name);
    if (!sv)
      r.fail(solver.value(), "unknown solver '" + name + "' (use default, ferrari or tianheng)" +
                                 suggestion(name, {"default", "ferrari", "tianheng"}));
    t->set_solver(*sv);
  }
  if (item.state.options.solver) t->set_solver(*item.state.options.solver);
  t->set_sweep(torus_sweep(r, theta_max, phi_min, phi_max));
  if (spindle) {
    const std::string v = spindle.name("spindle");
    if (v != "whole" && v != "outer")
      r.fail(spindle.value(),
             "unknown spindle surface '" + v + "' (use whole or outer)" + suggestion(v, {"whole", "outer"}));
    t->set_spindle(v == "outer" ? SpindleSurface::Outer : SpindleSurface::Whole);
  }
  // `caps: true` closes a partial torus's cuts (Torus::set_caps); a whole
  // torus is closed already. A partial spindle torus cannot be closed by
  // discs: an error rather than an open shape.
  if (caps && caps.boolean()) {
    if (!t->sweep().whole() && radii.minor > radii.major)
      r.fail(caps.value(), "torus 'caps' needs minor <= major on a partial torus (minor " + shortest(radii.minor) +
                               " > major " + shortest(radii.major) + "): a spindle torus's cut faces cross its axis");
    t->set_caps(true);
  }
  return t;
}

std::shared_ptr<Shape> group(ShapeItem& item) {
  const Param children = item.params.get("children");
  item.begin();
  auto g = std::make_shared<Group>();
  if (children) {
    if (!children.value().IsSequence())
      item.state.reader.fail(children.value(),
                             "'children' must be a list of shapes, got " + describe(children.value()));
    for (const YAML::Node& child : children.value()) g->add_child(item.child(child, false));
  }
  return g;
}

std::shared_ptr<Shape> csg(ShapeItem& item) {
  const Param operation = item.params.get("operation"), left = item.params.get("left"),
              right = item.params.get("right");
  item.begin();
  const SceneReader& r = item.state.reader;
  const std::string o = r.name(operation.need("a csg"), "operation");
  CsgOp op;
  if (o == "union")
    op = CsgOp::Union;
  else if (o == "intersection")
    op = CsgOp::Intersection;
  else if (o == "difference")
    op = CsgOp::Difference;
  else
    r.fail(operation.value(), "unknown csg operation '" + o + "'" +
                                  suggestion(o, {"union", "intersection", "difference"}) +
                                  " (use union, intersection or difference)");
  if (!left || !right)
    r.fail(item.kind_node,
           std::string("a csg needs both 'left' and 'right' operands (missing '") + (!left ? "left" : "right") + "')");
  auto l = item.child(left.value(), true);
  auto rt = item.child(right.value(), true);
  return std::make_shared<Csg>(op, std::move(l), std::move(rt));
}

std::shared_ptr<Shape> obj(ShapeItem& item) {
  const Param file_param = item.params.get("file");
  item.begin();
  const SceneReader& r = item.state.reader;
  const YAML::Node& f = file_param.need("an obj");
  const std::string file = r.name(f, "file");
  const std::filesystem::path p = resolve(item.state, file);
  if (!std::filesystem::exists(p)) fail_not_found(item.state, f, "OBJ", file, p);
  item.material_to_descendants = true;
  try {
    return load_obj(p);
  } catch (const std::exception& e) {
    r.fail(f, "cannot load OBJ file '" + file + "': " + e.what());
  }
}

constexpr NamedBuilder<ShapeBuild> kShapes[] = {
    {"sphere", plain<Sphere>}, {"plane", plain<Plane>}, {"cube", plain<Cube>}, {"cylinder", truncated<Cylinder>},
    {"cone", truncated<Cone>}, {"group", group},        {"csg", csg},          {"obj", obj},
    {"torus", torus},
};

}  // namespace

std::span<const NamedBuilder<ShapeBuild>> shape_builders() { return kShapes; }

}  // namespace toroid
