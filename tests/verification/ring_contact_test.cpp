// Our own closed-form check of the gap iteration: two concentric steel rings, the inner one heated
// across a small radial gap into the outer one (support/lame_rings.hpp states Lame's solution). The
// gaps' normal stress must be within the observed deviation from -p (p for the given clearance closed)
// and every gap's closure within the tolerance, both in axisymmetry (a slice of the rings held in z)
// and in plane strain (a quarter annulus, gap elements at many angles). The classic iteration stops
// with the gaps 1.26 % overclosed, so it transmits 0.7-0.8 % less than Lame's pressure.
#include <gtest/gtest.h>

#include <cmath>

#include "solver/analysis/analysis.hpp"
#include "support/lame_rings.hpp"
#include "support/mesh_builder.hpp"
#include "support/quoted_figure.hpp"
#include "support/ring_fit.hpp"

namespace saasgaps {
namespace {

using testing::lame_rings::expect_contact;

void set_gaps(Model& m, double xfact) {
  m.gaps->initial_modulus = 100.0;
  m.gaps->tensile_schedule = {20.0, 5.0, 1.0};
  m.gaps->extrapolation_factor = xfact;
  m.solver.max_iterations = 40;
}

Model axisymmetric_rings(int radial_elements) {
  Model m = testing::axisymmetric_ring_fit(radial_elements, 0.05);
  set_gaps(m, 0.0);
  return m;
}

Model quarter_annulus_rings(int radial_elements, int hoop_elements, double xfact) {
  Model m = testing::quarter_ring_fit(AnalysisType::plane_strain, radial_elements, hoop_elements);
  set_gaps(m, xfact);
  return m;
}

TEST(RingContact, LamePressureOfTheFitIsTheReadmesFigure) {
  // The README's CalculiX comparison (the same rings as make_ring_model.py): "the Lame value (12,610.8 psi)".
  EXPECT_TRUE(testing::rounds_to(testing::lame_rings::contact_pressure(1.0), "12610.8"));
}

TEST(RingContact, AxisymmetricContactPressureMatchesLame) {
  const Model m = axisymmetric_rings(12);
  expect_contact(m, solve(m), 0.0088);  // observed 8.04e-3 low (closure 101.26 %)
}

TEST(RingContact, PlaneStrainQuarterAnnulusWithGapsAtManyAngles) {
  const Model m = quarter_annulus_rings(8, 24, 0.0);
  expect_contact(m, solve(m), 0.008);  // observed 7.26e-3 low (closure 101.26 %)
}

TEST(RingContact, ExtrapolationReachesTheSameContactSooner) {
  const Model plain = quarter_annulus_rings(8, 24, 0.0);
  const Model extrapolating = quarter_annulus_rings(8, 24, 0.5);
  const Solution without = solve(plain);
  const Solution with = solve(extrapolating);
  expect_contact(extrapolating, with, 0.0012);  // observed 1.04e-3 low (closure 100.31 %)
  bool used = false;
  for (const IterationRecord& row : with.history) used = used || row.extrapolated;
  EXPECT_TRUE(used);
  EXPECT_LE(with.iterations, without.iterations);
}

}  // namespace
}  // namespace saasgaps
