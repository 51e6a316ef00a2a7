// The torus shape: ring in the object's xy-plane, axis z, centred at the
// origin; `major` (R) to the tube's centre, `minor` (r) the tube's radius.
// All math lives in torus_intersect.h; this class adapts it to Shape.
#pragma once

#include "toroid/roots/quartic.h"
#include "toroid/shapes/shape.h"

namespace toroid {

class Torus : public Shape {
 public:
  // Precondition: major > 0, minor > 0, both finite (the scene loader checks).
  Torus(double major = 1.0, double minor = 0.25) : major_(major), minor_(minor) {}

  double major() const { return major_; }
  double minor() const { return minor_; }
  void set_solver(QuarticSolver s) { solver_ = s; }
  QuarticSolver solver() const { return solver_; }

  BoundingBox bounds() const override;
  // Appends every real root (sorted), so CSG and refraction see the ray
  // leave and re-enter the same torus.
  void local_intersect(const Ray& ray, Intersections& xs) const override;
  Tuple local_normal_at(const Tuple& p, const Intersection& hit) const override;

 private:
  double major_, minor_;
  QuarticSolver solver_ = QuarticSolver::Default;
};

}  // namespace toroid
