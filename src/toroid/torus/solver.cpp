// SPDX-License-Identifier: Apache-2.0
#include "toroid/torus/solver.h"

namespace toroid {

std::string_view solver_name(TorusSolver s) {
  switch (s) {
    case TorusSolver::Default: return "default";
    case TorusSolver::Ferrari: return "ferrari";
    case TorusSolver::Tianheng: return "tianheng";
  }
  return "default";
}

std::optional<TorusSolver> solver_from_name(std::string_view name) {
  for (TorusSolver s : {TorusSolver::Default, TorusSolver::Ferrari, TorusSolver::Tianheng})
    if (solver_name(s) == name) return s;
  return std::nullopt;
}

}  // namespace toroid
