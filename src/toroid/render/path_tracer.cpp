// SPDX-License-Identifier: Apache-2.0
#include "toroid/render/path_tracer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

#include "toroid/math/hash.h"
#include "toroid/render/computations.h"
#include "toroid/render/pattern.h"
#include "toroid/shapes/shape.h"

namespace toroid {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kInvPi = std::numbers::inv_pi;
// Beyond this a Phong lobe is a mirror for any practical purpose; the cap
// keeps (n + 2) / (2 pi) cos^n finite where the sampled cos is 1.
constexpr double kMaxExponent = 1e6;
// Russian roulette starts at this vertex (0: the camera ray's hit).
constexpr int kRouletteFrom = 3;

// The dimensions of a vertex's random numbers; area light i uses
// kAreaLight + 2 i and kAreaLight + 2 i + 1.
enum Dimension : std::uint32_t { kRoulette, kLobe, kDirection1, kDirection2, kFresnel, kAreaLight };

// The path's random number `dim` at `vertex`: a hash of the path's seed and
// both, in [0, 1).
double random01(std::uint64_t seed, int vertex, std::uint32_t dim) {
  const std::uint64_t k = (static_cast<std::uint64_t>(static_cast<std::uint32_t>(vertex)) << 32) | dim;
  return unit_interval(splitmix64(seed ^ (k * 0xd1b54a32d192ed03ULL)));
}

double average(const Color& c) { return (c.r + c.g + c.b) / 3; }
double largest(const Color& c) { return std::max({c.r, c.g, c.b}); }
Color clamp_non_negative(const Color& c) { return {std::max(c.r, 0.0), std::max(c.g, 0.0), std::max(c.b, 0.0)}; }

// Two unit vectors that make an orthonormal basis with the unit `n`
// (Duff et al. 2017, "Building an orthonormal basis, revisited").
void basis(const Tuple& n, Tuple& t, Tuple& b) {
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z);
  const double c = n.x * n.y * a;
  t = vector(1 + sign * n.x * n.x * a, sign * c, -sign * n.x);
  b = vector(c, sign + n.y * n.y * a, -n.y);
}

// A unit vector at angle acos(cos_theta) from the unit `axis`, turned by
// 2 pi u about it.
Tuple around(const Tuple& axis, double cos_theta, double u) {
  Tuple t, b;
  basis(axis, t, b);
  const double sin_theta = std::sqrt(std::max(0.0, 1 - cos_theta * cos_theta));
  const double phi = 2 * kPi * u;
  return t * (sin_theta * std::cos(phi)) + b * (sin_theta * std::sin(phi)) + axis * cos_theta;
}

// The power heuristic (beta = 2) weight of a strategy of density `a` beside
// one of density `b`.
double power_heuristic(double a, double b) {
  const double a2 = a * a, b2 = b * b;
  return a2 + b2 > 0 ? a2 / (a2 + b2) : 0.0;
}

// Fresnel reflectance of a smooth dielectric, unpolarized light, for the
// cosine of incidence `cos_i` (> 0) and eta = n_incident / n_transmitted;
// sets cos_t, the cosine of the refracted ray. 1 under total internal
// reflection.
double fresnel_dielectric(double cos_i, double eta, double& cos_t) {
  const double sin2_t = eta * eta * (1 - cos_i * cos_i);
  if (sin2_t >= 1) {
    cos_t = 0;
    return 1;
  }
  cos_t = std::sqrt(1 - sin2_t);
  const double rs = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  const double rp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  return (rs * rs + rp * rp) / 2;
}

// The lobes of one vertex and the probabilities of choosing each (by their
// average albedos; they add up to 1).
struct Lobes {
  PathMaterial m;
  double q_diffuse = 0, q_glossy = 0, q_mirror = 0, q_dielectric = 0;
  double total = 0;  // the sum of the lobes' weights; 0: the surface absorbs all

  explicit Lobes(const PathMaterial& pm) : m(pm) {
    const double wd = average(m.diffuse), wg = average(m.glossy);
    total = wd + wg + m.mirror + m.dielectric;
    if (total > 0) {
      q_diffuse = wd / total;
      q_glossy = wg / total;
      q_mirror = m.mirror / total;
      q_dielectric = m.dielectric / total;
    }
  }
  bool has_smooth() const { return q_diffuse + q_glossy > 0; }

  // The cosine between `wi` and the mirror direction of `wo` about `n`.
  static double cos_alpha(const Tuple& wo, const Tuple& wi, const Tuple& n) { return dot(reflect(-wo, n), wi); }
  // The diffuse and glossy BRDF for light arriving from `wi` and leaving
  // along `wo` (unit, both on the side of `n`).
  Color brdf(const Tuple& wo, const Tuple& wi, const Tuple& n) const {
    Color f = m.diffuse * kInvPi;
    if (q_glossy > 0) {
      const double ca = cos_alpha(wo, wi, n);
      if (ca > 0) f += m.glossy * ((m.exponent + 2) / (2 * kPi) * std::pow(ca, m.exponent));
    }
    return f;
  }
  // The density (solid angle) with which this vertex's sampling picks a
  // diffuse or glossy direction `wi`: the one-sample mixture of the two,
  // each weighted by the probability of choosing it.
  double pdf(const Tuple& wo, const Tuple& wi, const Tuple& n) const {
    const double cos_i = dot(wi, n);
    if (cos_i <= 0) return 0;
    double p = q_diffuse * cos_i * kInvPi;
    if (q_glossy > 0) {
      const double ca = cos_alpha(wo, wi, n);
      if (ca > 0) p += q_glossy * (m.exponent + 1) / (2 * kPi) * std::pow(ca, m.exponent);
    }
    return p;
  }
};

// Where `ray` meets the parallelogram of `light` at some 0 < t < t_max:
// sets t and the cosine between the ray and the light's normal.
bool hit_area_light(const AreaLight& light, const Ray& ray, double t_max, double& t, double& cos_light) {
  const Tuple u = light.uvec * light.usteps, v = light.vvec * light.vsteps;
  const Tuple n = cross(u, v);
  const double nn = dot(n, n);
  const double denom = dot(ray.direction, n);
  if (denom == 0 || nn == 0) return false;
  t = dot(light.corner - ray.origin, n) / denom;
  if (!(t > 0 && t < t_max)) return false;
  const Tuple w = ray.origin + ray.direction * t - light.corner;
  const double a = dot(cross(w, v), n) / nn;
  const double b = dot(cross(u, w), n) / nn;
  if (!(a >= 0 && a <= 1 && b >= 0 && b <= 1)) return false;
  cos_light = std::abs(denom) / (magnitude(ray.direction) * std::sqrt(nn));
  return true;
}

double light_area(const AreaLight& light) {
  return magnitude(cross(light.uvec * light.usteps, light.vvec * light.vsteps));
}

}  // namespace

PathMaterial path_material(const Material& m, const Color& base) {
  PathMaterial p;
  p.emission = clamp_non_negative(m.emissive);
  p.diffuse = clamp_non_negative(base) * std::max(m.diffuse, 0.0);
  const double ks = std::max(m.specular, 0.0);
  p.glossy = Color{ks, ks, ks};
  p.exponent = std::clamp(m.shininess, 0.0, kMaxExponent);
  p.dielectric = std::max(m.transparency, 0.0);
  p.mirror = p.dielectric > 0 ? 0.0 : std::max(m.reflective, 0.0);
  p.ior = m.refractive_index;
  if (const double smooth_and_delta = p.mirror + p.dielectric; smooth_and_delta > 1) {
    p.mirror /= smooth_and_delta;
    p.dielectric /= smooth_and_delta;
  }
  const double left = std::max(0.0, 1 - p.mirror - p.dielectric);
  const double surface = largest(p.diffuse + p.glossy);
  if (surface > left) {
    const double scale = surface > 0 ? left / surface : 0.0;
    p.diffuse = p.diffuse * scale;
    p.glossy = p.glossy * scale;
  }
  return p;
}

std::uint64_t path_seed(int x, int y, int s) {
  const std::uint64_t pixel = (static_cast<std::uint64_t>(static_cast<std::uint32_t>(x)) << 32) |
                              static_cast<std::uint64_t>(static_cast<std::uint32_t>(y));
  return splitmix64(splitmix64(pixel ^ 0x5851f42d4c957f2dULL) ^
                    (static_cast<std::uint64_t>(static_cast<std::uint32_t>(s)) * 0x9e6c63d0676a9a99ULL));
}

Color trace_path(const World& world, const Ray& camera_ray, int max_depth, std::uint64_t seed) {
  constexpr double kNoLimit = std::numeric_limits<double>::infinity();
  Color radiance = kBlack;
  Color beta{1, 1, 1};  // the path's throughput
  Ray ray = camera_ray;
  // Whether the last scattering was a delta (mirror, dielectric) or there
  // was none (the camera): then no light sample could have found what the
  // ray hits, and it counts in full. Else `scatter_pdf` is the density of
  // its direction, for the MIS weight.
  bool delta = true;
  double scatter_pdf = 0;
  for (int depth = 0;; ++depth) {
    ++rays_traced_on_this_thread();
    Intersection hit;
    const bool found = intersect_nearest(world, ray, hit);
    double t_light = found ? hit.t : kNoLimit;
    const AreaLight* light_hit = nullptr;
    double cos_light = 0;
    for (const AreaLight& light : world.area_lights) {
      double t, c;
      if (hit_area_light(light, ray, t_light, t, c)) {
        t_light = t;
        cos_light = c;
        light_hit = &light;
      }
    }
    if (light_hit) {
      const double area = light_area(*light_hit);
      double weight = 1;
      if (!delta) {
        const double distance2 = t_light * t_light * dot(ray.direction, ray.direction);
        weight = power_heuristic(scatter_pdf, distance2 / (area * cos_light));
      }
      radiance += beta * light_hit->intensity * (weight / area);
      break;  // the light absorbs what meets it
    }
    if (!found) {
      radiance += beta * world.environment.radiance(ray.direction);
      break;
    }
    const Computations comps = prepare_computations(hit, ray);
    const Material& material = comps.object->material();
    const Color base =
        material.pattern ? material.pattern->pattern_at_shape(*comps.object, comps.point) : material.color;
    const Lobes lobes(path_material(material, base));
    radiance += beta * lobes.m.emission;
    if (depth >= max_depth || lobes.total <= 0) break;
    if (depth >= kRouletteFrom) {
      const double survive = std::min(1.0, largest(beta));
      if (!(random01(seed, depth, kRoulette) < survive)) break;
      beta = beta / survive;
    }
    const Tuple& wo = comps.eyev;
    const Tuple& n = comps.normalv;

    // Direct light on the diffuse and glossy lobes.
    if (lobes.has_smooth()) {
      for (const PointLight& light : world.lights) {
        const Tuple to_light = light.position - comps.over_point;
        const double distance2 = dot(to_light, to_light);
        const Tuple wi = to_light / std::sqrt(distance2);
        const double cos_i = dot(wi, n);
        if (cos_i <= 0 || is_shadowed(world, light.position, comps.over_point)) continue;
        radiance += beta * light.intensity * lobes.brdf(wo, wi, n) * (cos_i / distance2);
      }
      for (std::size_t i = 0; i < world.area_lights.size(); ++i) {
        const AreaLight& light = world.area_lights[i];
        const std::uint32_t dim = kAreaLight + 2 * static_cast<std::uint32_t>(i);
        const Tuple u = light.uvec * light.usteps, v = light.vvec * light.vsteps;
        const Tuple on_light = light.corner + u * random01(seed, depth, dim) + v * random01(seed, depth, dim + 1);
        const Tuple to_light = on_light - comps.over_point;
        const double distance2 = dot(to_light, to_light);
        if (!(distance2 > 0)) continue;
        const double distance = std::sqrt(distance2);
        const Tuple wi = to_light / distance;
        const double cos_i = dot(wi, n);
        const Tuple ln = cross(u, v);
        const double area = magnitude(ln);
        const double cos_l = std::abs(dot(wi, ln)) / area;
        if (cos_i <= 0 || !(cos_l > 0)) continue;
        const double light_pdf = distance2 / (area * cos_l);
        const double weight = power_heuristic(light_pdf, lobes.pdf(wo, wi, n));
        if (weight <= 0 || is_shadowed(world, on_light, comps.over_point)) continue;
        radiance += beta * (light.intensity / area) * lobes.brdf(wo, wi, n) * (cos_i * weight / light_pdf);
      }
    }

    // The next direction: one lobe, chosen by its weight.
    const double pick = random01(seed, depth, kLobe);
    const double u1 = random01(seed, depth, kDirection1), u2 = random01(seed, depth, kDirection2);
    if (pick < lobes.q_diffuse + lobes.q_glossy) {
      const Tuple wi = pick < lobes.q_diffuse ? around(n, std::sqrt(u1), u2)  // cosine-weighted
                                              : around(reflect(-wo, n), std::pow(u1, 1 / (lobes.m.exponent + 1)), u2);
      const double cos_i = dot(wi, n);
      const double pdf = lobes.pdf(wo, wi, n);
      if (cos_i <= 0 || !(pdf > 0)) break;  // a glossy sample under the surface: no light
      beta = beta * lobes.brdf(wo, wi, n) * (cos_i / pdf);
      ray = Ray{comps.over_point, wi};
      delta = false;
      scatter_pdf = pdf;
    } else if (pick < lobes.q_diffuse + lobes.q_glossy + lobes.q_mirror) {
      beta = beta * (lobes.m.mirror / lobes.q_mirror);
      ray = Ray{comps.over_point, comps.reflectv};
      delta = true;
    } else {
      if (lobes.q_dielectric <= 0) break;  // only by rounding, when the probabilities add up to under 1
      beta = beta * (lobes.m.dielectric / lobes.q_dielectric);
      // Entering when the ray meets the outward side.
      const double eta = comps.inside ? lobes.m.ior : 1 / lobes.m.ior;
      const double cos_i = dot(wo, n);
      double cos_t = 0;
      const double reflectance = fresnel_dielectric(cos_i, eta, cos_t);
      if (random01(seed, depth, kFresnel) < reflectance)
        ray = Ray{comps.over_point, comps.reflectv};
      else
        ray = Ray{comps.under_point, n * (eta * cos_i - cos_t) - wo * eta};
      delta = true;
    }
  }
  return radiance;
}

}  // namespace toroid
