// SPDX-License-Identifier: Apache-2.0
// embree-tori: a scene of tori rendered with Embree 3, the tori added as user
// geometry by toroid::embree (exact ray-torus roots). Embree builds the BVH
// and traces primary and shadow rays; shading is Lambert plus ambient from
// one point light. The camera is the one of "The Ray Tracer Challenge"
// (pixel-centre rays, view transform from/to/up, field of view across the
// longer side), so that embree-tori.yaml, the same scene for
// `toroid render`, gives the same silhouette.
//
//   embree-tori [--width W] [--height H] [-o OUT.png]
#include <embree3/rtcore.h>
#include <png.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <thread>
#include <vector>

#include "toroid/embree_tori.h"

namespace {

constexpr int kMaxSide = 8192;

// ------------------------------------------------------------ small linear algebra

using Vec = std::array<double, 3>;
using Affine = std::array<std::array<double, 4>, 3>;  // row-major 3x4

Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec normalize(const Vec& v) {
  const double m = std::sqrt(dot(v, v));
  return {v[0] / m, v[1] / m, v[2] / m};
}

constexpr Affine kIdentity{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}};

// a * b (b applies first).
Affine compose(const Affine& a, const Affine& b) {
  Affine r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) {
      double s = j == 3 ? a[i][3] : 0;
      for (int k = 0; k < 3; ++k) s += a[i][k] * b[k][j];
      r[i][j] = s;
    }
  return r;
}

Vec apply_point(const Affine& m, const Vec& p) {
  Vec r;
  for (int i = 0; i < 3; ++i) r[i] = m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] + m[i][3];
  return r;
}

// The inverse of an invertible affine map (cofactors of the 3x3 part).
Affine inverse(const Affine& m) {
  const double c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1];
  const double c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2];
  const double c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
  const double det = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
  Affine r{};
  r[0][0] = c00 / det;
  r[1][0] = c01 / det;
  r[2][0] = c02 / det;
  r[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) / det;
  r[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) / det;
  r[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) / det;
  r[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) / det;
  r[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) / det;
  r[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) / det;
  for (int i = 0; i < 3; ++i) r[i][3] = -(r[i][0] * m[0][3] + r[i][1] * m[1][3] + r[i][2] * m[2][3]);
  return r;
}

// The transform operations of the scene file, with the same matrices.
struct Op {
  enum Kind { Translate, Scale, RotateX, RotateY, RotateZ } kind;
  double a, b = 0, c = 0;
};

Affine matrix(const Op& op) {
  Affine m = kIdentity;
  const double cs = std::cos(op.a), sn = std::sin(op.a);
  switch (op.kind) {
    case Op::Translate: m[0][3] = op.a, m[1][3] = op.b, m[2][3] = op.c; break;
    case Op::Scale: m[0][0] = op.a, m[1][1] = op.b, m[2][2] = op.c; break;
    case Op::RotateX: m[1][1] = cs, m[1][2] = -sn, m[2][1] = sn, m[2][2] = cs; break;
    case Op::RotateY: m[0][0] = cs, m[0][2] = sn, m[2][0] = -sn, m[2][2] = cs; break;
    case Op::RotateZ: m[0][0] = cs, m[0][1] = -sn, m[1][0] = sn, m[1][1] = cs; break;
  }
  return m;
}

// First listed applies first, as in the scene file.
Affine transform(const std::vector<Op>& ops) {
  Affine m = kIdentity;
  for (const Op& op : ops) m = compose(matrix(op), m);
  return m;
}

// ------------------------------------------------------------ the scene (as embree-tori.yaml)

struct SceneTorus {
  double major, minor;
  std::vector<Op> ops;
  Vec color;
};

const std::vector<SceneTorus>& scene_tori() {
  static const std::vector<SceneTorus> tori{
      // A wide platter, flattened: lying in the xz-plane, squashed in y.
      {3.2, 0.9, {{Op::RotateX, 1.5708}, {Op::Scale, 1, 0.5, 1}, {Op::Translate, 0, -1.3, 0.8}}, {0.85, 0.8, 0.7}},
      // Two links of a chain: one upright, one flat through it.
      {1, 0.28, {{Op::RotateY, 0.3}, {Op::Translate, -0.7, 0.55, 0}}, {0.9, 0.35, 0.25}},
      {1, 0.28, {{Op::RotateX, 1.5708}, {Op::RotateY, 0.3}, {Op::Translate, 0.3, 0.55, -0.3}}, {0.25, 0.55, 0.9}},
      // A thin ring, tilted.
      {1.5, 0.03, {{Op::RotateX, 1.2}, {Op::RotateZ, 0.4}, {Op::Translate, 2.6, 1.1, 0.9}}, {0.95, 0.85, 0.3}},
      // A fat spindle (minor / major = 1.5): an apple.
      {0.5, 0.75, {{Op::RotateX, -1.0}, {Op::Translate, -2.8, 0.2, 0.7}}, {0.4, 0.8, 0.35}},
      // An oval ring: scaled non-uniformly, then turned.
      {0.7,
       0.3,
       {{Op::Scale, 1.6, 0.8, 1}, {Op::RotateY, 0.8}, {Op::RotateX, 0.3}, {Op::Translate, 2.2, -0.1, -1.6}},
       {0.8, 0.45, 0.85}},
  };
  return tori;
}

constexpr double kFieldOfView = 0.8;
constexpr Vec kFrom{0, 4.5, -10.5}, kTo{0, 0, 0}, kUp{0, 1, 0};
constexpr Vec kLight{-5, 8, -6};
constexpr double kAmbient = 0.1, kDiffuse = 0.9;

// ------------------------------------------------------------ the camera (RTC chapter 7)

struct Camera {
  int width, height;
  double half_width, half_height, pixel_size;
  Affine camera_to_world;

  Camera(int w, int h) : width(w), height(h) {
    const double half_view = std::tan(kFieldOfView / 2);
    const double aspect = static_cast<double>(w) / static_cast<double>(h);
    half_width = aspect >= 1 ? half_view : half_view * aspect;
    half_height = aspect >= 1 ? half_view / aspect : half_view;
    pixel_size = half_width * 2 / w;
    // view_transform: rows left, true up, -forward, after moving `from` to
    // the origin; the camera's rays need its inverse.
    const Vec forward = normalize(sub(kTo, kFrom));
    const Vec left = cross(forward, normalize(kUp));
    const Vec true_up = cross(left, forward);
    const Affine orientation{{{left[0], left[1], left[2], 0},
                              {true_up[0], true_up[1], true_up[2], 0},
                              {-forward[0], -forward[1], -forward[2], 0}}};
    const Affine move{{{1, 0, 0, -kFrom[0]}, {0, 1, 0, -kFrom[1]}, {0, 0, 1, -kFrom[2]}}};
    camera_to_world = inverse(compose(orientation, move));
  }

  // The ray through the centre of pixel (px, py): origin, unit direction.
  void ray(int px, int py, Vec& origin, Vec& direction) const {
    const double world_x = half_width - (px + 0.5) * pixel_size;
    const double world_y = half_height - (py + 0.5) * pixel_size;
    const Vec pixel = apply_point(camera_to_world, {world_x, world_y, -1});
    origin = apply_point(camera_to_world, {0, 0, 0});
    direction = normalize(sub(pixel, origin));
  }
};

// ------------------------------------------------------------ rendering

double srgb(double linear) {
  const double c = std::clamp(linear, 0.0, 1.0);
  return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055;
}

RTCRayHit primary_ray(const Vec& o, const Vec& d) {
  RTCRayHit rh{};
  rh.ray.org_x = static_cast<float>(o[0]), rh.ray.org_y = static_cast<float>(o[1]);
  rh.ray.org_z = static_cast<float>(o[2]);
  rh.ray.dir_x = static_cast<float>(d[0]), rh.ray.dir_y = static_cast<float>(d[1]);
  rh.ray.dir_z = static_cast<float>(d[2]);
  rh.ray.tnear = 0;
  rh.ray.tfar = std::numeric_limits<float>::infinity();
  rh.ray.mask = ~0u;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  return rh;
}

// The linear colour seen through one pixel: black where no torus is hit.
Vec shade(RTCScene scene, const Camera& camera, int px, int py) {
  Vec o, d;
  camera.ray(px, py, o, d);
  RTCRayHit rh = primary_ray(o, d);
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcIntersect1(scene, &context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return {0, 0, 0};
  const Vec& color = scene_tori()[rh.hit.primID].color;
  // The hit point on the float ray that was traced, and the normal facing
  // the eye.
  const Vec fo{rh.ray.org_x, rh.ray.org_y, rh.ray.org_z}, fd{rh.ray.dir_x, rh.ray.dir_y, rh.ray.dir_z};
  const double t = rh.ray.tfar;
  const Vec p{fo[0] + t * fd[0], fo[1] + t * fd[1], fo[2] + t * fd[2]};
  Vec n = normalize({rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z});
  if (dot(n, fd) > 0) n = {-n[0], -n[1], -n[2]};
  double light = kAmbient;
  const Vec to_light = sub(kLight, p);
  const double lambert = dot(n, normalize(to_light));
  if (lambert > 0) {
    // The shadow ray starts just off the surface, towards the eye's side.
    const double eps = 1e-4 * std::max({1.0, std::abs(p[0]), std::abs(p[1]), std::abs(p[2])});
    const Vec start{p[0] + eps * n[0], p[1] + eps * n[1], p[2] + eps * n[2]};
    RTCRay shadow = primary_ray(start, sub(kLight, start)).ray;
    shadow.tfar = 1.0f;  // the light itself is not a blocker
    rtcInitIntersectContext(&context);
    rtcOccluded1(scene, &context, &shadow);
    if (shadow.tfar != -std::numeric_limits<float>::infinity()) light += kDiffuse * lambert;
  }
  return {color[0] * light, color[1] * light, color[2] * light};
}

std::vector<unsigned char> render(RTCScene scene, const Camera& camera) {
  std::vector<unsigned char> rgb(static_cast<std::size_t>(camera.width) * camera.height * 3);
  const unsigned threads = std::clamp(std::thread::hardware_concurrency(), 1u, 64u);
  std::vector<std::thread> pool;
  for (unsigned k = 0; k < threads; ++k)
    pool.emplace_back([&, k] {
      for (int y = static_cast<int>(k); y < camera.height; y += static_cast<int>(threads))
        for (int x = 0; x < camera.width; ++x) {
          const Vec c = shade(scene, camera, x, y);
          unsigned char* px = &rgb[(static_cast<std::size_t>(y) * camera.width + x) * 3];
          for (int i = 0; i < 3; ++i) px[i] = static_cast<unsigned char>(std::lround(srgb(c[i]) * 255));
        }
    });
  for (std::thread& t : pool) t.join();
  return rgb;
}

// ------------------------------------------------------------ output

// A temporary file beside the output, renamed onto it once complete: the
// output path never holds a partial image.
class AtomicFile {
 public:
  explicit AtomicFile(const std::string& path) : path_(path), temp_(path + ".tmp-XXXXXX") {
    const int fd = mkstemp(temp_.data());
    if (fd < 0) fail(errno);
    // mkstemp makes the file private; the image gets the usual permissions.
    const mode_t mask = umask(0);
    umask(mask);
    fchmod(fd, 0666 & ~mask);
    file_ = fdopen(fd, "wb");
    if (!file_) {
      const int e = errno;
      close(fd);
      std::remove(temp_.c_str());
      fail(e);
    }
  }
  ~AtomicFile() {
    if (file_) std::fclose(file_);
    if (!committed_) std::remove(temp_.c_str());
  }
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  FILE* file() const { return file_; }
  void commit() {
    const bool flushed = std::fflush(file_) == 0 && fsync(fileno(file_)) == 0;
    const int e = errno;
    const bool closed = std::fclose(file_) == 0;
    file_ = nullptr;
    if (!flushed || !closed) fail(flushed ? errno : e);
    if (std::rename(temp_.c_str(), path_.c_str()) != 0) fail(errno);
    committed_ = true;
  }

 private:
  [[noreturn]] void fail(int e) const {
    throw std::runtime_error("cannot write '" + path_ + "': " + std::generic_category().message(e));
  }
  std::string path_, temp_;
  FILE* file_ = nullptr;
  bool committed_ = false;
};

void write_png(AtomicFile& out, const std::string& path, int width, int height, const std::vector<unsigned char>& rgb) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = static_cast<png_uint_32>(width);
  image.height = static_cast<png_uint_32>(height);
  image.format = PNG_FORMAT_RGB;
  if (!png_image_write_to_stdio(&image, out.file(), 0, rgb.data(), 0, nullptr))
    throw std::runtime_error("cannot write '" + path + "': " + image.message);
  out.commit();
}

// ------------------------------------------------------------ command line

struct Options {
  int width = 640, height = 480;
  std::string output = "embree-tori.png";
};

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

constexpr const char* kUsage =
    "usage: embree-tori [--width W] [--height H] [-o OUT.png]\n"
    "  Renders a scene of tori with Embree 3 (toroid::embree user geometry).\n"
    "  --width W, --height H   image size in pixels, 1 to 8192 (default 640 x 480)\n"
    "  -o, --output OUT.png    the PNG to write (default embree-tori.png)\n";

int side(std::string_view name, std::string_view text) {
  int v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc{} || end != text.data() + text.size() || v < 1 || v > kMaxSide)
    throw UsageError(std::string(name) + " must be a whole number from 1 to " + std::to_string(kMaxSide) + ", got '" +
                     std::string(text) + "'");
  return v;
}

// Returns false for --help (printed).
bool parse(int argc, char** argv, Options& o) {
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "-h" || arg == "--help") {
      std::fputs(kUsage, stdout);
      return false;
    }
    std::string_view name = arg, value;
    bool inline_value = false;
    if (const auto eq = arg.find('='); arg.starts_with("--") && eq != std::string_view::npos)
      name = arg.substr(0, eq), value = arg.substr(eq + 1), inline_value = true;
    if (name != "--width" && name != "--height" && name != "-o" && name != "--output")
      throw UsageError("unknown option '" + std::string(arg) + "'");
    if (!inline_value) {
      if (i + 1 >= argc) throw UsageError(std::string(name) + " needs a value");
      value = argv[++i];
    }
    if (name == "--width")
      o.width = side(name, value);
    else if (name == "--height")
      o.height = side(name, value);
    else
      o.output = value;
  }
  if (o.output.empty()) throw UsageError("the output path is empty");
  if (o.output.size() < 4 || o.output.compare(o.output.size() - 4, 4, ".png") != 0)
    throw UsageError("the output must be a .png file, got '" + o.output + "'");
  return true;
}

void embree_error(void*, RTCError code, const char* message) {
  std::fprintf(stderr, "embree-tori: Embree error %d: %s\n", static_cast<int>(code), message ? message : "");
}

int run(const Options& options) {
  // The output is opened first, so that a bad path fails before the render.
  AtomicFile out(options.output);
  RTCDevice device = rtcNewDevice(nullptr);
  if (!device)
    throw std::runtime_error("cannot create an Embree device (error " +
                             std::to_string(static_cast<int>(rtcGetDeviceError(nullptr))) + ")");
  rtcSetDeviceErrorFunction(device, embree_error, nullptr);
  std::vector<toroid::embree::EmbreeTorus> tori;
  for (const SceneTorus& s : scene_tori()) {
    toroid::embree::EmbreeTorus t;
    t.major = s.major;
    t.minor = s.minor;
    const Affine m = transform(s.ops);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 4; ++j) t.object_to_world[i][j] = m[i][j];
    tori.push_back(t);
  }
  std::vector<unsigned char> rgb;
  {
    RTCScene scene = rtcNewScene(device);
    try {
      const toroid::embree::ToriGeometry geometry = toroid::embree::attach_tori(device, scene, tori);
      rtcCommitScene(scene);
      if (rtcGetDeviceError(device) != RTC_ERROR_NONE) throw std::runtime_error("Embree failed to build the scene");
      rgb = render(scene, Camera(options.width, options.height));
      rtcReleaseScene(scene);  // before the geometry's owner goes
    } catch (...) {
      rtcReleaseScene(scene);
      rtcReleaseDevice(device);
      throw;
    }
  }
  rtcReleaseDevice(device);
  write_png(out, options.output, options.width, options.height, rgb);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  try {
    if (!parse(argc, argv, options)) return 0;
  } catch (const UsageError& e) {
    std::fprintf(stderr, "embree-tori: %s\n%s", e.what(), kUsage);
    return 2;
  }
  try {
    return run(options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "embree-tori: %s\n", e.what());
    return 1;
  }
}
