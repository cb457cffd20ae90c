#pragma once
/// A steady thermal model turned into a transient run long enough to settle: every material stores
/// heat (c = 1, density = 1), every node starts at 0, steps of 0.25 to t = 32 with output times
/// 0.5, 1, 2, ..., 32 (seven stress steps, 128 time steps). For tests whose bodies are a few units
/// across with k of a few units: t = 32 is many of their slowest time constants.

#include <gtest/gtest.h>

#include "solver/model/model.hpp"
#include "solver/thermal/thermal_analysis.hpp"

namespace saasgaps::testing {

inline void make_settling_transient(Model& m) {
  for (Material& mat : m.materials) {
    for (PropertyRow& row : mat.table) row.c = 1.0;
    mat.density = 1.0;
    mat.stores_heat = true;
  }
  m.thermal->type = ThermalType::transient;
  m.thermal->initial_temperature = 0.0;
  m.thermal->time_step = 0.25;
  m.thermal->end_time = 32.0;
  m.thermal->output_times = {0.5, 1.0, 2.0, 4.0, 8.0, 16.0, 32.0};
}

/// The model solved as it is (steady) and then as make_settling_transient's run (m becomes that);
/// each is expected to converge.
struct SettledRuns {
  Solution steady;
  Solution transient;
};
inline SettledRuns steady_then_settling_transient(Model& m) {
  SettledRuns runs{solve_with_heat(m), {}};
  EXPECT_EQ(runs.steady.status, RunStatus::converged) << runs.steady.message;
  make_settling_transient(m);
  runs.transient = solve_with_heat(m);
  EXPECT_TRUE(runs.transient.thermal.has_value());
  EXPECT_EQ(runs.transient.status, RunStatus::converged) << runs.transient.message;
  return runs;
}

}  // namespace saasgaps::testing
