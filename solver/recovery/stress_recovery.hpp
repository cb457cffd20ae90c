#pragma once
/// Recovered nodal stresses and the error estimate of a solved state, in one pass over the
/// elements to sample (sampling_points.hpp), one over the patches (patch_recovery.hpp) and one over
/// the elements to integrate the error (error_estimate.hpp). Pure: the model, the displacements,
/// the laws the last solve used and the stresses at the material points in; plain data out.
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

/// displacement: (u_r, u_z) per node; laws: each element's laws per material point as solved;
/// point_states: the kernel's states at every material point (points' numbering).
StressRecovery recover_stresses(const Model& model, std::span<const double> displacement, const PointLawsOf& laws,
                                std::span<const ElementState> point_states, const MaterialPoints& points);

}  // namespace saasgaps
