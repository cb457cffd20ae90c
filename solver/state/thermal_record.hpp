#pragma once
/// One row of a heat conduction run's history: what the thermal side of solve_with_heat reports to
/// the IterationObserver, beside the stress iterations' IterationRecord.
///
/// Steady runs report one row per conduction solve to convergence (one per thermal-contact pass
/// when gaps or contact pairs conduct); transient runs report one row per output time (each the end
/// of a load step of the stress analysis), covering the time steps taken since the one before.

#include "solver/base/name_table.hpp"

namespace saasgaps {

enum class ThermalRowKind { steady, transient };

struct ThermalRecord {
  ThermalRowKind kind = ThermalRowKind::steady;
  /// 1-based position of the row in its run. A resumed run reports the same rows again, with the
  /// same numbers (the conduction is recomputed exactly), so (job, index) identifies a row.
  int index = 0;
  /// Steady: the thermal-contact pass the row belongs to (1 without conducting gaps or pairs).
  /// Transient: 1.
  int pass = 1;
  /// Steady: conduction solves of the k(T) (Picard) iteration in this pass (1 for a constant k).
  /// Transient: 0.
  int iterations = 0;
  /// Transient: the output time reached (model time units); steady: 0.
  double time = 0.0;
  /// Transient: time steps taken since the start of the run, up to `time`; steady: 0.
  int time_steps = 0;
  /// Largest |change| of a node temperature (model temperature units). Steady: that of the last
  /// Picard solve of the pass (with a single solve, a constant k, the change from the starting
  /// temperatures: the reference temperature); transient: the largest over the single time steps
  /// since the previous output time.
  double max_change = 0.0;
  /// Steady: the largest node temperature change from the previous pass's temperatures (0 in pass 1).
  /// Transient: 0.
  double pass_change = 0.0;
  double min_T = 0.0;  ///< lowest node temperature of the row's solution
  double max_T = 0.0;  ///< highest node temperature of the row's solution

  /// Equality of every number: what an exact restart reports again.
  [[nodiscard]] bool same_numbers(const ThermalRecord& other) const;
};

inline constexpr NameTable<ThermalRowKind, 2> thermal_row_kind_names{
    {{{ThermalRowKind::steady, "steady"}, {ThermalRowKind::transient, "transient"}}}};
inline const char* to_string(ThermalRowKind kind) { return thermal_row_kind_names.name(kind).data(); }

}  // namespace saasgaps
