#include "solver/thermal/transient_coupling.hpp"

#include <optional>

#include "solver/base/errors.hpp"
#include "solver/thermal/contact_conductance.hpp"
#include "solver/thermal/thermal_analysis.hpp"

namespace saasgaps {

namespace {

/// Passes every iteration on to the caller's observer (unless quiet) and keeps the state after the
/// last one: the state the next load step resumes from.
class LastState final : public IterationObserver {
 public:
  explicit LastState(IterationObserver* next) : next_(next) {}

  void on_iteration(const IterationRecord& row, const RestartState& state) override {
    last = state;
    if (next_ != nullptr && !quiet) next_->on_iteration(row, state);
  }
  bool stop_requested() override { return next_ != nullptr && next_->stop_requested(); }

  std::optional<RestartState> last;
  bool quiet = false;  // replaying the load steps before a resume: their rows were reported before

 private:
  IterationObserver* next_;
};

/// The output time (0-based) of the load step a resume state stopped in.
std::size_t resumed_output(const RestartState& state, const Model& model) {
  const std::size_t count = model.thermal->output_times.size();
  if (!state.position || state.position->step < 0 || static_cast<std::size_t>(state.position->step) >= count) {
    throw SolverError("the restart state does not belong to this model (its load step is not one of the " +
                      std::to_string(count) + " output times of the transient run)");
  }
  return static_cast<std::size_t>(state.position->step);
}

}  // namespace

Solution solve_coupled_transient(const Model& model, IterationObserver* observer, const RestartState* resume,
                                 const ResumeOptions& options, const OrderingCache* cache,
                                 const ContactMethodFactory& contact) {
  const ContactConductance pairs(model);
  // A resume at output time j replays the load steps before j as the first run solved them (a
  // fresh run's settings, the same calls in the same order: the same numbers), silently, for the
  // conductances of the intervals up to t_j; step j resumes from the state.
  const std::size_t resume_at = resume != nullptr ? resumed_output(*resume, model) : 0;
  LastState states(observer);
  ThermalResult reached;  // output times and temperatures solved so far
  Solution s;
  const auto solve_step = [&](const Model& stepped, const ResumeOptions& first) {
    if (!states.last) return solve(stepped, &states, nullptr, first, cache, contact);
    // Later steps continue the run: a new tensile schedule given at its start is not restarted.
    ResumeOptions continuing = first;
    continuing.restart_schedule = false;
    // The same run goes on, not a restart: resumed() counts one attempt up, so start one lower.
    RestartState from = *states.last;
    from.attempt -= 1;
    return solve(stepped, &states, &from, continuing, cache, contact);
  };
  const auto at_output = [&](std::size_t k, std::span<const double> T) -> std::optional<InterfaceConductances> {
    reached.times.push_back(model.thermal->output_times[k]);
    reached.history.emplace_back(T.begin(), T.end());
    const Model stepped = with_temperature_steps(model, reached);
    if (resume != nullptr && k < resume_at) {
      states.quiet = true;
      s = solve_step(stepped, ResumeOptions{});
      states.quiet = false;
    } else if (resume != nullptr && k == resume_at) {
      // A state that ended its step converges at once without an iteration: the next step then
      // goes on from it, numbered as the resumed run's states are.
      states.last = *resume;
      states.last->attempt += 1;
      s = solve(stepped, &states, resume, options, cache, contact);
    } else {
      s = solve_step(stepped, options);
    }
    if (s.status != RunStatus::converged) return std::nullopt;
    return InterfaceConductances{gap_conductances(model, s.gaps), pairs.conductances(s.contact)};
  };
  s.thermal = solve_transient_conduction(model, gap_conductances(model, {}), pairs.conductances({}), at_output, observer);
  return s;
}

}  // namespace saasgaps
