#pragma once
/// Heat conduction runs: the temperatures of a model's `thermal` section, and the layer above the
/// stress analysis that feeds them to it exactly as `loads.temperatures` would (the contact loop of
/// analysis.cpp knows nothing of heat).
///
/// Steady. K(T) T = f is nonlinear when a conductivity depends on T; it is solved by fixed-point
/// (Picard) iteration: every node starts at the reference temperature; each pass solves with the
/// conductivities at the current temperatures (element means). It stops when the conductivities
/// did not change (a constant k: one solve) or when the largest change of a node temperature is at
/// most steady_tolerance x (1 + max |T|); after max_conduction_iterations passes without either it
/// throws SolverError with the last change.
/// Radiating edges (thermal_system.hpp) join the same iteration, linearized at the current
/// temperatures; only the change test ends it then. A transient step with radiation iterates the same way.
///
/// Transient. Backward Euler, (C / dt + K) T_n+1 = C / dt T_n + f, from initial_temperature
/// (prescribed nodes jump to their values at t > 0). Conductivity and capacity are taken at T_n. A
/// step that would pass an output time is shortened to end on it. The factorization is reused while
/// the assembled matrix is unchanged (bit for bit): a constant k and c and a constant step reuse one.
/// While the matrix's inputs (k, the capacity rates density c / dt, the conductances) are those of
/// the last assembly and no edge radiates, a step assembles only its right-hand side
/// (ThermalSystem::assemble_rhs, the same bits).
/// The run ends at the last output time.
///
/// Gap elements conduct (gaps.conductance) with H = h(p) when closed (p the contact pressure, h
/// interpolated in p, constant beyond the ends) and H = k_gas / gap when open, gap = w (1 + eps_M)
/// from the stress solution (w the gap's width, thermal_system.hpp). Steady runs then alternate:
/// conduction with the gap states of the last stress solve (first pass: every gap open at its
/// width), stress solve with those temperatures; they stop when no gap changed between open and
/// closed and the largest node temperature change is at most coupling_tolerance x (1 + max |T|),
/// and throw SolverError after max_coupling_passes. Each pass is a contraction in practice because
/// the states can only flip a finite number of times and, with fixed states, T depends on the
/// pressures only through the table's slope.
///
/// Contact pairs with a `conductance` conduct the same way through their mortar rows
/// (contact_conductance.hpp), H per point of side A from its gap and pressure, and join the same
/// passes: a point's touching or not counts as a state like a gap's.
///
/// Transient runs with conducting gaps or pairs couple to the stress analysis at each output time,
/// the contact state of the last stress solve holding until the next (transient_coupling.hpp).

#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "solver/analysis/analysis.hpp"
#include "solver/model/model.hpp"
#include "solver/state/solution.hpp"

namespace saasgaps {

inline constexpr int max_conduction_iterations = 50;
inline constexpr double steady_tolerance = 1.0e-10;
inline constexpr int max_coupling_passes = 20;
inline constexpr double coupling_tolerance = 1.0e-8;

/// The conductance H across each gap element of the model from a stress solution's gap results
/// (empty results: every gap open at its full width). Empty when the gaps do not conduct.
std::vector<double> gap_conductances(const Model& model, std::span<const GapResult> gaps);

/// The steady temperatures; gap_conductance: H per gap element (gap_conductances), empty when
/// the gaps do not conduct; contact_conductance: H per row of the conducting contact pairs
/// (ContactConductance::conductances), empty for every point at its initial gap. Throws
/// SingularModelError when a body has no temperature fixed.
ThermalResult solve_steady_conduction(const Model& model, std::span<const double> gap_conductance = {},
                                      std::span<const double> contact_conductance = {});

/// Conductances across the interfaces: H per gap element (gap_conductances) and per row of the
/// conducting contact pairs (ContactConductance::conductances).
struct InterfaceConductances {
  std::vector<double> gaps;
  std::vector<double> pairs;
};

/// Called at output time k (index into thermal.output_times) with its node temperatures: the
/// conductances of the time steps after it, or nullopt to end the run there.
using OutputTimeHook =
    std::function<std::optional<InterfaceConductances>(std::size_t k, std::span<const double> T)>;

/// The transient temperatures at each output time. gap_conductance, contact_conductance: as for
/// solve_steady_conduction (empty contact_conductance: every point at its initial gap), the
/// conductances of the steps up to the first output time; at_output (optional) replaces them after
/// each output time (a change refactorizes, an unchanged matrix reuses its factorization). A run
/// that at_output ends has the output times up to that one only. observer (optional) receives a
/// ThermalRecord at each output time, before at_output is called.
ThermalResult solve_transient_conduction(const Model& model, std::span<const double> gap_conductance = {},
                                         std::span<const double> contact_conductance = {},
                                         const OutputTimeHook& at_output = {}, IterationObserver* observer = nullptr);

/// The model with node temperatures T as its loads, in `loads` and in every step's loads.
Model with_temperatures(const Model& model, const std::vector<double>& T);

/// The model of a transient run's stress analysis: one load step of one increment per output time,
/// named "t = <time>", with the temperatures of that time.
Model with_temperature_steps(const Model& model, const ThermalResult& transient);

/// solve() for any model: without `thermal` exactly solve(); with it, the conduction first (and the
/// thermal-contact passes for conducting gaps and pairs), then the stress analysis, and the result's thermal.
/// The observer receives a ThermalRecord (thermal_record.hpp) per steady pass or transient output
/// time before the stress iterations that use it. A resumed transient run recomputes the
/// conduction (the same numbers, the same rows) and resumes the stress analysis at the state's load
/// step: its output time, and with it the temperatures, follow from the state's position (with
/// conducting gaps or pairs, the stress steps before it are replayed for their conductances:
/// transient_coupling.hpp).
Solution solve_with_heat(const Model& model, IterationObserver* observer = nullptr,
                         const RestartState* resume = nullptr, const ResumeOptions& options = {},
                         const OrderingCache* cache = nullptr, const ContactMethodFactory& contact = make_contact_method);

}  // namespace saasgaps
