#pragma once
/// quad4i: the bilinear quadrilateral with incompatible modes (Wilson, Taylor et al.). Beside the
/// bilinear field, each component gets the bubbles P1 = 1 - xi^2 and P2 = 1 - eta^2 (four internal
/// unknowns a, condensed out statically), which let the element bend without the shear locking of
/// the plain bilinear quad. Their strains G a are built like B's (rows rr, zz, rz, th; P / r in the
/// hoop row in axisymmetry) and then corrected to
///   G_c = G - (1/V) integral G dV,
/// Taylor's correction in its integral form: the enhanced strains are orthogonal to every constant
/// stress (Simo and Rifai's condition), so a constant stress does no work on the modes and the patch
/// test is passed on any shape, in plane and axisymmetric analyses alike. The modes carry the
/// thermal and initial-strain loads through G_c, not the body force (they are strains, not
/// displacements). Integration 2 x 2; material points are its four points.

#include <span>

#include "solver/fe/element_kernel.hpp"

namespace saasgaps {

ElementMatrices incompatible_mode_matrices(const ElementData& e);

ElementStates incompatible_mode_states(const ElementData& e, std::span<const double> u);

}  // namespace saasgaps
