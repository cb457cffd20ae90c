#pragma once
/// The interference fit of two rings meshed on their own, with contact surfaces (model.contact) on
/// non-matching meshes, and its closed form: surface_contact_test.cpp and the surface-contact
/// benchmark.
///
/// Lame shrink fit. Inner ring a1..b of material 1, outer ring b..b2 of material 2, with an
/// interference delta: the inner ring's outer radius is b + delta/2, the outer ring's inner radius
/// b - delta/2. Lame: sigma_r = A - B/r^2, sigma_t = A + B/r^2, and in plane strain (also the
/// axisymmetric slice held in z)
///   u(r) = (1 + nu) r / E [(1 - 2 nu) A + B / r^2],
/// in plane stress
///   u(r) = r / E [(1 - nu) A + (1 + nu) B / r^2].
/// Inner ring under external pressure p: A = -p b^2 / (b^2 - a1^2), B = A a1^2, so u_i(b) = -p C_i;
/// outer ring under internal pressure p: A = p b^2 / (b2^2 - b^2), B = A b2^2, so u_o(b) = p C_o, with
///   plane strain  C_i = (1 + nu1) b [(1 - 2 nu1) b^2 + a1^2] / (E1 (b^2 - a1^2)),
///                 C_o = (1 + nu2) b [(1 - 2 nu2) b^2 + b2^2] / (E2 (b2^2 - b^2)),
///   plane stress  C_i = b [(1 - nu1) b^2 + (1 + nu1) a1^2] / (E1 (b^2 - a1^2)),
///                 C_o = b [(1 - nu2) b^2 + (1 + nu2) b2^2] / (E2 (b2^2 - b^2)).
/// The fit closes the overlap, u_o(b) - u_i(b) = delta:  p = delta / (C_i + C_o).
/// (Linear theory at the nominal radius b: the faces' radii differ by delta = 1e-4 b, a relative
/// effect of that order on p, far below the discretisation error measured.)

#include <array>

#include "solver/model/model.hpp"

namespace saasgaps::testing::shrink_fit_rings {

constexpr double a1 = 1.0, b = 1.5, b2 = 2.2, delta = 1.5e-4;
constexpr double E1 = 30.0e6, nu1 = 0.3, E2 = 10.0e6, nu2 = 0.33;

/// Lame's interface pressure p = delta / (C_i + C_o) (lame_rings.hpp; plane strain also for the
/// axisymmetric slice).
double lame_interference_pressure(AnalysisType type);

/// The shrink fit, the two rings meshed on their own (`radial` elements through each, `around` the
/// interface: inner, outer; plane: multiples of 4), surfaces "shaft" (A) and "hub" (B). Plane: each
/// ring held at its inner radius in z at 0 and 180 degrees and in r at 90 degrees (no rigid motion,
/// and nothing against the symmetric expansion). Axisymmetric: every node held in z (the
/// plane-strain state of a long fit). Materials: the inner ring's elements come first.
Model shrink_fit(AnalysisType type, int radial, std::array<int, 2> around);

/// The plane-strain fit as a quarter of both rings, of quad8 elements (mid-side nodes on the true
/// circles) or any family add_quadratic_grid builds (`saas`: the SAAS element, straight edges whose
/// corners lie on the circles), symmetric on both axes: `radial` elements through each ring,
/// around[0] edges on the shaft's face (side A, "shaft"), around[1] on the hub's ("hub").
/// eccentricity e > 0 moves the hub's bore out by e delta angle / 90 degrees: the interference falls
/// from delta at 0 degrees to (1 - e) delta at 90, so for e > 1 the fit opens towards the y axis (a
/// partial contact).
Model quarter_shrink_fit(int radial, std::array<int, 2> around, double eccentricity = 0.0,
                         ElementType type = ElementType::quad8);

}  // namespace saasgaps::testing::shrink_fit_rings
