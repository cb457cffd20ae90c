#pragma once
/// Recovered nodal heat flux and the error estimate of a heat conduction solution: the
/// Zienkiewicz-Zhu estimate of stress_recovery.hpp with the flux q = -k grad T in the place of the
/// stress and the conductivity in the place of the elastic law (docs/recovery.md, "Heat conduction").
///
/// Sampling points of q_h (the element's own flux, from its shape functions' gradients):
///   saas    the centroids of its four linear triangles (each triangle's constant flux; the centre
///           temperature the mean of the corners', as the element's reported flux takes it)
///   tri3    its centroid
///   tri6    the 3-point rule (1/6, 1/6), (2/3, 1/6), (1/6, 2/3)
///   quad4i, quad8, quad9   the 2 x 2 Gauss points +-1/sqrt(3)
/// recovered by patch_recovery.hpp's recover_field (values (q_r, q_z, 0, 0)), per material side.
///
/// Per element, in the conduction energy norm (no factor 1/2; dV = t dA plane, 2 pi r dA axisymmetric):
///   error_e^2 = integral_e (q* - q_h) . k^-1 (q* - q_h) dV,   norm_e^2 = integral_e q_h . k^-1 q_h dV,
/// q* the recovered nodal flux interpolated with the element's shape functions (saas: linear on each
/// triangle, its centre the mean of the corners), k the element's conductivity tensor as the last
/// conduction solve used it. Integration: the isoparametric families by their full stiffness rule;
/// the report's elements per triangle by the edge-midpoint rule (exact for a linear q*). The model's
/// error, energy_norm and relative as error_estimate.hpp's total_error.

#include <span>
#include <vector>

#include <Eigen/Core>

#include "solver/model/model.hpp"
#include "solver/recovery/error_estimate.hpp"
#include "solver/state/recovered_field.hpp"

namespace saasgaps {

struct FluxRecovery {
  RecoveredField flux;                ///< per node and material side, (q_r, q_z, 0, 0)
  std::vector<double> element_error;  ///< per solid element: sqrt of its error integral
  ErrorEstimate estimate;
};

/// T: the temperature per node; k: the (r, z) conductivity tensor per solid element (constant over
/// the element, symmetric positive definite).
FluxRecovery recover_heat_flux(const Model& model, std::span<const double> T, std::span<const Eigen::Matrix2d> k);

}  // namespace saasgaps
