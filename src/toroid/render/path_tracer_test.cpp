// SPDX-License-Identifier: Apache-2.0
// The path integrator against closed forms: furnaces (a closed or convex
// object in a uniform environment), a point light over a diffuse plane, an
// area light's irradiance; its convergence rate, its determinism, and the
// book's renderer's additions (environment, emission).
#include "toroid/render/path_tracer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "toroid/math/transform.h"
#include "toroid/render/camera.h"
#include "toroid/render/renderer.h"
#include "toroid/render/world.h"
#include "toroid/shapes/plane.h"
#include "toroid/shapes/sphere.h"
#include "toroid/shapes/torus.h"

namespace toroid {
namespace {

constexpr double kPi = std::numbers::pi;

Material matte(const Color& albedo) {
  Material m;
  m.color = albedo;
  m.diffuse = 1;
  m.specular = 0;
  return m;
}

// A torus (R = 1, r = 0.45) tipped towards the camera, so that the camera
// sees into its hole and onto its inner faces, where rays bounce more than
// once.
std::shared_ptr<Torus> tipped_torus(const Material& m) {
  auto t = std::make_shared<Torus>(1.0, 0.45);
  t->set_transform(rotation_x(0.9));
  t->set_material(m);
  return t;
}

World world_of(std::vector<std::shared_ptr<Shape>> shapes, const Color& environment = kBlack) {
  World w;
  w.objects = std::move(shapes);
  w.environment.color = environment;
  index_objects(w);
  return w;
}

Camera looking_at_origin(int w, int h, const Tuple& from, double fov = 0.9) {
  Camera c(w, h, fov);
  c.set_transform(view_transform(from, point(0, 0, 0), vector(0, 1, 0)));
  return c;
}

RenderOptions path_options(int samples, int max_depth) {
  RenderOptions o;
  o.integrator = Integrator::path;
  o.samples = samples;
  o.max_depth = max_depth;
  o.threads = 2;
  o.tile_size = 8;
  return o;
}

double channel(const Color& c, int i) { return i == 0 ? c.r : i == 1 ? c.g : c.b; }

// How many of the pixel-centre rays hit something: the tests below are
// about surfaces, so most pixels must see one.
int pixels_on_objects(const Camera& camera, const World& world) {
  int n = 0;
  for (int y = 0; y < camera.vsize(); ++y)
    for (int x = 0; x < camera.hsize(); ++x) {
      Intersection h;
      n += intersect_nearest(world, camera.ray_for_pixel(x, y), h);
    }
  return n;
}

// The white furnace: a closed object of diffuse albedo 1 in a uniform
// environment L looks like L. Every path's throughput stays 1 (cosine
// sampling of an albedo-1 Lambertian lobe gives f cos / pdf = 1 up to a few
// ulp per bounce, and roulette survives with probability 1), so each sample
// is L exactly, unless its path is cut at max_depth without escaping. With
// max_depth = 300 that needs 300 bounces on faces that let a good share of
// rays out: no sample is cut, and the only error is rounding, far below the
// 1e-9 allowed.
TEST(PathTracer, WhiteFurnaceTorusLooksLikeTheEnvironment) {
  const Color L{0.25, 0.5, 1.0};
  const World world = world_of({tipped_torus(matte(kWhite))}, L);
  const Camera camera = looking_at_origin(32, 24, point(0, 0.5, -4));
  ASSERT_GT(pixels_on_objects(camera, world), 32 * 24 / 3);
  const Canvas image = render_image(camera, world, path_options(16, 300));
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 32; ++x)
      for (int i = 0; i < 3; ++i)
        ASSERT_NEAR(channel(image.pixel_at(x, y), i), channel(L, i), 1e-9 * channel(L, i)) << x << "," << y;
}

// A convex diffuse object of albedo rho in the furnace: one bounce, then the
// ray escapes: rho L exactly on the sphere (each sample is), L beside it.
TEST(PathTracer, DiffuseSphereInTheFurnaceLooksLikeAlbedoTimesEnvironment) {
  const Color L{0.7, 0.7, 0.7}, rho{0.2, 0.5, 0.8};
  auto sphere = std::make_shared<Sphere>();
  sphere->set_material(matte(rho));
  const World world = world_of({sphere}, L);
  const Camera camera = looking_at_origin(24, 24, point(0, 0, -4), 0.7);
  const Canvas image = render_image(camera, world, path_options(1, 5));
  int on_sphere = 0;
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 24; ++x) {
      Intersection h;
      const bool hit = intersect_nearest(world, camera.ray_for_pixel(x, y), h);
      on_sphere += hit;
      const Color expected = hit ? rho * L : L;
      for (int i = 0; i < 3; ++i)
        ASSERT_NEAR(channel(image.pixel_at(x, y), i), channel(expected, i), 1e-12) << x << "," << y;
    }
  EXPECT_GT(on_sphere, 100);
}

// A point light of intensity I at distance d over a Lambertian plane of
// albedo rho: L = rho / pi * I cos(theta) / d^2. Without an environment or
// other objects nothing else reaches the plane, and the light is sampled
// without randomness: exact.
TEST(PathTracer, PointLightOverDiffusePlaneGivesLambertsLaw) {
  const Color rho{0.3, 0.6, 0.9}, I{10, 8, 6};
  auto plane = std::make_shared<Plane>();
  plane->set_material(matte(rho));
  World world = world_of({plane});
  const Tuple light = point(1, 3, -0.5);
  world.lights.push_back(PointLight{light, I});
  const Camera camera = looking_at_origin(16, 12, point(0, 5, -5));
  const Canvas image = render_image(camera, world, path_options(1, 5));
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 16; ++x) {
      const Ray r = camera.ray_for_pixel(x, y);
      const Tuple p = r.origin + r.direction * (-r.origin.y / r.direction.y);
      const Tuple to_light = light - p;
      const double d2 = dot(to_light, to_light);
      const double cos_theta = to_light.y / std::sqrt(d2);
      const Color expected = rho * I * (cos_theta / (kPi * d2));
      for (int i = 0; i < 3; ++i)
        ASSERT_NEAR(channel(image.pixel_at(x, y), i), channel(expected, i), 1e-12 * channel(expected, i) + 1e-15)
            << x << "," << y;
    }
}

// The mean and the standard error of the mean of n estimates of the red
// channel of the radiance along `ray` (samples s = 0 .. n - 1 of pixel
// (key, 0)).
struct Estimate {
  double mean, error;
};
Estimate estimate(const World& world, const Ray& ray, int n, int key, int max_depth = 5) {
  double sum = 0, sum2 = 0;
  for (int s = 0; s < n; ++s) {
    const double v = trace_path(world, ray, max_depth, path_seed(key, 0, s)).r;
    sum += v;
    sum2 += v * v;
  }
  const double mean = sum / n;
  const double variance = std::max(0.0, sum2 / n - mean * mean) * n / (n - 1);
  return {mean, std::sqrt(variance / n)};
}

// The book's default highlight (specular 1 beside diffuse 0.9) at several
// shininesses, on a convex sphere in the furnace: each sample is L times the
// path's throughput after one bounce, whose mean is the material's albedo at
// that angle, which energy conservation keeps at or under 1. Checked at
// normal to grazing incidence, with 4 standard errors of margin; and above
// the diffuse part's share (0.9 / 1.9 after normalization), so that a lobe
// that loses everything fails too.
TEST(PathTracer, GlossyMaterialInTheFurnaceNeverExceedsTheEnvironment) {
  const double L = 0.8;
  for (const double shininess : {1.0, 10.0, 200.0, 1000.0}) {
    Material m;
    m.specular = 1;
    m.diffuse = 0.9;
    m.shininess = shininess;
    auto sphere = std::make_shared<Sphere>();
    sphere->set_material(m);
    const World world = world_of({sphere}, Color{L, L, L});
    // Rays that meet the unit sphere at incidence angles with these cosines.
    for (const double cos_i : {1.0, 0.7, 0.3, 0.05}) {
      const double b = std::sqrt(1 - cos_i * cos_i);
      const Ray ray{point(b, 0, -5), vector(0, 0, 1)};
      const Estimate e = estimate(world, ray, 20000, static_cast<int>(shininess) + static_cast<int>(100 * cos_i));
      EXPECT_LE(e.mean, L + 4 * e.error) << "shininess " << shininess << ", cos " << cos_i;
      EXPECT_GT(e.mean, L * 0.9 / 1.9 * 0.95) << "shininess " << shininess << ", cos " << cos_i;
    }
  }
}

// Clear glass (transparency 1, no surface lobes) loses nothing: the exact
// Fresnel split between reflection and refraction keeps each path's
// throughput at 1, so every sample is L exactly unless it is cut at
// max_depth (rays can ring inside the tube by total internal reflection;
// 2000 vertices leave none that way here).
TEST(PathTracer, GlassTorusInTheFurnaceLooksLikeTheEnvironment) {
  const Color L{0.5, 0.5, 0.5};
  Material glass;
  glass.diffuse = 0;
  glass.specular = 0;
  glass.transparency = 1;
  glass.refractive_index = 1.5;
  const World world = world_of({tipped_torus(glass)}, L);
  const Camera camera = looking_at_origin(32, 24, point(0, 0.5, -4));
  ASSERT_GT(pixels_on_objects(camera, world), 32 * 24 / 3);
  const Canvas image = render_image(camera, world, path_options(16, 2000));
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 32; ++x) ASSERT_NEAR(image.pixel_at(x, y).r, L.r, 1e-9) << x << "," << y;
}

// Inside a closed sphere whose wall emits E and reflects diffusely with
// albedo rho, radiance is the same everywhere: L = E + rho L, so
// L = E / (1 - rho), the sum over every bounce. Emission counts once per
// vertex, and roulette's survival is divided out (the paths that it ends
// early would otherwise take their share with them). Within 4 standard
// errors.
TEST(PathTracer, InsideAGlowingSphereRadianceIsEmissionOverOneMinusAlbedo) {
  const double E = 0.3, rho = 0.5;
  Material wall = matte(Color{rho, rho, rho});
  wall.emissive = Color{E, E, E};
  auto sphere = std::make_shared<Sphere>();
  sphere->set_transform(scaling(2, 2, 2));
  sphere->set_material(wall);
  const World world = world_of({sphere});
  for (const Tuple& d : {vector(0, 0, 1), vector(0.6, 0.8, 0), vector(-1, -1, 1)}) {
    const Estimate e = estimate(world, Ray{point(0.5, 0.2, 0), normalize(d)}, 20000, 7, 200);
    EXPECT_NEAR(e.mean, E / (1 - rho), 4 * e.error);
    EXPECT_LT(e.error, 0.01 * E / (1 - rho));
  }
}

// An emissive object of albedo 0 looks like its emission, the environment
// around it: each sample exactly.
TEST(PathTracer, AnEmissiveBlackSphereLooksLikeItsEmission) {
  Material lamp = matte(kBlack);
  lamp.emissive = Color{2, 1, 0.5};
  auto sphere = std::make_shared<Sphere>();
  sphere->set_material(lamp);
  const World world = world_of({sphere}, Color{0.1, 0.1, 0.1});
  EXPECT_DOUBLE_EQ(trace_path(world, Ray{point(0, 0, -5), vector(0, 0, 1)}, 5, path_seed(1, 2, 3)).r, 2);
  EXPECT_DOUBLE_EQ(trace_path(world, Ray{point(0, 0, -5), vector(0, 0, 1)}, 5, path_seed(1, 2, 3)).b, 0.5);
  EXPECT_DOUBLE_EQ(trace_path(world, Ray{point(0, 3, -5), vector(0, 0, 1)}, 5, path_seed(1, 2, 3)).g, 0.1);
}

// The form factor from a point to a rectangle a x b whose corner lies on
// the point's normal at distance c, the rectangle parallel to the point's
// plane: F = 1/(2 pi) [A/sqrt(1+A^2) atan(B/sqrt(1+A^2)) + B/sqrt(1+B^2)
// atan(A/sqrt(1+B^2))], A = a/c, B = b/c. The irradiance from a Lambertian
// rectangle of radiance L is pi L F.
double corner_form_factor(double a, double b, double c) {
  const double A = a / c, B = b / c;
  const double sa = std::sqrt(1 + A * A), sb = std::sqrt(1 + B * B);
  return (A / sa * std::atan(B / sa) + B / sb * std::atan(A / sb)) / (2 * kPi);
}

// A square area light of side s at height h over the plane y = 0 (albedo
// rho), centred over the origin; radiance L = intensity / s^2.
struct AreaLightStage {
  double s, h, rho = 0.5, L = 2;
  World world() const {
    auto plane = std::make_shared<Plane>();
    plane->set_material(matte(Color{rho, rho, rho}));
    World w = world_of({plane});
    const Color intensity = Color{1, 1, 1} * (L * s * s);
    w.area_lights.emplace_back(point(-s / 2, h, -s / 2), vector(s, 0, 0), 1, vector(0, 0, s), 1, intensity);
    return w;
  }
  // The radiance the plane reflects at (x, 0, z), for the points below the
  // light's centre, a corner's midpoint of an edge: rho / pi * pi L sum F.
  double under_centre() const { return rho * L * 4 * corner_form_factor(s / 2, s / 2, h); }
  double under_corner() const { return rho * L * corner_form_factor(s, s, h); }
  double under_edge_middle() const { return rho * L * 2 * corner_form_factor(s / 2, s, h); }
  // A ray down onto (x, 0, z), from under the light.
  Ray onto(double x, double z) const { return Ray{point(x, h / 4, z), vector(0, -1, 0)}; }
};

// Light sampling and scattered rays that hit the light, weighted by the
// power heuristic, add up to the closed form: for a small light (which
// light sampling finds best) and a large one (which scattered rays find
// often), at three points. Each within 4 standard errors.
TEST(PathTracer, AreaLightIrradianceMatchesTheFormFactor) {
  for (const AreaLightStage stage : {AreaLightStage{0.5, 2}, AreaLightStage{8, 1}}) {
    const World world = stage.world();
    const double s = stage.s;
    const struct {
      Ray ray;
      double expected;
    } cases[] = {{stage.onto(0, 0), stage.under_centre()},
                 {stage.onto(s / 2, s / 2), stage.under_corner()},
                 {stage.onto(s / 2, 0), stage.under_edge_middle()}};
    int key = 0;
    for (const auto& c : cases) {
      const Estimate e = estimate(world, c.ray, 20000, ++key);
      EXPECT_NEAR(e.mean, c.expected, 4 * e.error) << "side " << s << ", case " << key;
      EXPECT_LT(e.error, 0.02 * c.expected) << "side " << s << ", case " << key;
    }
  }
}

// Seen straight on, from either side, the light is its radiance.
TEST(PathTracer, AreaLightSeenDirectlyFromBothSides) {
  const AreaLightStage stage{2, 3};
  const World world = stage.world();
  EXPECT_DOUBLE_EQ(trace_path(world, Ray{point(0.3, 1, 0.2), vector(0, 1, 0)}, 5, path_seed(0, 0, 0)).g, stage.L);
  EXPECT_DOUBLE_EQ(trace_path(world, Ray{point(0.3, 9, 0.2), vector(0, -1, 0)}, 5, path_seed(0, 0, 0)).g, stage.L);
  // Beside the light, the ray from above meets the lit plane instead.
  EXPECT_NE(trace_path(world, Ray{point(1.5, 9, 0), vector(0, -1, 0)}, 5, path_seed(0, 0, 0)).g, stage.L);
}

// The error of an unbiased estimate falls as 1/sqrt(N): the root mean
// square error of 1024 independent estimates of the large light's
// irradiance at N = 16 and at 4N samples differ by a factor of 2. The ratio
// of two such RMS values, each from 1024 estimates, scatters by a few
// percent; 1.75 .. 2.25 allows about three times that. A biased estimate
// (an error that does not shrink) gives a ratio near 1.
TEST(PathTracer, ErrorShrinksAsOneOverSquareRootOfSamples) {
  const AreaLightStage stage{8, 1};
  const World world = stage.world();
  const double exact = stage.under_centre();
  auto rms = [&](int n) {
    double sum2 = 0;
    for (int k = 0; k < 1024; ++k) {
      const double e = estimate(world, stage.onto(0, 0), n, 1000 + k).mean - exact;
      sum2 += e * e;
    }
    return std::sqrt(sum2 / 1024);
  };
  const double ratio = rms(16) / rms(64);
  EXPECT_GT(ratio, 1.75);
  EXPECT_LT(ratio, 2.25);
}

// A scene with every kind of light and lobe.
World mixed_world() {
  Material glass;
  glass.diffuse = 0.1;
  glass.transparency = 0.9;
  glass.reflective = 0.9;
  glass.refractive_index = 1.5;
  auto sphere = std::make_shared<Sphere>();
  sphere->set_transform(translation(1.2, 0.5, -0.5) * scaling(0.5, 0.5, 0.5));
  sphere->set_material(glass);
  Material mirror;
  mirror.color = Color{0.9, 0.3, 0.2};
  mirror.reflective = 0.4;
  mirror.shininess = 30;
  auto torus = tipped_torus(mirror);
  Material lamp = matte(Color{0.1, 0.1, 0.1});
  lamp.emissive = Color{4, 3, 2};
  auto bulb = std::make_shared<Sphere>();
  bulb->set_transform(translation(-1.5, 1.5, 0) * scaling(0.2, 0.2, 0.2));
  bulb->set_material(lamp);
  auto floor = std::make_shared<Plane>();
  floor->set_transform(translation(0, -1, 0));
  World w = world_of({sphere, torus, bulb, floor}, Color{0.1, 0.15, 0.2});
  w.environment.zenith = Color{0.3, 0.4, 0.6};
  w.lights.push_back(PointLight{point(-3, 4, -3), Color{8, 8, 8}});
  w.area_lights.emplace_back(point(-1, 3, -1), vector(2, 0, 0), 1, vector(0, 0, 2), 1, Color{3, 3, 3});
  return w;
}

// The same image whatever the number of threads, bit for bit, with no NaN.
TEST(PathTracer, SameImageWithOneOrTwoThreads) {
  const World world = mixed_world();
  const Camera camera = looking_at_origin(24, 16, point(0, 1.5, -5));
  RenderOptions one = path_options(4, 8), two = one;
  one.threads = 1;
  two.threads = 2;
  const Canvas a = render_image(camera, world, one), b = render_image(camera, world, two);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 24; ++x) {
      const Color p = a.pixel_at(x, y), q = b.pixel_at(x, y);
      ASSERT_TRUE(std::isfinite(p.r) && std::isfinite(p.g) && std::isfinite(p.b)) << x << "," << y;
      ASSERT_EQ(p.r, q.r) << x << "," << y;
      ASSERT_EQ(p.g, q.g) << x << "," << y;
      ASSERT_EQ(p.b, q.b) << x << "," << y;
    }
}

// Every ray the path tracer traces is counted: at least one per sample.
TEST(PathTracer, CountsItsRays) {
  const World world = mixed_world();
  const Camera camera = looking_at_origin(8, 8, point(0, 1.5, -5));
  RenderStats stats;
  render_image(camera, world, path_options(4, 8), &stats);
  EXPECT_GT(stats.rays, 8u * 8u * 4u);
}

// The mapping conserves energy: for any of the book's numbers, no channel
// of diffuse + glossy + mirror + dielectric exceeds 1.
TEST(PathMaterial, WeightsNeverAddUpToMoreThanOne) {
  for (const double diffuse : {0.0, 0.5, 0.9, 2.0})
    for (const double specular : {0.0, 0.3, 0.9, 3.0})
      for (const double reflective : {0.0, 0.5, 1.0, 1.7})
        for (const double transparency : {0.0, 0.4, 0.9, 1.5}) {
          Material m;
          m.diffuse = diffuse;
          m.specular = specular;
          m.reflective = reflective;
          m.transparency = transparency;
          const PathMaterial p = path_material(m, Color{1.5, 0.7, 0.2});
          for (int i = 0; i < 3; ++i)
            EXPECT_LE(channel(p.diffuse, i) + channel(p.glossy, i) + p.mirror + p.dielectric, 1 + 1e-12);
        }
}

TEST(PathMaterial, TheBookDefaultsShareAlbedoBetweenDiffuseAndGlossy) {
  const PathMaterial p = path_material(Material{}, kWhite);  // diffuse 0.9, specular 0.9
  EXPECT_DOUBLE_EQ(p.diffuse.r, 0.5);
  EXPECT_DOUBLE_EQ(p.glossy.r, 0.5);
  EXPECT_DOUBLE_EQ(p.exponent, 200);
}

TEST(PathMaterial, TheBooksGlassIsADielectric) {
  Material m;
  m.color = Color{0.1, 0.1, 0.12};
  m.diffuse = 0.1;
  m.specular = 1;
  m.reflective = 0.9;
  m.transparency = 0.9;
  m.refractive_index = 1.5;
  const PathMaterial p = path_material(m, m.color);
  EXPECT_EQ(p.mirror, 0);  // the dielectric's Fresnel reflection stands for it
  EXPECT_DOUBLE_EQ(p.dielectric, 0.9);
  EXPECT_NEAR(p.glossy.r + p.diffuse.b, 0.1, 1e-12);  // the surface lobes share what is left
  EXPECT_DOUBLE_EQ(p.ior, 1.5);
}

TEST(PathMaterial, KeepsSmallWeightsAsTheyAre) {
  Material m;
  m.color = Color{0.5, 0.4, 0.3};
  m.diffuse = 0.6;
  m.specular = 0.2;
  m.reflective = 0.1;
  const PathMaterial p = path_material(m, m.color);
  EXPECT_DOUBLE_EQ(p.diffuse.g, 0.4 * 0.6);
  EXPECT_DOUBLE_EQ(p.glossy.g, 0.2);
  EXPECT_DOUBLE_EQ(p.mirror, 0.1);
}

// The book's renderer sees the environment on a miss (black by default) and
// adds the emissive colour to the surface colour.
TEST(WhittedAdditions, RaysThatMissSeeTheEnvironment) {
  World w = default_world();
  const Ray away{point(0, 0, -5), vector(0, 1, 0)};
  EXPECT_EQ(color_at(w, away).r, 0);
  w.environment.color = Color{0.2, 0.3, 0.4};
  EXPECT_TRUE(approx_equal(color_at(w, away), Color{0.2, 0.3, 0.4}));
  w.environment.zenith = Color{1, 1, 1};
  EXPECT_TRUE(approx_equal(color_at(w, away), Color{1, 1, 1}));  // straight up
  EXPECT_TRUE(approx_equal(color_at(w, Ray{point(0, 0, -5), vector(0, -1, 0)}), Color{0.2, 0.3, 0.4}));
  EXPECT_TRUE(approx_equal(w.environment.radiance(vector(1, 1, 0)),
                           Color{0.2, 0.3, 0.4} * (1 - std::sqrt(0.5)) + Color{1, 1, 1} * std::sqrt(0.5)));
}

TEST(WhittedAdditions, EmissiveAddsToTheSurfaceColour) {
  World w = default_world();
  const Ray ray{point(0, 0, -5), vector(0, 0, 1)};
  const Color plain = color_at(w, ray);
  Material m = w.objects[0]->material();
  m.emissive = Color{0.5, 0.25, 0};
  w.objects[0]->set_material(m);
  EXPECT_TRUE(approx_equal(color_at(w, ray), plain + Color{0.5, 0.25, 0}));
}

}  // namespace
}  // namespace toroid
