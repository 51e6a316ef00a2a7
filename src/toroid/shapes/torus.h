// The torus shape: ring in the object's xy-plane, axis z, centred at the
// origin; `major` (R) to the tube's centre, `minor` (r) the tube's radius.
// All math lives in torus_intersect.h; this class adapts it to Shape.
#pragma once

#include "toroid/roots/quartic.h"
#include "toroid/shapes/annular_cylinder.h"
#include "toroid/shapes/primitive.h"

namespace toroid {

class Torus : public Primitive {
 public:
  // Precondition: major > 0, minor > 0, both finite (the scene loader checks).
  Torus(double major = 1.0, double minor = 0.25) : major_(major), minor_(minor) {}

  double major() const { return major_; }
  double minor() const { return minor_; }
  void set_solver(QuarticSolver s) { solver_ = s; }
  QuarticSolver solver() const { return solver_; }

  BoundingBox bounds() const override;
  // Every real root (sorted), so CSG and refraction see the ray leave and
  // re-enter the same torus.
  int local_hits(const Ray& ray, Intersection hits[kMaxHits]) const override;
  Tuple local_normal_at(const Tuple& p, const Intersection& hit) const override;
  // The solver's nearest-root query: no list, early exit.
  bool local_intersect_nearest(const Ray& ray, double t_max, Intersection& hit) const override;
  bool local_blocks(const Ray& ray, double t_max) const override;

 private:
  // The bounding washer: the solver runs only for rays that may meet it.
  AnnularCylinder washer() const;
  bool nearest_root(const Ray& ray, double t_max, double& t) const;

  // The solver first: it fits in the tail padding of Shape (sizeof matters,
  // scenes hold thousands of tori).
  QuarticSolver solver_ = QuarticSolver::Default;
  double major_, minor_;
};

}  // namespace toroid
