#include "transient_coupling.hpp"

#include <optional>

#include "contact_conductance.hpp"
#include "errors.hpp"
#include "thermal_analysis.hpp"

namespace saasgaps {

namespace {

/// Passes every iteration on to the caller's observer and keeps the state after the last one: the
/// state the next load step resumes from.
class LastState final : public IterationObserver {
 public:
  explicit LastState(IterationObserver* next) : next_(next) {}

  void on_iteration(const IterationRecord& row, const RestartState& state) override {
    last = state;
    if (next_ != nullptr) next_->on_iteration(row, state);
  }
  bool stop_requested() override { return next_ != nullptr && next_->stop_requested(); }

  std::optional<RestartState> last;

 private:
  IterationObserver* next_;
};

}  // namespace

Solution solve_coupled_transient(const Model& model, IterationObserver* observer, const RestartState* resume,
                                 const ResumeOptions& options, const OrderingCache* cache,
                                 const ContactMethodFactory& contact) {
  if (resume != nullptr) {
    throw SolverError("a transient thermal run with conductance across gaps or contact pairs cannot resume mid-way "
                      "(its conductances depend on every stress solve before); run it again from the start");
  }
  const ContactConductance pairs(model);
  LastState states(observer);
  ThermalResult reached;  // output times and temperatures solved so far
  Solution s;
  // Later steps continue the run: a new tensile schedule given at its start is not restarted.
  ResumeOptions continuing = options;
  continuing.restart_schedule = false;
  const auto at_output = [&](std::size_t k, std::span<const double> T) -> std::optional<InterfaceConductances> {
    reached.times.push_back(model.thermal->output_times[k]);
    reached.history.emplace_back(T.begin(), T.end());
    const Model stepped = with_temperature_steps(model, reached);
    if (!states.last) {
      s = solve(stepped, &states, nullptr, options, cache, contact);
    } else {
      // The same run goes on, not a restart: resumed() counts one attempt up, so start one lower.
      RestartState from = *states.last;
      from.attempt -= 1;
      s = solve(stepped, &states, &from, continuing, cache, contact);
    }
    if (s.status != RunStatus::converged) return std::nullopt;
    return InterfaceConductances{gap_conductances(model, s.gaps), pairs.conductances(s.contact)};
  };
  s.thermal = solve_transient_conduction(model, gap_conductances(model, {}), pairs.conductances({}), at_output, observer);
  return s;
}

}  // namespace saasgaps
