#pragma once
/// The ring fit used by the contact tests and the contact benchmark: a steel ring a1..b1 heated by dT
/// inside a steel ring a2..b2, a2 = b1 + delta (a radial gap), as a quarter annulus with symmetry on
/// both axes, gap elements around the interface with M radial at each element's mid angle.

#include <functional>

#include "solver/base/voigt.hpp"
#include "solver/model/model.hpp"
#include "support/lame_rings.hpp"

namespace saasgaps {
class StiffnessSystem;
}

namespace saasgaps::testing {

/// The rings' material and radii: those of the closed form in lame_rings.hpp.
struct RingFit {
  static constexpr double E = lame_rings::E, nu = lame_rings::nu, alpha = lame_rings::alpha, dT = lame_rings::dT;
  static constexpr double a1 = lame_rings::a1, b1 = lame_rings::b1, delta = lame_rings::delta;
  static constexpr double a2 = lame_rings::a2, b2 = lame_rings::b2;
};

/// (s, t) in [0, 1]^2 to the quarter annulus r0..r1, angle 0..90 degrees (counter-clockwise).
std::function<Vec2(double, double)> quarter_annulus(double r0, double r1);

/// The quarter-annulus ring fit with radial x hoop quads per ring and hoop gap elements; gaps in
/// classic mode with the default settings (tests set the method and schedule they need).
/// eccentricity e > 0 widens the gap from delta at angle 0 to (1 + e) delta at 90 degrees (the
/// outer ring's bore a2 + e delta angle / 90), so that contact covers only part of the interface.
Model quarter_ring_fit(AnalysisType analysis, int radial, int hoop, double eccentricity = 0.0);

/// Switches a ring fit's gaps to the exact method with the schedule the exact-contact tests use
/// (E0 100, then 20, 5, 1: the floor modulus 1).
void use_exact_contact(Model& model);

/// The axisymmetric version: a slice `height` high of both rings, radial quads per ring, one gap
/// element (M along r), every node held in z (the rings in plane strain along z).
Model axisymmetric_ring_fit(int radial, double height);

/// K and f of a model as the exact contact mode assembles them: the initial materials, every gap
/// element at the floor modulus (the schedule's last value).
void assemble_with_gaps_at_floor(const Model& model, StiffnessSystem& system);

}  // namespace saasgaps::testing
