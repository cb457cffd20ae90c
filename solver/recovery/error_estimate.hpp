#pragma once
/// The Zienkiewicz-Zhu error estimate in the energy norm: per element
///   error_e^2 = integral_e (sigma* - sigma_h) : D^-1 : (sigma* - sigma_h) dV,
/// sigma_h the element's stress as its kernel computed it, sigma* the recovered nodal stresses
/// (patch_recovery.hpp) interpolated with the element's shape functions, D the law of each material
/// point as the last solve used it (the secant law of a yielded or bimodulus point). No factor 1/2;
/// dV over the thickness (plane) or the full ring 2 pi r (axisymmetric). And for the model
///   error^2 = sum_e error_e^2,   energy_norm^2 = sum_e integral_e sigma_h : D^-1 : sigma_h dV,
///   relative = error / sqrt(energy_norm^2 + error^2).
///
/// The compliance D^-1: axisymmetric, of the 4 x 4 (rr, zz, rz, th) law; plane stress and plane
/// strain, of its in-plane 3 x 3 block on (rr, zz, rz) (sigma_th does no work: eps_th = 0 in plane
/// strain, sigma_th = 0 in plane stress).
///
/// Integration: the isoparametric families (tri6, quad8, quad9, quad4i) at their material points
/// with the stiffness rule's weights; the report's elements on each constant-strain triangle by the
/// edge-midpoint rule (exact for the quadratic integrand of a linear sigma*; axisymmetric weight
/// 2 pi r A / 3 at each midpoint, so that a constant integrand gets the kernel's 2 pi r_c A).

#include <span>

#include "solver/fe/element_kernel.hpp"
#include "solver/state/recovered_field.hpp"

namespace saasgaps {

/// One element's integrals.
struct ElementError {
  double error2 = 0.0;  ///< integral (sigma* - sigma_h) : D^-1 : (sigma* - sigma_h) dV
  double norm2 = 0.0;   ///< integral sigma_h : D^-1 : sigma_h dV
};

/// sigma : D^-1 : sigma for the analysis (see the file comment).
double complementary_energy_density(const Mat4& D, AnalysisType analysis, const Vec4& sigma);

/// Element e's integrals: states its kernel states at the material points, u its displacements,
/// nodal the recovered stress at its nodes (node_count of them, in its order).
ElementError element_error(const ElementData& e, const ElementStates& states, std::span<const double> u,
                           std::span<const Vec4> nodal);

/// A report element's (saas, tri3) integrals over its constant-strain triangles, solved from its
/// displacements u (the saas quad's centre condensed back): e with its law, temperatures and loads.
ElementError report_element_error(const ElementData& e, std::span<const double> u, std::span<const Vec4> nodal);

/// An isoparametric element's integrals from its material points' states alone. geometry:
/// solid_element_geometry's (no law); laws: the law of each material point, or one for all.
ElementError element_error(const ElementData& geometry, std::span<const Constitutive> laws,
                           std::span<const ElementState> point_states, std::span<const Vec4> nodal);

/// The model's estimate from the elements' integrals.
ErrorEstimate total_error(std::span<const ElementError> elements);

}  // namespace saasgaps
