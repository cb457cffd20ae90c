#pragma once
/// An observer for restart tests: keeps every history row, thermal row and restart state, and asks
/// to stop after `stop_after` iterations (0: never).

#include <vector>

#include "solver/analysis/analysis.hpp"

namespace saasgaps::testing {

class StateRecorder : public IterationObserver {
 public:
  explicit StateRecorder(int stop_after = 0) : stop_after_(stop_after) {}
  void on_iteration(const IterationRecord& row, const RestartState& state) override {
    rows.push_back(row);
    states.push_back(state);
  }
  void on_thermal(const ThermalRecord& row) override { thermal.push_back(row); }
  bool stop_requested() override { return stop_after_ > 0 && static_cast<int>(states.size()) >= stop_after_; }
  std::vector<IterationRecord> rows;
  std::vector<RestartState> states;
  std::vector<ThermalRecord> thermal;

 private:
  int stop_after_;
};

}  // namespace saasgaps::testing
