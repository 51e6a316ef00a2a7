// SPDX-License-Identifier: Apache-2.0
// Memory: one torus instance costs at most 256 bytes. The object
// and the shared-pointer control block it is allocated with, as the scene
// loader allocates it (make_shared), come to 176 bytes; its material is a
// pointer to a block shared with every shape of equal material (the
// loader's), or to the process-wide default. docs/performance.md has what
// glibc makes of that (its chunk header and rounding) and the whole scene's
// cost per torus (the world's list and index too).
#include <gtest/gtest.h>

#include <cstddef>
#include <memory>

#include "toroid/math/transform.h"
#include "toroid/shapes/torus.h"

namespace toroid {
namespace {

std::size_t requested_bytes = 0;

// Counts the bytes requested through it in requested_bytes. Stateless, so
// that the control block does not grow by a copy of it: the block is then
// make_shared's.
template <typename T>
struct CountingAllocator {
  using value_type = T;
  CountingAllocator() = default;
  template <typename U>
  CountingAllocator(const CountingAllocator<U>&) {}
  T* allocate(std::size_t n) {
    requested_bytes += n * sizeof(T);
    return std::allocator<T>().allocate(n);
  }
  void deallocate(T* p, std::size_t n) { std::allocator<T>().deallocate(p, n); }
  template <typename U>
  bool operator==(const CountingAllocator<U>&) const {
    return true;
  }
};

// The shape base: vtable pointer, affine inverse (96), material pointer
// (8), parent (8) and the shadow flag, whose tail padding holds the torus's
// one-byte fields; then the radii and the partial sweep's pointer.
TEST(TorusFootprint, ObjectFitsIn152Bytes) { EXPECT_LE(sizeof(Torus), 152u); }

// make_shared's 16-byte control block with it: 168 bytes asked, which glibc
// serves from a 176-byte chunk (176 asked would take 192).
TEST(TorusFootprint, InstanceWithItsControlBlockFitsIn168Bytes) {
  Material glaze;
  glaze.color = Color{0.5, 0.4, 0.3};
  const SharedMaterial shared(glaze);  // the loader's, made once per scene
  requested_bytes = 0;
  auto t = std::allocate_shared<Torus>(CountingAllocator<Torus>(), 1.0, 0.25);
  // A transform of its own and a shared material add nothing to the heap.
  t->set_transform(translation(3, 0, 0) * rotation_x(0.5) * scaling(2, 2, 2));
  t->set_material(shared);
  EXPECT_EQ(&t->material(), shared.get());
  EXPECT_GE(requested_bytes, sizeof(Torus));  // the count sees the object
  EXPECT_LE(requested_bytes, 168u);
}

TEST(TorusFootprint, PartialTorusKeepsItsSweepApart) {
  Torus t;
  EXPECT_TRUE(t.sweep().whole());
  t.set_sweep(TorusSweep{3.0, -1.0, 1.0});
  EXPECT_EQ(t.sweep().theta_max, 3.0);
  EXPECT_EQ(t.sweep().phi_min, -1.0);
  t.set_sweep(TorusSweep{});
  EXPECT_TRUE(t.sweep().whole());
}

}  // namespace
}  // namespace toroid
