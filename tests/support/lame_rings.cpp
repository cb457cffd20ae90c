#include "support/lame_rings.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace saasgaps::testing::lame_rings {

double contact_pressure(double closure) {
  const double free_growth = (1.0 + nu) * alpha * dT * b1;
  // Radial displacements per unit pressure.
  const double Ai = -b1 * b1 / (b1 * b1 - a1 * a1), Bi = Ai * a1 * a1;
  const double inner = (1.0 + nu) / E * ((1.0 - 2.0 * nu) * Ai * b1 + Bi / b1);
  const double Ao = a2 * a2 / (b2 * b2 - a2 * a2), Bo = Ao * b2 * b2;
  const double outer = (1.0 + nu) / E * ((1.0 - 2.0 * nu) * Ao * a2 + Bo / a2);
  return (closure * delta - free_growth) / (inner - outer);
}

void expect_contact(const Model& m, const Solution& s) {
  ASSERT_EQ(s.status, RunStatus::converged) << s.message;
  const double tolerance = m.gaps->closure_tolerance;
  double closure_sum = 0.0;
  for (const GapResult& g : s.gaps) {
    EXPECT_GT(g.eps_m, -1.0 - tolerance) << "gap " << g.id;
    EXPECT_LT(g.eps_m, -1.0 + tolerance) << "gap " << g.id;
    closure_sum += g.closure / 100.0;
  }
  const double p = contact_pressure(closure_sum / static_cast<double>(s.gaps.size()));
  ASSERT_GT(p, 0.0);
  for (const GapResult& g : s.gaps) {
    EXPECT_LT(std::abs(-g.sigma_m - p) / p, 0.02) << "gap " << g.id << ": " << g.sigma_m << " vs " << -p;
  }
}

}  // namespace saasgaps::testing::lame_rings
