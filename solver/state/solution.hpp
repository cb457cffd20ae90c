#pragma once
/// The outcome of a run: status, history, and the last iteration's displacements, element
/// stresses and strains, and gap states.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "solver/base/name_table.hpp"
#include "solver/base/voigt.hpp"
#include "solver/state/gap_history.hpp"
#include "solver/state/iteration_record.hpp"
#include "solver/state/recovered_field.hpp"

namespace saasgaps {

enum class RunStatus {
  converged,
  not_converged,  ///< max_iterations reached; resumable
  stopped,        ///< stopped at an iteration boundary on request; resumable
};

inline constexpr NameTable<RunStatus, 3> run_status_names{{{
    {RunStatus::converged, "converged"}, {RunStatus::not_converged, "not_converged"}, {RunStatus::stopped, "stopped"}}}};
inline const char* to_string(RunStatus status) { return run_status_names.name(status).data(); }

struct NodeResult {
  int id = 0;
  double u_r = 0.0;
  double u_z = 0.0;
};

struct ElementResult {
  int id = 0;
  Vec4 stress = Vec4::Zero();  ///< (rr, zz, rz, th)
  Vec4 strain = Vec4::Zero();  ///< total (rr, zz, gamma_rz, th)
  Principal principal;
  double effective = 0.0;      ///< von Mises
  bool yielded = false;        ///< YIELD?
  bool plastic_converged = true;  ///< N-L/CONV?
  double error = 0.0;  ///< estimated error in the energy norm (solver/recovery/error_estimate.hpp)
};

/// open: eps_M >= 0; partial: closing but short of contact by more than the tolerance; closed:
/// within the tolerance of contact; overclosed: beyond it.
enum class GapState { open, partial, closed, overclosed };

inline constexpr NameTable<GapState, 4> gap_state_names{{{{GapState::open, "open"},
                                                          {GapState::partial, "partial"},
                                                          {GapState::closed, "closed"},
                                                          {GapState::overclosed, "overclosed"}}}};
inline const char* to_string(GapState state) { return gap_state_names.name(state).data(); }

struct GapResult {
  int id = 0;
  double eps_m = 0.0;
  double closure = 0.0;  ///< % (100 = faces touching)
  double modulus = 0.0;  ///< E_M of the last iteration
  double sigma_m = 0.0;  ///< normal stress across the gap: the contact pressure (negative = compression)
  GapState state = GapState::open;
  bool converged = false;  ///< GAP-CONV?
  GapFailure failure = GapFailure::none;
};

/// The force the supports exert on a constrained node (reactions.hpp): plane analyses on the whole
/// thickness, axisymmetric ones on the full ring.
struct NodeReaction {
  int id = 0;        ///< node id
  double f_r = 0.0;  ///< along r (0 where u_r is free)
  double f_z = 0.0;  ///< along z (0 where u_z is free)
};

/// One load step of a stepped model: converged when its last increment converged; not_converged
/// when the run ended (max_iterations, or a stop on request) before it did or before it began.
/// (failed is the service's word for a run that threw; a finished run never says it.)
enum class StepStatus { converged, not_converged, failed };

inline constexpr NameTable<StepStatus, 3> step_status_names{{{
    {StepStatus::converged, "converged"}, {StepStatus::not_converged, "not_converged"}, {StepStatus::failed, "failed"}}}};
inline const char* to_string(StepStatus status) { return step_status_names.name(status).data(); }

struct StepResult {
  std::string name;
  int increments = 1;
  StepStatus status = StepStatus::not_converged;
};

/// A point of a contact surface pair: open, or touching (stick: also every touching point of a
/// frictionless pair; slip: friction > 0 and slipping).
enum class ContactPointState { open, stick, slip };

inline constexpr NameTable<ContactPointState, 3> contact_point_state_names{{{
    {ContactPointState::open, "open"}, {ContactPointState::stick, "stick"}, {ContactPointState::slip, "slip"}}}};
inline const char* to_string(ContactPointState state) { return contact_point_state_names.name(state).data(); }

/// One node of side A of a contact pair (result `contact[].points[]`).
struct ContactPointResult {
  double r = 0.0, z = 0.0;  ///< the node's reference coordinates
  double gap = 0.0;         ///< current gap along the node's normal (length; < 0 never once solved)
  double pressure = 0.0;    ///< >= 0, force per unit area of side A's face
  double shear = 0.0;       ///< tangential traction of side B on side A along A's chain direction (0: frictionless)
  double slip = 0.0;        ///< accumulated tangential slip, length (0: frictionless)
  ContactPointState state = ContactPointState::open;
};

/// A contact pair's points along side A, in the order of its chain.
struct ContactPairResult {
  std::array<std::string, 2> surfaces;  ///< names of sides A and B
  std::vector<ContactPointResult> points;
  /// The resultant force (f_r, f_z) that side B exerts on side A, in force units (plane analyses on
  /// the whole thickness, axisymmetric ones on the full ring, like nodal forces):
  ///   force = sum over the pair's rows j, and their entries k on a node of A, of lambda_j c_jk / D_j,
  /// the forces the rows put on A's nodes (lambda_j the multiplier, a force: mortar_method.hpp). A
  /// rigid translation leaves every gap unchanged, so each row's coefficients sum to zero and B feels
  /// -force. Zero before the first solve and for a pair that never touches.
  Vec2 force = Vec2::Zero();
};

/// The heat conduction of a thermal run (thermal_analysis.hpp).
struct ThermalResult {
  std::vector<double> T;          ///< per node: steady, the solution; transient, at the last output time
  std::vector<Vec2> flux;         ///< per solid element, (q_r, q_z) = -k grad T with T above
  std::vector<double> times;      ///< transient: the output times (empty when steady)
  std::vector<std::vector<double>> history;  ///< transient: T per node at each output time
  int iterations = 0;             ///< steady: conduction solves of the k(T) iteration (last pass)
  double last_change = 0.0;       ///< steady: largest node temperature change of the last of those solves
  int passes = 1;                 ///< thermal-contact passes (conducting gaps), else 1
  int time_steps = 0;             ///< transient: steps taken
  int factorizations = 0;         ///< of the conduction matrix
  /// Solves whose matrix was that of the solve before, so that only their right-hand side was
  /// assembled (ThermalSystem::assemble_rhs); not written to the result.
  int rhs_only_solves = 0;
  /// The recovered nodal heat flux (q_r, q_z, 0, 0) per node and material side, each element's
  /// estimated flux error in the conduction energy norm, and the model's estimate, with T above
  /// (solver/recovery/flux_recovery.hpp); empty / none before a conduction solve.
  RecoveredField recovered_flux;
  std::vector<double> heat_error;
  std::optional<ErrorEstimate> heat_error_estimate;
  double recovery_seconds = 0.0;  ///< wall time of that recovery and estimate (not written to the result)
};

struct Solution {
  RunStatus status = RunStatus::not_converged;
  int iterations = 0;
  std::string message;
  std::vector<IterationRecord> history;
  std::vector<NodeResult> nodes;
  std::vector<ElementResult> elements;
  std::vector<GapResult> gaps;
  std::vector<ContactPairResult> contact;  ///< one per model.contact pair; empty without contact
  std::vector<NodeReaction> reactions;  ///< every node with a prescribed component, in node order (empty before iteration 1)
  std::vector<SetReaction> set_reactions;  ///< one per Model::reaction_groups entry (empty before iteration 1)
  std::vector<StepResult> steps;  ///< stepped models only, one per Model::steps entry; else empty
  std::optional<ThermalResult> thermal;  ///< models with `thermal` only
  /// The recovered nodal stresses, per node and material side (rr, zz, rz, th); empty before iteration 1.
  RecoveredField recovered;
  /// The estimate of the stresses' error in the energy norm; none before iteration 1.
  std::optional<ErrorEstimate> error_estimate;
  /// Wall time (s) of the recovery and the error estimate (stresses, and heat flux with `thermal`),
  /// summed over the solves of the run; not written to the result (the adaptive loop's time split).
  double recovery_seconds = 0.0;
};

}  // namespace saasgaps
