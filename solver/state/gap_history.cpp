#include "solver/state/gap_history.hpp"

namespace saasgaps {

const char* describe(GapFailure failure) {
  switch (failure) {
    case GapFailure::none: return "converged";
    case GapFailure::first_iteration: return "first iteration";
    case GapFailure::overclosed: return "overclosed beyond the tolerance";
    case GapFailure::not_relaxed: return "open but not relaxed to the floor modulus";
    case GapFailure::not_settled: return "closure still changing";
    case GapFailure::loaded_open: return "not touching but stiffer than the floor modulus";
  }
  return "?";
}

}  // namespace saasgaps
