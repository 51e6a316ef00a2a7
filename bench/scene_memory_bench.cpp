// SPDX-License-Identifier: Apache-2.0
// Heap per torus in a loaded scene (the goal: one torus instance costs at
// most 256 bytes beyond the scene's fixed cost). Loads a YAML scene of 1
// and of 1 + N tori, each with its own transform and material, and counts
// glibc's bytes in use once load_scene has returned (the YAML document is
// freed by then): the difference over N is the cost of one torus in the
// scene, split into the Torus object with its allocation, the world's list
// and the world's index. The materials are written out in full on every
// torus; with distinct_materials=0 they are equal (the loader shares one
// block), with 1 each torus has its own colour (a block each). The timing is
// that of loading the larger scene.
//   build/bench/scene_memory_bench          (docs/performance.md)
#include <benchmark/benchmark.h>
#include <malloc.h>

#include <filesystem>
#include <sstream>
#include <string>

#include "toroid/scene/scene_loader.h"
#include "toroid/shapes/torus.h"

namespace {

std::string scene_with_tori(int n, bool distinct_materials) {
  std::ostringstream s;
  s << "- add: camera\n  width: 8\n  height: 8\n  field-of-view: 1\n  from: [0, 0, -50]\n  to: [0, 0, 0]\n"
       "  up: [0, 1, 0]\n- add: light\n  at: [0, 50, -50]\n  intensity: [1, 1, 1]\n";
  for (int i = 0; i < n; ++i)
    s << "- add: torus\n  major: 0.4\n  minor: 0.1\n  material:\n    color: [0.8, 0.3, "
      << (distinct_materials ? 0.2 + 1e-5 * i : 0.2)
      << "]\n    specular: 0.4\n"
         "  transform:\n    - [rotate-x, "
      << 0.01 * i << "]\n    - [translate, " << (i % 100) - 50 << ", " << (i / 100) % 100 - 50 << ", " << i / 10000
      << "]\n";
  return s.str();
}

// glibc's bytes in use: chunks from the heap and blocks it maps on their own
// (large vectors: the world's list and index).
std::size_t heap_in_use() {
  const struct mallinfo2 m = mallinfo2();
  return m.uordblks + m.hblkhd;
}

// Bytes in use after loading (the scene kept alive), less those before.
std::size_t heap_of_loaded_scene(const std::string& text, toroid::Scene* keep) {
  const std::size_t before = heap_in_use();
  *keep = toroid::load_scene_from_string(text, "memory.yml", std::filesystem::current_path());
  return heap_in_use() - before;
}

void BM_HeapPerTorus(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const bool distinct = state.range(1) != 0;
  const std::string small = scene_with_tori(1, distinct), large = scene_with_tori(1 + n, distinct);
  std::size_t heap_small = 0, heap_large = 0, index_bytes = 0, list_bytes = 0, chunk_bytes = 0;
  for (auto _ : state) {
    toroid::Scene a{{}, toroid::Camera(1, 1, 1), {}}, b{{}, toroid::Camera(1, 1, 1), {}};
    heap_small = heap_of_loaded_scene(small, &a);
    heap_large = heap_of_loaded_scene(large, &b);
    index_bytes = b.world.index.bytes() - a.world.index.bytes();
    list_bytes = (b.world.objects.capacity() - a.world.objects.capacity()) * sizeof(b.world.objects[0]);
    // The heap chunk of each torus (usable size + glibc's 8-byte header);
    // libstdc++'s make_shared puts its 16-byte control block first.
    for (const auto& s : b.world.objects) chunk_bytes += malloc_usable_size(reinterpret_cast<char*>(s.get()) - 16) + 8;
  }
  const double per = static_cast<double>(heap_large - heap_small) / n;
  state.counters["heap_per_torus_B"] = per;
  state.counters["index_per_torus_B"] = static_cast<double>(index_bytes) / n;
  state.counters["list_per_torus_B"] = static_cast<double>(list_bytes) / n;
  state.counters["instance_B"] = per - static_cast<double>(index_bytes + list_bytes) / n;
  // glibc hands a torus (168 bytes asked: a 176-byte chunk) a freed chunk of
  // 192 bytes when one is free, as the parser leaves them, since the rest
  // (16) is too small to split off.
  state.counters["instance_chunk_B"] = static_cast<double>(chunk_bytes) / (n + 1);
  state.counters["sizeof_Torus_B"] = sizeof(toroid::Torus);
}
BENCHMARK(BM_HeapPerTorus)
    ->ArgNames({"tori", "distinct_materials"})
    ->Args({10000, 0})
    ->Args({10000, 1})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

}  // namespace
