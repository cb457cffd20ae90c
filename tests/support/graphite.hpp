#pragma once
/// The orthotropic graphite of the kernel tests: moduli, Poisson ratios and expansions all
/// different, so that a law rotated off its axes couples every component.

#include "solver/materials/material.hpp"

namespace saasgaps::testing {

inline ElasticConstants graphite() {
  ElasticConstants c;
  c.E1 = 1.6e6;
  c.E2 = 1.1e6;
  c.E3 = 1.3e6;
  c.nu12 = 0.12;
  c.nu13 = 0.1;
  c.nu23 = 0.15;
  c.G12 = 0.45e6;
  c.alpha1 = 2.0e-6;
  c.alpha2 = 3.0e-6;
  c.alpha3 = 2.5e-6;
  return c;
}

}  // namespace saasgaps::testing
