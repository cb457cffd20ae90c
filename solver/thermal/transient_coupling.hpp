#pragma once
/// Transient heat conduction across conducting gaps and contact pairs, coupled to the stress
/// analysis at the output times (thermal_analysis.hpp gives the conduction itself).
///
/// The run marches the conduction to output time t_1 with the conductances of the undeformed model
/// (every gap open at its width, every pair point at its initial gap, as the steady run's first
/// pass); there it solves the stress analysis's load step 1 with T(t_1), and the conductances of
/// that contact state (pressures, gaps, states) hold for every time step up to t_2; and so on: the
/// contact state of the last stress solve holds until the next output time.
///
/// Why lagged and not iterated at each step or output time: a stress solve costs far more than a
/// conduction step (a nonlinear contact iteration against one back-substitution with a reused
/// factorization), so one stress solve per output time is what the run would pay anyway, and the
/// conductances change only when one is made. Iterating each output time to a fixed point would
/// repeat the interval's steps and the stress step per pass, for a coupling error that the output
/// times' spacing already controls. The lag is first order in that spacing; as T settles
/// (late times) the state of t_k is that of t_k+1 and the run reaches the steady coupled solution,
/// which the tests check. The matrix changes only at output times whose conductances changed, so
/// the factorization is redone only then.
///
/// Load step k is solved by resuming the stress analysis from its state at the end of step k-1
/// (restart exactness: the same as solving steps 1..k from the start), carrying contact,
/// plasticity and gap history. A step that does not converge (or is stopped) ends the run there:
/// the thermal result then has the output times up to it.

#include "solver/analysis/analysis.hpp"
#include "solver/model/model.hpp"
#include "solver/state/solution.hpp"

namespace saasgaps {

/// Resuming mid-way. The conductances of every interval up to the resumed load step j come from the
/// stress solves of steps 1..j-1, which the state does not hold; they are recomputed: the resumed
/// run marches the conduction from t = 0 as the first run did and replays steps 1..j-1 silently
/// (no history rows: the state already has them), each as the first run solved it (a fresh run's
/// settings, step k from step k-1's last state), so that the same calls give the same numbers; step
/// j then resumes from the state with the resume's settings, and the run goes on as before. The
/// result, the rows after the state's iteration and the thermal rows are the uninterrupted run's to
/// the last digit. Costs: the replayed stress steps (what the first run paid for them again).
/// Limitation: a run that an earlier resume changed (a READ card) before step j replays those steps
/// with the fresh run's settings, not the changed ones.

/// solve_with_heat for a transient model whose gaps or contact pairs conduct. resume (optional):
/// a state of this run; throws SolverError when its load step is not one of the output times.
Solution solve_coupled_transient(const Model& model, IterationObserver* observer, const RestartState* resume,
                                 const ResumeOptions& options, const OrderingCache* cache,
                                 const ContactMethodFactory& contact);

}  // namespace saasgaps
