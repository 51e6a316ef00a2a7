// SPDX-License-Identifier: Apache-2.0
// The torus shape: ring in the object's xy-plane, axis z, centred at the
// origin; `major` (R) to the tube's centre, `minor` (r) the tube's radius.
// All math lives in torus_intersect.h; this class adapts it to Shape and adds
// RenderMan's partial tori (RiTorus's thetamax, phimin, phimax), caps that
// close a partial torus into a solid, and the choice of a spindle torus's
// surface.
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

// The faces of a capped partial torus; a hit's face travels in its
// Intersection (Torus::face_of). The tube is the torus's own surface; the
// others are the caps.
enum class TorusFace : std::uint8_t {
  Tube,
  ThetaStart,  // the disc in the meridian plane theta = 0
  ThetaEnd,    // the disc in the meridian plane theta = theta_max
  PhiMin,      // the cone (annulus, cylinder) swept by the tube's radius at phi_min
  PhiMax,      // ... at phi_max
};

// The most intersections of a torus along a ray: the quartic's 4 roots; with
// caps also one on each theta cap and two on each phi cap.
inline constexpr int kMaxTorusHits = 10;

class Torus : public Primitive<Torus, kMaxTorusHits> {
 public:
  // The tube's hits alone (the quartic's roots).
  static constexpr int kMaxTubeHits = 4;

  // Precondition: major > 0, minor > 0, both finite (the scene loader checks).
  Torus(double major = 1.0, double minor = 0.25) : major_(major), minor_(minor) {}

  double major() const { return major_; }
  double minor() const { return minor_; }
  void set_solver(TorusSolver s) { solver_ = s; }
  TorusSolver solver() const { return solver_; }

  // Precondition: sweep.valid().
  void set_sweep(const TorusSweep& sweep);
  const TorusSweep& sweep() const { return partial_ ? partial_->sweep : kWholeSweep; }
  void set_spindle(SpindleSurface s);
  SpindleSurface spindle() const { return spindle_; }

  // Caps close each cut of a partial torus, so that it bounds a solid: the
  // points within the tube (distance <= minor from the centre circle) whose
  // theta and phi (torus_angles) lie in the sweep. A theta cut is closed by
  // the tube's disc in the meridian plane at theta = 0 or theta_max (its
  // sector within [phi_min, phi_max] when phi is cut too); a phi cut by the
  // surface the tube's radius at that phi sweeps from the centre circle out
  // to the tube (a cone; an annulus at phi = 0 or +-pi, a cylinder at +-pi/2)
  // for theta in [0, theta_max]. Normals point out of the solid. The torus
  // uv map (toroidal_map) gives a cap's point the uv of the rim point
  // straight out from the centre circle (a theta cap: the cut's u, and v the
  // point's angle about the disc's centre; a phi cap: its own u and the cut's
  // v), so that a texture runs on across the rim. On a whole torus (closed
  // already) caps change nothing. A spindle torus (minor > major) is not
  // capped: its cut discs would cross the axis into the other side of the
  // tube (the scene loader rejects caps on a partial one).
  void set_caps(bool on);
  bool caps() const { return caps_; }
  // Whether caps are in effect: asked for, a partial sweep, minor <= major.
  bool capped() const { return capped_; }
  bool closed_surface() const override { return partial_ == nullptr || capped_; }
  // The face a hit of this torus lies on (the tube unless capped).
  static TorusFace face_of(const Intersection& hit) { return static_cast<TorusFace>(static_cast<int>(hit.u)); }

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
  // re-enter the same torus. A partial torus is an open surface unless it is
  // capped: a ray through an open edge meets its inside. A capped torus adds
  // its caps' hits, each with its face in Intersection::u (face_of), all
  // sorted by t. Returns how many (at most kMaxHits).
  int find_hits(const Ray& ray, Intersection hits[kMaxHits]) const;
  // The tube's normal, or a cap's outward normal for a hit on a cap.
  Tuple local_normal_at(const Tuple& p, const Intersection& hit) const override;
  // The solver's nearest-root query (no list, early exit) when every root is
  // kept; a partial torus filters find_hits instead.
  bool local_intersect_nearest(const Ray& ray, double t_max, Intersection& hit) const override;
  bool local_blocks(const Ray& ray, double t_max) const override;

 private:
  // The partial sweep with the sines and cosines of its cuts (for the caps).
  struct Partial {
    TorusSweep sweep;
    double cos_theta_max, sin_theta_max;
    double cos_phi[2], sin_phi[2];  // phi_min, phi_max
  };

  // Whether the ray may meet the solid torus in (t_min, t_max). The closed
  // forms run only for rays that meet its bounding washer; the default
  // solver turns away the others itself, more tightly (the ball, the slab
  // and the hole, torus/hole.h), so for it this is true.
  bool may_meet(const Ray& ray, double t_min, double t_max) const;
  bool nearest_root(const Ray& ray, double t_max, double& t) const;
  // The kept roots, sorted (find_hits without the caps).
  int tube_hits(const Ray& ray, Intersection hits[kMaxTubeHits]) const;
  // Appends the caps' hits to hits[0, n) and sorts them all by t.
  int add_cap_hits(const Ray& ray, Intersection hits[kMaxHits], int n) const;
  // The outward normal of a cap.
  Tuple cap_normal(const Tuple& p, TorusFace face) const;
  void update_flags();

  // The one-byte fields first: they fit in the tail padding of Shape
  // (sizeof matters, scenes hold thousands of tori).
  TorusSolver solver_ = TorusSolver::Default;
  SpindleSurface spindle_ = SpindleSurface::Whole;
  bool keeps_all_ = true;  // whole sweep and whole surface: no root test
  bool caps_ = false;      // asked for (set_caps)
  bool capped_ = false;    // in effect (capped())
  double major_, minor_;
  // The sweep, held apart when it is partial (rare): a whole torus stays at
  // 152 bytes, 168 with make_shared's control block (docs/performance.md).
  std::unique_ptr<const Partial> partial_;
  static constexpr TorusSweep kWholeSweep{};
};

}  // namespace toroid
