#pragma once
/// Recovered nodal stresses and the error estimate of a solved state: one pass over the patches
/// (patch_recovery.hpp), which sample their elements' material point states as they gather them
/// (sampling_points.hpp), one over the boundary nodes of known traction (boundary_stresses.hpp) and
/// one over the elements to integrate the error (error_estimate.hpp). Pure: the model, the
/// displacements, the laws the last solve used and the stresses at the material points in; plain
/// data out. Working memory beyond the result: the node-element incidence, a kind and a fit slot
/// per node side, and the fits that boundary and mid-side nodes read.
/// docs/recovery.md describes the method and what the numbers mean.

#include <span>
#include <vector>

#include "solver/assembly/stiffness_system.hpp"
#include "solver/fe/material_points.hpp"
#include "solver/recovery/error_estimate.hpp"
#include "solver/recovery/patch_recovery.hpp"

namespace saasgaps {

struct StressRecovery {
  RecoveredField stress;              ///< per node and material side, (rr, zz, rz, th)
  std::vector<double> element_error;  ///< per solid element: sqrt of its error integral
  ErrorEstimate estimate;
};

/// displacement: (u_r, u_z) per node; laws_for_thread: each element's laws per material point as
/// solved, a lookup made for each thread; point_states: the kernel's states at every material point
/// (points' numbering).
StressRecovery recover_stresses(const Model& model, std::span<const double> displacement,
                                const PointLawsFactory& laws_for_thread, std::span<const ElementState> point_states,
                                const MaterialPoints& points);

}  // namespace saasgaps
