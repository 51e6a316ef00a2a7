// SPDX-License-Identifier: Apache-2.0
#include "toroid/core/shared_material.h"

#include <utility>

namespace toroid {

SharedMaterial::Block* SharedMaterial::default_block() noexcept {
  static Block block{Material{}, 0};
  return &block;
}

SharedMaterial::SharedMaterial() noexcept : block_(default_block()) {}

SharedMaterial::SharedMaterial(const Material& m) : block_(new Block{m, 1}) {}

SharedMaterial::SharedMaterial(const SharedMaterial& other) noexcept : block_(other.block_) {
  // As std::shared_ptr: taking a reference needs no ordering, only the
  // release that may free the block does.
  if (block_ != default_block()) block_->holders.fetch_add(1, std::memory_order_relaxed);
}

SharedMaterial::SharedMaterial(SharedMaterial&& other) noexcept
    : block_(std::exchange(other.block_, default_block())) {}

SharedMaterial& SharedMaterial::operator=(SharedMaterial other) noexcept {
  std::swap(block_, other.block_);
  return *this;
}

SharedMaterial::~SharedMaterial() {
  if (block_ != default_block() && block_->holders.fetch_sub(1, std::memory_order_acq_rel) == 1) delete block_;
}

std::uint32_t SharedMaterial::use_count() const noexcept {
  return block_ == default_block() ? 0 : block_->holders.load(std::memory_order_relaxed);
}

}  // namespace toroid
