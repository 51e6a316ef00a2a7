// SPDX-License-Identifier: Apache-2.0
// The soft-shadows bonus chapter's test helper sequence(...): a generator
// that returns its numbers in turn, cyclically, to jitter area-light samples
// predictably in tests.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <vector>

namespace toroid::testing {

class Sequence {
 public:
  Sequence(std::initializer_list<double> values) : values_(values) {}
  double next() {
    const double v = values_[next_];
    next_ = (next_ + 1) % values_.size();
    return v;
  }

 private:
  std::vector<double> values_;
  std::size_t next_ = 0;
};

}  // namespace toroid::testing
