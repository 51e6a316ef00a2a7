// Memory: one torus instance costs at most 256 bytes (issue 6), its object
// and its own heap allocation together. docs/performance.md has the whole
// scene's cost per torus (the world's list and index too).
#include <malloc.h>

#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "toroid/math/transform.h"
#include "toroid/shapes/torus.h"

namespace toroid {
namespace {

TEST(TorusFootprint, ObjectFitsIn256Bytes) { EXPECT_LE(sizeof(Torus), 256u); }

TEST(TorusFootprint, InstanceWithItsAllocationFitsIn256Bytes) {
  constexpr int kCount = 2000;
  std::vector<std::shared_ptr<Torus>> tori;
  tori.reserve(kCount);
  // glibc's bytes in use (chunk headers and rounding included), on this
  // thread's arena: the tori are built here, as the scene loader builds them.
  const std::size_t before = mallinfo2().uordblks;
  for (int i = 0; i < kCount; ++i) {
    auto t = std::make_shared<Torus>(1.0 + i * 1e-3, 0.25);
    t->set_transform(translation(i, 0, 0) * rotation_x(0.5) * scaling(2, 2, 2));
    t->material.color = Color{0.5, 0.4, 0.3};
    tori.push_back(std::move(t));
  }
  const std::size_t per_torus = (mallinfo2().uordblks - before) / kCount;
  EXPECT_LE(per_torus, 256u);
  EXPECT_GE(per_torus, sizeof(Torus));  // the measure sees the objects
}

}  // namespace
}  // namespace toroid
