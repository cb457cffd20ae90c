#pragma once
/// The computational restart of the report (Appendix A, "COMPUTATIONAL RESTART"): after every
/// iteration, a complete snapshot of everything the next iteration depends on. Resuming from it
/// with nothing changed reproduces the uninterrupted run to the last digit.

#include <vector>

#include "exact_contact.hpp"
#include "gap_closure.hpp"
#include "iteration_record.hpp"
#include "material_state.hpp"

namespace saasgaps {

struct RestartState {
  static constexpr int current_version = 1;
  int version = current_version;
  int iteration = 0;               ///< K: iterations finished (0: nothing solved yet)
  int attempt = 1;                 ///< run that produced iteration K (1, then +1 per resume)
  MaterialState materials;         ///< secant ratios and bimodulus choices iteration K used
  GapHistory gaps;                 ///< gap moduli and strains of iterations K and K-1
  std::vector<double> displacement;  ///< (u_r, u_z) per node of iteration K, prescribed ones included
  ContactState contact;            ///< exact mode: pair forces and active set of iteration K (empty in classic)
  std::vector<IterationRecord> history;  ///< rows 1..K

  /// Model dimensions the state belongs to, checked on resume.
  std::size_t node_count = 0;
  std::size_t element_count = 0;
  std::size_t gap_count = 0;
};

}  // namespace saasgaps
