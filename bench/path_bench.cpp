// SPDX-License-Identifier: Apache-2.0
// The path integrator's speed: a small torus scene (a torus with a glossy
// highlight, a glass sphere, a matte floor, a point light, an area light
// and a sky) rendered at 64 x 48 pixels and 4 samples per pixel, on one
// thread and on every core. The counter rays_per_s counts every ray traced
// (path segments and shadow rays, RenderStats::rays) per second of wall
// time.
//   build/bench/path_bench --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cstdint>
#include <memory>

#include "toroid/math/transform.h"
#include "toroid/render/renderer.h"
#include "toroid/shapes/plane.h"
#include "toroid/shapes/sphere.h"
#include "toroid/shapes/torus.h"

namespace {

using namespace toroid;

World torus_scene() {
  World w;
  auto torus = std::make_shared<Torus>(1.0, 0.35);
  torus->set_transform(translation(-0.4, 0.35, 0) * rotation_x(-1.5708));
  Material dough;
  dough.color = Color{0.84, 0.56, 0.27};
  dough.diffuse = 0.8;
  dough.specular = 0.3;
  dough.shininess = 40;
  torus->set_material(dough);
  auto ball = std::make_shared<Sphere>();
  ball->set_transform(translation(1.3, 0.5, -0.8) * scaling(0.5, 0.5, 0.5));
  Material glass;
  glass.diffuse = 0.1;
  glass.specular = 1;
  glass.transparency = 0.9;
  glass.reflective = 0.9;
  glass.refractive_index = 1.5;
  ball->set_material(glass);
  auto floor = std::make_shared<Plane>();
  Material matte;
  matte.color = Color{0.7, 0.7, 0.65};
  matte.specular = 0;
  floor->set_material(matte);
  w.objects = {torus, ball, floor};
  w.lights.push_back(PointLight{point(-4, 6, -5), Color{20, 20, 20}});
  w.area_lights.emplace_back(point(-1, 4, -1), vector(2, 0, 0), 1, vector(0, 0, 2), 1, Color{8, 8, 8});
  w.environment.color = Color{0.3, 0.3, 0.35};
  w.environment.zenith = Color{0.1, 0.2, 0.5};
  index_objects(w);
  return w;
}

// state.range(0): threads (0: every core).
void BM_PathTorusScene(benchmark::State& state) {
  const World world = torus_scene();
  Camera camera(64, 48, 0.9);
  camera.set_transform(view_transform(point(0, 2.5, -5), point(0, 0.4, 0), vector(0, 1, 0)));
  RenderOptions options;
  options.integrator = Integrator::path;
  options.samples = 4;
  options.threads = static_cast<int>(state.range(0));
  std::uint64_t rays = 0;
  for (auto _ : state) {
    RenderStats stats;
    benchmark::DoNotOptimize(render_image(camera, world, options, &stats));
    rays += stats.rays;
  }
  state.counters["threads"] = render_threads(options);
  state.counters["rays_per_s"] = benchmark::Counter(static_cast<double>(rays), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_PathTorusScene)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
