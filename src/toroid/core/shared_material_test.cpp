// SPDX-License-Identifier: Apache-2.0
#include "toroid/core/shared_material.h"

#include <gtest/gtest.h>

#include <thread>
#include <utility>
#include <vector>

namespace toroid {
namespace {

Material with_diffuse(double d) {
  Material m;
  m.diffuse = d;
  return m;
}

TEST(SharedMaterial, DefaultIsTheBooksDefaultMaterialAndIsShared) {
  const SharedMaterial a, b;
  EXPECT_EQ(a->ambient, 0.1);
  EXPECT_EQ(a->diffuse, 0.9);
  EXPECT_EQ(a->specular, 0.9);
  EXPECT_EQ(a->shininess, 200.0);
  EXPECT_EQ(a.get(), b.get());
  EXPECT_EQ(a.use_count(), 0u);  // not counted
}

TEST(SharedMaterial, FromAMaterialHoldsACopyOfItsOwn) {
  Material m = with_diffuse(0.3);
  const SharedMaterial s(m);
  m.diffuse = 0.5;
  EXPECT_EQ(s->diffuse, 0.3);
  EXPECT_EQ(s.use_count(), 1u);
  EXPECT_NE(s.get(), SharedMaterial().get());
}

TEST(SharedMaterial, CopiesShareTheBlockAndCountHolders) {
  const SharedMaterial s(with_diffuse(0.3));
  {
    const SharedMaterial t = s;
    EXPECT_EQ(t.get(), s.get());
    EXPECT_TRUE(t == s);
    EXPECT_EQ(s.use_count(), 2u);
  }
  EXPECT_EQ(s.use_count(), 1u);
}

TEST(SharedMaterial, AssignmentReleasesTheOldBlockAndTakesTheNew) {
  const SharedMaterial a(with_diffuse(0.3));
  SharedMaterial b(with_diffuse(0.6));
  const SharedMaterial b_copy = b;
  EXPECT_EQ(b.use_count(), 2u);
  b = a;
  EXPECT_EQ(b->diffuse, 0.3);
  EXPECT_EQ(a.use_count(), 2u);
  EXPECT_EQ(b_copy.use_count(), 1u);
  const SharedMaterial& same = b;  // through a reference: clang warns on a plain b = b
  b = same;                        // self-assignment keeps the block
  EXPECT_EQ(b->diffuse, 0.3);
  EXPECT_EQ(a.use_count(), 2u);
}

TEST(SharedMaterial, MovingLeavesTheDefaultBehind) {
  SharedMaterial a(with_diffuse(0.3));
  const Material* block = a.get();
  const SharedMaterial b = std::move(a);
  EXPECT_EQ(b.get(), block);
  EXPECT_EQ(b.use_count(), 1u);
  EXPECT_EQ(a.get(), SharedMaterial().get());  // NOLINT(bugprone-use-after-move): moved-from state is specified
}

TEST(SharedMaterial, CountsStayExactUnderCopiesOnSeveralThreads) {
  const SharedMaterial s(with_diffuse(0.3));
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&s] {
      for (int i = 0; i < 10000; ++i) {
        const SharedMaterial copy = s;
        ASSERT_EQ(copy->diffuse, 0.3);
      }
    });
  for (auto& t : threads) t.join();
  EXPECT_EQ(s.use_count(), 1u);
}

}  // namespace
}  // namespace toroid
