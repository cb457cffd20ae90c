#pragma once
/// The closed form of the verification suite's shrink fit: two concentric steel rings, the inner one
/// heated across a small radial gap into the outer one, in plane strain along z. Lame's solution
/// gives the contact pressure p from
///   u_inner(b1) - u_outer(a2) = closure * delta,
///   u_inner(b1) = (1 + nu) alpha dT b1 + (1 + nu)/E [(1 - 2 nu) A_i b1 + B_i / b1],
///                 A_i = -p b1^2/(b1^2 - a1^2), B_i = A_i a1^2,
///   u_outer(a2) = (1 + nu)/E [(1 - 2 nu) A_o a2 + B_o / a2],  A_o = p a2^2/(b2^2 - a2^2), B_o = A_o b2^2,
/// (plane strain: u = (1 + nu)/E [(1 - 2 nu) A r + B / r] for sigma_r = A - B/r^2).

#include "solver/model/model.hpp"
#include "solver/state/solution.hpp"

namespace saasgaps::testing::lame_rings {

constexpr double E = 30.0e6, nu = 0.3, alpha = 6.5e-6, dT = 400.0;
constexpr double a1 = 1.0, b1 = 1.5, delta = 0.002, a2 = b1 + delta, b2 = 2.2;

/// Lame contact pressure when the gap closes to `closure` (fraction) of delta.
double contact_pressure(double closure);

/// The run converged, every gap's closure is within the closure tolerance of 100 %, and every gap's
/// normal stress is within `tolerance` (relative) of -p for the given clearance delta closed,
/// contact_pressure(1) (gtest expectations; prints the worst relative error).
void expect_contact(const Model& m, const Solution& s, double tolerance);

/// Two rings of different materials fitted with a radial interference: a ring a..b (E_in, nu_in)
/// inside a ring b..c (E_out, nu_out), their faces overlapping by `interference` at radius b, in
/// plane strain along z (also an axisymmetric slice held in z). Under a pressure p the inner face
/// moves in by p C_in and the outer face out by p C_out (u = (1 + nu) r / E [(1 - 2 nu) A + B / r^2]
/// with sigma_r = A - B / r^2),
///   C_in  = (1 + nu_in)  b [(1 - 2 nu_in)  b^2 + a^2] / (E_in  (b^2 - a^2)),
///   C_out = (1 + nu_out) b [(1 - 2 nu_out) b^2 + c^2] / (E_out (c^2 - b^2)),
/// and the fit closes the overlap: p = interference / (C_in + C_out).
struct RingPair {
  double a, b, c;
  double E_in, nu_in, E_out, nu_out;
};
double plane_strain_interference_pressure(const RingPair& rings, double interference);

/// The same fit in plane stress (thin rings, sigma_z = 0). Lame's stresses are those of plane strain,
/// sigma_r = A - B / r^2, sigma_theta = A + B / r^2 (equilibrium and compatibility alone fix them);
/// only the strain law changes, eps_theta = (sigma_theta - nu sigma_r) / E, so
///   u = r eps_theta = r / E [(1 - nu) A + (1 + nu) B / r^2].
/// Inner ring under external pressure p: A = -p b^2 / (b^2 - a^2), B = A a^2, so u_in(b) = -p C_in;
/// outer ring under internal pressure p: A = p b^2 / (c^2 - b^2), B = A c^2, so u_out(b) = p C_out:
///   C_in  = b [(1 - nu_in)  b^2 + (1 + nu_in)  a^2] / (E_in  (b^2 - a^2)),
///   C_out = b [(1 - nu_out) b^2 + (1 + nu_out) c^2] / (E_out (c^2 - b^2)),
/// and again p = interference / (C_in + C_out). (Plane strain is this with E -> E / (1 - nu^2),
/// nu -> nu / (1 - nu): C_in then becomes the plane-strain form above.)
double plane_stress_interference_pressure(const RingPair& rings, double interference);

}  // namespace saasgaps::testing::lame_rings
