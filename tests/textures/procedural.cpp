// SPDX-License-Identifier: Apache-2.0
#include "textures/procedural.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "toroid/io/image_writer.h"

namespace toroid::textures {

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

std::uint64_t hash(std::int64_t x, std::int64_t y, std::int64_t z, std::uint64_t seed) {
  std::uint64_t h = seed ^ 0x9e3779b97f4a7c15ULL;
  for (const std::int64_t c : {x, y, z}) {
    h ^= static_cast<std::uint64_t>(c) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    h *= 0xbf58476d1ce4e5b9ULL;
    h ^= h >> 31;
  }
  return h;
}

double unit(std::uint64_t h) { return static_cast<double>(h >> 11) * 0x1.0p-53; }  // [0, 1)

double smooth(double t) { return t * t * (3 - 2 * t); }

// Value noise in [0, 1]: random values on the integer lattice, blended.
double noise(double x, double y, double z, std::uint64_t seed) {
  const double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
  const auto ix = static_cast<std::int64_t>(fx), iy = static_cast<std::int64_t>(fy), iz = static_cast<std::int64_t>(fz);
  const double tx = smooth(x - fx), ty = smooth(y - fy), tz = smooth(z - fz);
  double corners[2][2][2];
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b)
      for (int c = 0; c < 2; ++c) corners[a][b][c] = unit(hash(ix + a, iy + b, iz + c, seed));
  auto lerp = [](double p, double q, double t) { return p + (q - p) * t; };
  const double x00 = lerp(corners[0][0][0], corners[1][0][0], tx), x10 = lerp(corners[0][1][0], corners[1][1][0], tx);
  const double x01 = lerp(corners[0][0][1], corners[1][0][1], tx), x11 = lerp(corners[0][1][1], corners[1][1][1], tx);
  return lerp(lerp(x00, x10, ty), lerp(x01, x11, ty), tz);
}

// Fractal sum of `octaves` noises, each twice as fine and half as strong;
// about [0, 1], mean 0.5.
double fbm(const Tuple& p, int octaves, std::uint64_t seed) {
  double sum = 0, amplitude = 0.5, frequency = 1, total = 0;
  for (int i = 0; i < octaves; ++i) {
    sum += amplitude * noise(p.x * frequency, p.y * frequency, p.z * frequency, seed + i);
    total += amplitude;
    amplitude *= 0.5;
    frequency *= 2.03;
  }
  return sum / total;
}

Color mix(const Color& a, const Color& b, double t) { return a + (b - a) * std::clamp(t, 0.0, 1.0); }

double smoothstep(double lo, double hi, double x) { return smooth(std::clamp((x - lo) / (hi - lo), 0.0, 1.0)); }

// (u, v) of pixel (x, y) as UvImage samples it: pixel centres from 0 to 1.
UvCoord pixel_uv(int x, int y, int width, int height) {
  return {static_cast<double>(x) / (width - 1), 1.0 - static_cast<double>(y) / (height - 1)};
}

template <typename F>
Canvas paint(int width, int height, F colour_at_uv) {
  Canvas c(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) c.write_pixel(x, y, colour_at_uv(pixel_uv(x, y, width, height)));
  return c;
}

Color planet_at(const Tuple& p) {
  const Tuple q = point(p.x * 1.7 + 3.1, p.y * 1.7 - 1.3, p.z * 1.7 + 0.7);
  const double elevation = fbm(q, 6, 11) - 0.53;
  const double latitude = std::asin(std::clamp(p.y, -1.0, 1.0)) * 180 / std::numbers::pi;
  const double ice_edge = 66 + 12 * (fbm(q * 3.0, 3, 21) - 0.5);
  if (std::abs(latitude) > ice_edge) return Color{0.80, 0.85, 0.90};
  if (elevation < 0) {
    const Color deep{0.005, 0.03, 0.16}, shallow{0.03, 0.20, 0.38};
    return mix(deep, shallow, 1 + elevation / 0.08);
  }
  const double dryness = fbm(q * 2.0, 4, 31) + 0.25 * std::exp(-std::pow((std::abs(latitude) - 24) / 12, 2));
  const Color forest{0.05, 0.20, 0.03}, desert{0.50, 0.38, 0.18}, rock{0.22, 0.18, 0.14};
  const Color ground = mix(forest, desert, smoothstep(0.55, 0.7, dryness));
  const Color land = mix(ground, rock, smoothstep(0.06, 0.14, elevation));
  return mix(land, Color{0.85, 0.85, 0.88}, smoothstep(0.17, 0.2, elevation));  // snowy peaks
}

Color sky_at(const Tuple& direction) {
  const Tuple d = normalize(vector(direction.x, direction.y, direction.z));
  const double azimuth = std::atan2(d.x, d.z);
  // Mountains: a ridge height periodic in the azimuth.
  const Tuple ring = point(std::cos(azimuth) * 2.5, 0, std::sin(azimuth) * 2.5);
  const double ridge = 0.02 + 0.16 * std::pow(fbm(ring, 5, 41), 2.0);
  if (d.y < 0) {
    // Fields on the plane y = -1, fading into haze at the horizon.
    const double s = 1 / -d.y;
    const Tuple g = point(d.x * s, 0, d.z * s);
    const bool odd =
        (static_cast<std::int64_t>(std::floor(g.x / 3)) + static_cast<std::int64_t>(std::floor(g.z / 3))) & 1;
    const Color field = mix(odd ? Color{0.10, 0.26, 0.04} : Color{0.20, 0.32, 0.05}, Color{0.30, 0.22, 0.08},
                            fbm(g * 0.7, 3, 51) - 0.25);
    return mix(field, Color{0.45, 0.52, 0.60}, smoothstep(4, 60, s));
  }
  if (d.y < ridge) {
    const Color rock = mix(Color{0.16, 0.18, 0.24}, Color{0.30, 0.32, 0.38}, fbm(d * 8.0, 4, 61));
    return mix(rock, Color{0.75, 0.78, 0.82}, smoothstep(ridge - 0.03, ridge, d.y) * 0.5 + 0.3 * (1 - d.y / ridge));
  }
  const Color horizon{0.65, 0.75, 0.90}, zenith{0.10, 0.25, 0.70};
  Color sky = mix(horizon, zenith, std::pow(d.y, 0.6));
  // Clouds on a layer above: noise on the plane y = 1.
  const double s = 1 / std::max(d.y, 0.02);
  const double cloud = smoothstep(0.5, 0.75, fbm(point(d.x * s * 0.9, 0, d.z * s * 0.9), 5, 71));
  sky = mix(sky, Color{0.95, 0.95, 0.97}, cloud * smoothstep(0.0, 0.25, d.y));
  const Tuple sun = normalize(vector(0.35, 0.3, 1));
  const double c = dot(d, sun);
  if (c > std::cos(0.05)) return Color{1, 0.97, 0.85};
  return sky + Color{1, 0.8, 0.5} * (0.35 * std::pow(std::max(c, 0.0), 64));
}

// The doughnut at (u, v): angles around the axis and the tube in turns.
Color doughnut_at(UvCoord uv) {
  const double a = kTwoPi * uv.u, b = kTwoPi * uv.v;
  // Points on a torus in 3D make every noise below periodic in u and v.
  const Tuple p = point((2 + std::cos(b)) * std::cos(a), (2 + std::cos(b)) * std::sin(a), std::sin(b));
  const Color crust{0.42, 0.17, 0.04}, pale{0.75, 0.50, 0.22};
  // Paler where the dough touched the tray (the bottom, v near 0.75).
  Color colour = mix(crust, pale, 0.5 - 0.5 * std::sin(b) + 0.3 * (fbm(p * 3.0, 5, 81) - 0.5));
  // Icing over the top of the tube (v near 0.25) down to a wavy edge.
  const double wave = 0.035 * std::sin(7 * a) + 0.02 * std::sin(17 * a + 1) + 0.05 * (fbm(p * 1.5, 3, 91) - 0.5);
  const double reach = 0.2 + wave;  // half-width of the icing, in turns around the tube
  const double from_top = std::abs(std::remainder(uv.v - 0.25, 1.0));
  if (from_top > reach) return colour;
  Color icing = mix(Color{0.95, 0.35, 0.55}, Color{0.85, 0.22, 0.42}, fbm(p * 4.0, 3, 101));
  // Sprinkles: one per cell of a 48 x 16 grid (periodic in u and v),
  // jittered, rotated, in surface units (the tube is 2.5 times narrower).
  const int nu = 48, nv = 16;
  const double su = uv.u * nu, sv = uv.v * nv;
  const auto cu = static_cast<int>(std::floor(su)), cv = static_cast<int>(std::floor(sv));
  for (int du = -1; du <= 1; ++du)
    for (int dv = -1; dv <= 1; ++dv) {
      const int iu = ((cu + du) % nu + nu) % nu, iv = ((cv + dv) % nv + nv) % nv;
      const std::uint64_t h = hash(iu, iv, 0, 111);
      if (unit(h) < 0.25) continue;  // some cells have none
      const double centre_u = cu + du + 0.2 + 0.6 * unit(hash(iu, iv, 1, 111));
      const double centre_v = cv + dv + 0.2 + 0.6 * unit(hash(iu, iv, 2, 111));
      const double angle = std::numbers::pi * unit(hash(iu, iv, 3, 111));
      const double x = su - centre_u, y = (sv - centre_v) * (48.0 / 16.0) / 2.5;
      const double along = x * std::cos(angle) + y * std::sin(angle);
      const double across = -x * std::sin(angle) + y * std::cos(angle);
      const double half_length = 0.28, radius = 0.09;
      const double along_out = std::max(std::abs(along) - half_length, 0.0);
      if (along_out * along_out + across * across < radius * radius) {
        static const Color colours[] = {{0.9, 0.9, 0.85},   {0.95, 0.75, 0.05}, {0.05, 0.35, 0.85},
                                        {0.10, 0.60, 0.15}, {0.55, 0.10, 0.60}, {0.90, 0.30, 0.02}};
        icing = colours[hash(iu, iv, 4, 111) % 6];
      }
    }
  // A soft edge between icing and dough.
  return mix(icing, colour, smoothstep(reach - 0.008, reach, from_top));
}

}  // namespace

Canvas planet(int width, int height) {
  return paint(width, height, [](UvCoord uv) { return planet_at(spherical_point(uv)); });
}

Canvas sky_face(CubeFace face, int size) {
  return paint(size, size, [face](UvCoord uv) { return sky_at(cube_point(face, uv)); });
}

std::string sky_face_file(CubeFace face) {
  switch (face) {
    case CubeFace::Left: return "negx.ppm";
    case CubeFace::Right: return "posx.ppm";
    case CubeFace::Front: return "posz.ppm";
    case CubeFace::Back: return "negz.ppm";
    case CubeFace::Up: return "posy.ppm";
    case CubeFace::Down: return "negy.ppm";
  }
  return {};
}

Canvas doughnut(int width, int height) { return paint(width, height, doughnut_at); }

void write_scene_textures(const std::filesystem::path& dir, int size) {
  write_image(planet(2 * size, size), (dir / "earthmap1k.ppm").string());
  for (const CubeFace f :
       {CubeFace::Left, CubeFace::Right, CubeFace::Front, CubeFace::Back, CubeFace::Up, CubeFace::Down})
    write_image(sky_face(f, size), (dir / sky_face_file(f)).string());
  write_image(doughnut(2 * size, size), (dir / "doughnut.png").string());
}

}  // namespace toroid::textures
