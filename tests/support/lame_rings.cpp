#include "support/lame_rings.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

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

double plane_strain_interference_pressure(const RingPair& k, double interference) {
  const double bb = k.b * k.b;
  const double inner = (1.0 + k.nu_in) * k.b * ((1.0 - 2.0 * k.nu_in) * bb + k.a * k.a) / (k.E_in * (bb - k.a * k.a));
  const double outer = (1.0 + k.nu_out) * k.b * ((1.0 - 2.0 * k.nu_out) * bb + k.c * k.c) / (k.E_out * (k.c * k.c - bb));
  return interference / (inner + outer);
}

double plane_stress_interference_pressure(const RingPair& k, double interference) {
  const double bb = k.b * k.b;
  const double inner = k.b * ((1.0 - k.nu_in) * bb + (1.0 + k.nu_in) * k.a * k.a) / (k.E_in * (bb - k.a * k.a));
  const double outer = k.b * ((1.0 - k.nu_out) * bb + (1.0 + k.nu_out) * k.c * k.c) / (k.E_out * (k.c * k.c - bb));
  return interference / (inner + outer);
}

void expect_contact(const Model& m, const Solution& s, double tolerance) {
  ASSERT_EQ(s.status, RunStatus::converged) << s.message;
  const double closure_tolerance = m.gaps->closure_tolerance;
  for (const GapResult& g : s.gaps) {
    EXPECT_GT(g.eps_m, -1.0 - closure_tolerance) << "gap " << g.id;
    EXPECT_LT(g.eps_m, -1.0 + closure_tolerance) << "gap " << g.id;
  }
  // The given clearance closed (closure 1), not the closures the solver reached: an independent check.
  const double p = contact_pressure(1.0);
  ASSERT_GT(p, 0.0);
  double worst = 0.0;
  for (const GapResult& g : s.gaps) {
    const double error = std::abs(-g.sigma_m - p) / p;
    worst = std::max(worst, error);
    EXPECT_LT(error, tolerance) << "gap " << g.id << ": " << g.sigma_m << " vs " << -p;
  }
  std::printf("ring fit: gap pressure within %.3e of Lame's %.1f\n", worst, p);
}

}  // namespace saasgaps::testing::lame_rings
