// SPDX-License-Identifier: Apache-2.0
// The torus shape: ring in the object's xy-plane, axis z, centred at the
// origin; `major` (R) to the tube's centre, `minor` (r) the tube's radius.
// All math lives in torus_intersect.h; this class adapts it to Shape and adds
// RenderMan's partial tori (RiTorus's thetamax, phimin, phimax) and the choice
// of a spindle torus's surface.
#pragma once

#include <cstdint>
#include <memory>
#include <numbers>

#include "toroid/shapes/annular_cylinder.h"
#include "toroid/shapes/primitive.h"
#include "toroid/torus/solver.h"

namespace toroid {

// Which part of a spindle torus's (minor > major) quartic surface is kept:
// all of it, or the outer sheet only (the inner "lemon" removed).
enum class SpindleSurface : std::uint8_t { Whole, Outer };

// The swept part of the surface, in the angles of torus_angles(): theta
// around the z axis from +x towards +y, phi around the tube from the outer
// equator towards +z. A point is kept when theta <= theta_max and phi (or
// phi +- 2 pi) lies in [phi_min, phi_max].
struct TorusSweep {
  static constexpr double kTwoPi = 2 * std::numbers::pi;
  double theta_max = kTwoPi;
  double phi_min = -std::numbers::pi;
  double phi_max = std::numbers::pi;

  // 0 < theta_max <= 2 pi; -2 pi <= phi_min < phi_max <= 2 pi; phi_max -
  // phi_min <= 2 pi; all finite.
  bool valid() const;
  bool whole() const { return theta_max >= kTwoPi && phi_max - phi_min >= kTwoPi; }
};

class Torus : public Primitive<Torus> {
 public:
  // Precondition: major > 0, minor > 0, both finite (the scene loader checks).
  Torus(double major = 1.0, double minor = 0.25) : major_(major), minor_(minor) {}

  double major() const { return major_; }
  double minor() const { return minor_; }
  void set_solver(TorusSolver s) { solver_ = s; }
  TorusSolver solver() const { return solver_; }

  // Precondition: sweep.valid().
  void set_sweep(const TorusSweep& sweep);
  const TorusSweep& sweep() const { return partial_ ? *partial_ : kWholeSweep; }
  void set_spindle(SpindleSurface s);
  SpindleSurface spindle() const { return spindle_; }

  // Whether a point on the quartic's surface belongs to this torus (the sweep
  // and the spindle choice).
  bool keeps(const Tuple& surface_point) const;

  // The box of the kept part (exact for the swept angles' ranges).
  BoundingBox bounds() const override;
  // A whole torus's exact box under any affine transform; a rotated torus's
  // object box, transformed, is up to ~40% wider on an axis.
  BoundingBox parent_space_bounds() const override;
  // The tube radius for a whole torus (its box is 2r thick), without the
  // box's trigonometry: it is asked at every hit.
  double half_thickness() const override;
  // Every kept root (sorted), so CSG and refraction see the ray leave and
  // re-enter the same torus. A partial torus is an open surface: a ray
  // through an open edge meets its inside.
  int find_hits(const Ray& ray, Intersection hits[kMaxHits]) const;
  Tuple local_normal_at(const Tuple& p, const Intersection& hit) const override;
  // The solver's nearest-root query (no list, early exit) when every root is
  // kept; a partial torus filters find_hits instead.
  bool local_intersect_nearest(const Ray& ray, double t_max, Intersection& hit) const override;
  bool local_blocks(const Ray& ray, double t_max) const override;

 private:
  // The bounding washer: the solver runs only for rays that may meet it.
  AnnularCylinder washer() const;
  bool nearest_root(const Ray& ray, double t_max, double& t) const;

  // The one-byte fields first: they fit in the tail padding of Shape
  // (sizeof matters, scenes hold thousands of tori).
  TorusSolver solver_ = TorusSolver::Default;
  SpindleSurface spindle_ = SpindleSurface::Whole;
  bool keeps_all_ = true;  // whole sweep and whole surface: no root test
  double major_, minor_;
  // The sweep, held apart when it is partial (rare): a whole torus stays at
  // 152 bytes, 168 with make_shared's control block (docs/performance.md).
  std::unique_ptr<const TorusSweep> partial_;
  static constexpr TorusSweep kWholeSweep{};
};

}  // namespace toroid
