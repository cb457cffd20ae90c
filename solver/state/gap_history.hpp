#pragma once
/// The classic gap iteration's state between iterations (gaps/gap_closure.hpp), as plain data: the
/// moduli each iteration used, the strains they gave, and why a gap failed the convergence test.

#include <vector>

namespace saasgaps {

/// The gap moduli one iteration uses.
struct GapModuli {
  std::vector<double> normal;  ///< E_M per gap
  double tensile = 0.0;        ///< the schedule's current tensile modulus: E_N = E_theta of every gap
  int schedule_step = -1;      ///< schedule entry in use; -1 = the initial modulus
  bool extrapolated = false;   ///< some E_M came from the extrapolation of Fig. 19
};

/// Everything the next iteration's gap moduli depend on, after iteration K.
struct GapHistory {
  GapModuli used;                        ///< moduli of iteration K
  std::vector<double> strain;            ///< eps_M of iteration K
  std::vector<double> previous_normal;   ///< E_M of iteration K-1 (empty when K = 1)
  std::vector<double> previous_strain;   ///< eps_M of iteration K-1 (empty when K = 1)
  double previous_tensile = 0.0;         ///< tensile modulus of iteration K-1
  [[nodiscard]] bool has_previous() const { return !previous_strain.empty(); }
};

/// Why a gap fails test (e); the first failing check is reported.
enum class GapFailure {
  none,
  first_iteration,  ///< nothing to compare with yet
  overclosed,       ///< eps_M <= -(1 + tolerance)
  not_relaxed,      ///< in tension but not yet at the schedule's floor modulus
  not_settled,      ///< eps_M moved by more than the tolerance since the last iteration
  loaded_open,      ///< strict test: does not touch, yet stiffer than the floor modulus
};

const char* describe(GapFailure failure);

}  // namespace saasgaps
