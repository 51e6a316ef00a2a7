#include "toroid/roots/quartic.h"

namespace toroid {

std::string_view solver_name(QuarticSolver s) {
  switch (s) {
    case QuarticSolver::Default: return "default";
    case QuarticSolver::Ferrari: return "ferrari";
    case QuarticSolver::Tianheng: return "tianheng";
  }
  return "default";
}

std::optional<QuarticSolver> solver_from_name(std::string_view name) {
  for (QuarticSolver s : {QuarticSolver::Default, QuarticSolver::Ferrari, QuarticSolver::Tianheng})
    if (solver_name(s) == name) return s;
  return std::nullopt;
}

}  // namespace toroid
