// SPDX-License-Identifier: Apache-2.0
// Shadow acne, light leaks and black pixels on tori at every scale.
//
// Each case renders a small image of a torus (ring in its xy-plane) lying on
// a plane, lit by a point light on its axis, with a sphere on the axis between
// them. Whether a point is lit has a closed form here, independent of the
// renderer's shadow rays:
//  - on the torus: lit iff n.l > 0 and the segment to the light misses the
//    sphere (the light is on the axis, so the segment stays in the meridian
//    plane, where the torus is two discs; it leaves the convex disc it starts
//    on and never reaches the other);
//  - on the plane: lit iff the segment misses the sphere and, in the meridian
//    plane, passes farther than r from the tube's centre (R, 0).
// Every pixel whose first hit is the torus or the plane is classified this
// way (pixels within a margin of a shadow boundary or the terminator are
// skipped) and its rendered colour must agree: the ambient colour exactly
// where shadowed, clearly more where lit. Acne (lit points rendered
// shadowed), leaks (shadowed points rendered lit) and black pixels are
// counted; every count must be zero.
//
// The glass cases render a glass torus over a checkered plane inside a sky
// sphere at several scales and positions; the image must be the same as at
// unit scale (the scene is the same up to a similarity) and have no black
// pixel.
//
// Set TOROID_STRESS_IMAGES=DIR to write each image (and, for the lit cases, a
// mask: red = acne, blue = leak, green = checked) to DIR for inspection.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <numbers>
#include <string>

#include "toroid/io/image_writer.h"
#include "toroid/math/transform.h"
#include "toroid/render/camera.h"
#include "toroid/render/pattern.h"
#include "toroid/render/world.h"
#include "toroid/shapes/plane.h"
#include "toroid/shapes/sphere.h"
#include "toroid/shapes/torus.h"
#include "toroid/torus/surface.h"

namespace toroid {
namespace {

struct StressCase {
  const char* name;
  double major, minor;  // R, r
  Tuple offset;         // the whole scene moves by this
  // The camera looks at `target` (a point of the torus frame, in units of R)
  // from `distance` (in units of R) away, seeing `view` (in units of R)
  // across.
  Tuple target;
  double distance, view;
};

std::ostream& operator<<(std::ostream& os, const StressCase& c) { return os << c.name; }

// The camera's side of the scene: above the ring, from the right and front.
const Tuple kViewDirection = normalize(vector(0.9, -1.0, 1.1));

constexpr int kWidth = 96, kHeight = 72;

// Where the pieces go, in the torus frame (R = major).
struct Layout {
  double R, r;
  Tuple offset;
  Tuple light;    // on the axis
  Tuple blocker;  // sphere centre, on the axis
  double blocker_radius;
};

// p moved by the offset (a point: offset.w is 1).
Tuple shifted(const Tuple& p, const Tuple& offset) { return point(p.x + offset.x, p.y + offset.y, p.z + offset.z); }

Layout layout_of(const StressCase& c) {
  Layout l{c.major, c.minor, c.offset, point(0, 0, 3 * c.major), point(0, 0, 2 * c.major), 0};
  // The sphere's shadow reaches out to rho = R on the plane z = 0: inner half
  // of the tube shadowed, outer half lit.
  const double half_angle = std::atan(c.major / (3 * c.major));
  l.blocker_radius = (l.light.z - l.blocker.z) * std::sin(half_angle);
  return l;
}

Material matte(const Color& c) {
  Material m;
  m.color = c;
  m.ambient = 0.1;
  m.diffuse = 0.9;
  m.specular = 0;
  return m;
}

const Color kTorusColor{1, 0.5, 0.3};
const Color kPlaneColor{0.8, 0.8, 0.8};

World lit_world(const Layout& l) {
  World w;
  w.lights.push_back({shifted(l.light, l.offset), Color{1, 1, 1}});
  auto torus = std::make_shared<Torus>(l.R, l.r);
  torus->set_transform(translation(l.offset.x, l.offset.y, l.offset.z));
  torus->set_material(matte(kTorusColor));
  auto plane = std::make_shared<Plane>();  // touches the torus from below
  plane->set_transform(translation(l.offset.x, l.offset.y, l.offset.z - l.r) * rotation_x(std::numbers::pi / 2));
  plane->set_material(matte(kPlaneColor));
  auto sphere = std::make_shared<Sphere>();
  sphere->set_transform(translation(l.offset.x + l.blocker.x, l.offset.y + l.blocker.y, l.offset.z + l.blocker.z) *
                        scaling(l.blocker_radius, l.blocker_radius, l.blocker_radius));
  sphere->set_material(matte(Color{0.3, 0.6, 0.9}));
  w.objects = {torus, plane, sphere};
  return w;
}

Camera camera_for(const StressCase& c, int width = kWidth, int height = kHeight) {
  const Tuple target = point(c.target.x * c.major, c.target.y * c.major, c.target.z * c.major);
  const Tuple to = shifted(target, c.offset);
  const Tuple from = to + kViewDirection * (c.distance * c.major);
  Camera cam(width, height, 2 * std::atan(0.5 * c.view / c.distance));
  cam.set_transform(view_transform(from, to, vector(0, 0, 1)));
  return cam;
}

// Distance from point c to the segment [a, b].
double segment_distance(const Tuple& a, const Tuple& b, const Tuple& c) {
  const Tuple ab = b - a;
  const double s = std::clamp(dot(c - a, ab) / dot(ab, ab), 0.0, 1.0);
  return magnitude(a + ab * s - c);
}

enum class Expect { Lit, Shadowed, Unsure };

// Analytic lighting of a point q (torus frame) on the torus or the plane.
Expect expected_light(const Layout& l, const Tuple& q, bool on_torus) {
  // Points this close to a shadow's edge (a fiftieth of the tube's radius)
  // are not judged: far more than any bias should move the edge, and far
  // less than the tube, so a thin tube still has pixels on both sides.
  const double margin = 0.02 * l.r;
  const double to_sphere = segment_distance(q, l.light, l.blocker);
  if (std::abs(to_sphere - l.blocker_radius) < margin) return Expect::Unsure;
  const bool behind_sphere = to_sphere < l.blocker_radius;
  if (on_torus) {
    const double p[3] = {q.x, q.y, q.z};
    double n[3];
    torus_normal(l.R, l.r, p, n);
    const double n_dot_l = dot(normalize(vector(n[0], n[1], n[2])), normalize(l.light - q));
    if (std::abs(n_dot_l) < 0.05) return Expect::Unsure;
    return n_dot_l > 0 && !behind_sphere ? Expect::Lit : Expect::Shadowed;
  }
  // Meridian plane: (rho, z) from (rho_q, z_q) to the light at (0, L).
  const double rho = std::hypot(q.x, q.y);
  const double to_tube = segment_distance(point(rho, q.z, 0), point(0, l.light.z, 0), point(l.R, 0, 0));
  if (std::abs(to_tube - l.r) < margin) return Expect::Unsure;
  return to_tube > l.r && !behind_sphere ? Expect::Lit : Expect::Shadowed;
}

std::string image_dir() {
  const char* d = std::getenv("TOROID_STRESS_IMAGES");
  return d ? d : "";
}

struct Counts {
  int lit = 0, shadowed = 0;  // checked pixels of each kind
  int acne = 0, leaks = 0, black = 0;
};

Counts check_lit_case(const StressCase& c, Counts* plane_counts) {
  const Layout l = layout_of(c);
  const World world = lit_world(l);
  const Camera cam = camera_for(c);
  const Shape* torus = world.objects[0].get();
  const Shape* plane = world.objects[1].get();
  Counts on_torus;
  Canvas image(kWidth, kHeight), mask(kWidth, kHeight);
  Intersections xs;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const Ray ray = cam.ray_for_pixel(x, y);
      const Color rendered = color_at(world, ray);
      image.write_pixel(x, y, rendered);
      Counts* counts = nullptr;
      if (rendered.r == 0 && rendered.g == 0 && rendered.b == 0) ++on_torus.black;
      intersect_world(world, ray, xs);
      const Intersection* h = hit(xs);
      if (h == nullptr) continue;
      const Color* base = nullptr;
      if (h->object == torus) counts = &on_torus, base = &kTorusColor;
      if (h->object == plane) counts = plane_counts, base = &kPlaneColor;
      if (counts == nullptr) continue;
      const Tuple p = ray.position(h->t);
      const Tuple q = point(p.x - c.offset.x, p.y - c.offset.y, p.z - c.offset.z);
      const Expect e = expected_light(l, q, h->object == torus);
      if (e == Expect::Unsure) continue;
      const double ambient_only = 0.1 * base->r;
      const bool renders_shadowed = std::abs(rendered.r - ambient_only) < 1e-9 * base->r;
      const bool renders_lit = rendered.r > ambient_only + 0.02 * base->r;
      if (e == Expect::Lit) {
        ++counts->lit;
        if (!renders_lit) ++counts->acne;
      } else {
        ++counts->shadowed;
        if (!renders_shadowed) ++counts->leaks;
      }
      const bool bad = (e == Expect::Lit) != renders_lit || (e == Expect::Shadowed) != renders_shadowed;
      mask.write_pixel(x, y, bad ? (e == Expect::Lit ? Color{1, 0, 0} : Color{0, 0, 1}) : Color{0, 0.4, 0});
    }
  if (const std::string dir = image_dir(); !dir.empty()) {
    write_image(image, dir + "/lit-" + c.name + ".png");
    write_image(mask, dir + "/lit-" + c.name + "-mask.png");
  }
  return on_torus;
}

// Far: thousands of radii away, narrow field of view. Thin: r/R = 1e-3, the
// camera close to one stretch of the tube. Offsets move everything far from
// the origin, where the hit points' coordinates round coarsely.
const StressCase kLitCases[] = {
    {"unit", 1, 0.25, point(0, 0, 0), point(0, 0, 0), 6, 3.2},
    {"far_camera", 1, 0.25, point(0, 0, 0), point(0, 0, 0), 5000, 3.2},
    {"huge", 1e4, 2.5e3, point(0, 0, 0), point(0, 0, 0), 6, 3.2},
    {"tiny", 1e-3, 2.5e-4, point(0, 0, 0), point(0, 0, 0), 6, 3.2},
    {"thin", 1, 1e-3, point(0, 0, 0), point(1, 0, 0), 0.03, 0.012},
    {"thin_far_camera", 1, 1e-3, point(0, 0, 0), point(1, 0, 0), 3000, 0.012},
    {"thin_tiny", 1e-3, 1e-6, point(0, 0, 0), point(1, 0, 0), 0.03, 0.012},
    {"thin_huge", 1e4, 10, point(0, 0, 0), point(1, 0, 0), 0.03, 0.012},
    {"offset_1e6", 1, 0.25, point(1e6, -2e6, 1.5e6), point(0, 0, 0), 6, 3.2},
    {"offset_1e10", 1, 0.25, point(1e10, -2e10, 1.5e10), point(0, 0, 0), 6, 3.2},
    {"offset_1e12", 1, 0.25, point(1e12, -2e12, 1.5e12), point(0, 0, 0), 6, 3.2},
    {"huge_1e12", 1e12, 2.5e11, point(0, 0, 0), point(0, 0, 0), 6, 3.2},
    {"far_camera_1e7", 1, 0.25, point(0, 0, 0), point(0, 0, 0), 1e7, 3.2},
};

class TorusShadowAcne : public testing::TestWithParam<StressCase> {};

TEST_P(TorusShadowAcne, LitWhereTheGeometrySaysLitAndNoBlackPixels) {
  Counts plane;
  const Counts torus = check_lit_case(GetParam(), &plane);
  // The picture shows what it is meant to: both kinds of pixel on both.
  EXPECT_GE(torus.lit, 300);
  EXPECT_GE(torus.shadowed, 300);
  EXPECT_GE(plane.lit + plane.shadowed, 100);
  EXPECT_EQ(torus.acne, 0) << "torus pixels rendered in shadow where the light reaches them";
  EXPECT_EQ(torus.leaks, 0) << "torus pixels rendered lit where the light is blocked";
  EXPECT_EQ(plane.acne, 0) << "plane pixels rendered in shadow where the light reaches them";
  EXPECT_EQ(plane.leaks, 0) << "plane pixels rendered lit where the torus or sphere blocks the light";
  EXPECT_EQ(torus.black, 0) << "black pixels (nothing in view should be black)";
}

INSTANTIATE_TEST_SUITE_P(Scales, TorusShadowAcne, testing::ValuesIn(kLitCases),
                         [](const testing::TestParamInfo<StressCase>& i) { return std::string(i.param.name); });

// --- glass ------------------------------------------------------------------

// A glass torus floating over a checkered plane, inside a sky sphere (so no
// ray can leave the scene and come back black), with the light off to one
// side. Everything scales with R and the case's view.
World glass_world(const StressCase& c) {
  const double R = c.major;
  const Tuple& o = c.offset;
  World w;
  w.lights.push_back({shifted(point(2 * R, -3 * R, 4 * R), o), Color{1, 1, 1}});
  auto torus = std::make_shared<Torus>(R, c.minor);
  torus->set_transform(translation(o.x, o.y, o.z));
  Material torus_material = torus->material();
  torus_material.color = Color{0.1, 0.1, 0.12};
  torus_material.ambient = 0.05;
  torus_material.diffuse = 0.1;
  torus_material.specular = 1;
  torus_material.shininess = 300;
  torus_material.reflective = 0.9;
  torus_material.transparency = 0.9;
  torus_material.refractive_index = 1.5;
  torus->set_material(torus_material);
  auto plane = std::make_shared<Plane>();
  const double floor = -c.minor - 0.1 * c.view * R;
  plane->set_transform(translation(o.x, o.y, o.z + floor) * rotation_x(std::numbers::pi / 2));
  Material plane_material = matte(Color{1, 1, 1});
  // A twelfth of the view per tile, offset by a third of a tile so that no
  // tile edge runs through the torus's centre.
  const double tile = c.view / 12 * R;
  auto checkers = std::make_shared<CheckersPattern>(Color{0.9, 0.85, 0.7}, Color{0.25, 0.3, 0.45});
  checkers->set_transform(scaling(tile, tile, tile) * translation(1.0 / 3, 1.0 / 3, 1.0 / 3));
  plane_material.pattern = checkers;
  plane->set_material(plane_material);
  auto sky = std::make_shared<Sphere>();
  const double sky_radius = 2 * std::max(c.distance, 25.0) * R;  // the camera is inside
  sky->set_transform(translation(o.x, o.y, o.z) * scaling(sky_radius, sky_radius, sky_radius));
  Material sky_material = matte(Color{0.55, 0.7, 0.9});
  sky_material.ambient = 1;
  sky_material.diffuse = 0;
  sky->set_material(sky_material);
  sky->casts_shadow = false;
  w.objects = {torus, plane, sky};
  return w;
}

Canvas render_glass(const StressCase& c) {
  const World world = glass_world(c);
  const Camera cam = camera_for(c);
  Canvas image(kWidth, kHeight);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) image.write_pixel(x, y, color_at(world, cam.ray_for_pixel(x, y)));
  if (const std::string dir = image_dir(); !dir.empty()) write_image(image, dir + "/glass-" + c.name + ".png");
  return image;
}

double channel_difference(const Color& a, const Color& b) {
  return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

int black_pixels(const Canvas& image) {
  int n = 0;
  for (const Color& p : image.pixels()) n += std::max({p.r, p.g, p.b}) < 0.01;
  return n;
}

// The same scene, scaled by `scale` and moved by `offset` (in units of R).
StressCase scaled(const StressCase& base, const char* name, double scale, const Tuple& offset) {
  StressCase c = base;
  c.name = name;
  c.major *= scale;
  c.minor *= scale;
  c.offset = point(offset.x * c.major, offset.y * c.major, offset.z * c.major);
  return c;
}

struct GlassCase {
  StressCase base;
  // How much of the image may differ (silhouettes and tile edges whose
  // pixel centres round to the other side); the rest must match.
  double tolerated_fraction;
};

std::ostream& operator<<(std::ostream& os, const GlassCase& c) { return os << c.base.name; }

class GlassTorusAtEveryScale : public testing::TestWithParam<GlassCase> {};

TEST_P(GlassTorusAtEveryScale, LooksTheSameAndHasNoBlackPixels) {
  const StressCase& base = GetParam().base;
  const Canvas reference = render_glass(base);
  EXPECT_EQ(black_pixels(reference), 0) << base.name;
  const std::string prefix = std::string(base.name) + "_";
  const std::string names[] = {prefix + "tiny", prefix + "huge", prefix + "offset"};
  const StressCase variants[] = {
      scaled(base, names[0].c_str(), 1e-3, point(0, 0, 0)),
      scaled(base, names[1].c_str(), 1e4, point(0, 0, 0)),
      scaled(base, names[2].c_str(), 1, point(3e6, -1e6, 2e6)),
  };
  for (const StressCase& v : variants) {
    const Canvas image = render_glass(v);
    EXPECT_EQ(black_pixels(image), 0) << v.name;
    int differing = 0;
    for (std::size_t i = 0; i < image.pixels().size(); ++i)
      differing += channel_difference(image.pixels()[i], reference.pixels()[i]) > 0.02;
    EXPECT_LE(differing, GetParam().tolerated_fraction * kWidth * kHeight)
        << v.name << ": " << differing << " pixels differ from " << base.name;
  }
}

const GlassCase kGlassCases[] = {
    {{"unit", 1, 0.25, point(0, 0, 0), point(0, 0, 0), 6, 3.2}, 0.002},
    {{"thin", 1, 1e-3, point(0, 0, 0), point(1, 0, 0), 0.03, 0.012}, 0.002},
    {{"far_camera", 1, 0.25, point(0, 0, 0), point(0, 0, 0), 5000, 3.2}, 0.002},
};

INSTANTIATE_TEST_SUITE_P(Scales, GlassTorusAtEveryScale, testing::ValuesIn(kGlassCases),
                         [](const testing::TestParamInfo<GlassCase>& i) { return std::string(i.param.base.name); });

}  // namespace
}  // namespace toroid
