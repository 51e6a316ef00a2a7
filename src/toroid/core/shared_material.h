// SPDX-License-Identifier: Apache-2.0
// What a shape holds of its material: a counted reference to an immutable
// Material, one pointer wide. std::shared_ptr takes two (16 bytes); a scene
// may hold many thousands of shapes, and a torus with make_shared's control
// block must fit in a 176-byte heap block (docs/performance.md). The count
// lives in the block, beside the material.
#pragma once

#include <atomic>
#include <cstdint>

#include "toroid/core/material.h"

namespace toroid {

class SharedMaterial {
 public:
  // The process-wide default material (Material{}): never freed, not
  // counted, so that copying it for every new shape costs nothing.
  SharedMaterial() noexcept;
  // A new block holding a copy of m, with this one holder.
  explicit SharedMaterial(const Material& m);
  SharedMaterial(const SharedMaterial& other) noexcept;
  SharedMaterial(SharedMaterial&& other) noexcept;
  SharedMaterial& operator=(SharedMaterial other) noexcept;
  ~SharedMaterial();

  const Material& operator*() const noexcept { return *get(); }
  const Material* operator->() const noexcept { return get(); }
  const Material* get() const noexcept { return &block_->material; }
  // How many SharedMaterials hold this block; 0 for the default.
  std::uint32_t use_count() const noexcept;

  friend bool operator==(const SharedMaterial& a, const SharedMaterial& b) { return a.block_ == b.block_; }

 private:
  struct Block {
    Material material;
    std::atomic<std::uint32_t> holders;
  };
  static Block* default_block() noexcept;
  Block* block_;
};

}  // namespace toroid
