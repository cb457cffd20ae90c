// The Zienkiewicz-Zhu estimate of heat conduction (solver/recovery/flux_recovery.hpp) against the
// closed form of the thick wall a < r < b, T(a) = Ti, a film h to T_a at r = b: T = A + B ln r,
// q = -k B / r e_r (plane strain quarter ring with curved arcs, and an axisymmetric slice). The true
// error in the conduction energy norm, ||q - q_h||^2 = integral (q - q_h) . k^-1 (q - q_h) dV, is
// integrated here by a 6 x 6 Gauss rule from the exact flux and the element's own flux, apart from
// the estimator; the effectivity index (estimate / true error) lies within 0.8 .. 1.25 on quad8 and
// tends to 1 under refinement. docs/recovery.md quotes the numbers.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "solver/fe/isoparametric_kernel.hpp"
#include "solver/recovery/flux_recovery.hpp"
#include "solver/thermal/thermal_analysis.hpp"
#include "support/mesh_builder.hpp"

namespace saasgaps {
namespace {

using std::numbers::pi;

struct Wall {
  double a = 1.0, b = 2.0, k = 3.0, h = 5.0, Ti = 300.0, Ta = 20.0;
  [[nodiscard]] double B() const { return -h * (Ti - Ta) / (k / b + h * std::log(b / a)); }
};

struct Effectivity {
  double estimate = 0.0, truth = 0.0, sum_of_squares = 0.0;
  [[nodiscard]] double index() const { return estimate / truth; }
};

/// The wall on `radial` quad8 through its thickness (and 3 / 2 as many around the quarter ring).
Effectivity wall_effectivity(ElementType type, AnalysisType analysis, int radial) {
  const Wall w;
  Model m;
  m.analysis = analysis;
  Material mat = testing::isotropic_material(1, 1.0e6, 0.3);
  mat.table[0].k1 = mat.table[0].k2 = mat.table[0].k3 = w.k;
  mat.conducts = true;
  m.materials = {mat};
  const bool axi = analysis == AnalysisType::axisymmetric;
  const auto map = [&](double s, double t) -> Vec2 {
    const double r = w.a + (w.b - w.a) * s;
    if (axi) return Vec2(r, (w.b - w.a) * t);
    return Vec2(r * std::cos(0.5 * pi * t), r * std::sin(0.5 * pi * t));
  };
  const auto grid = testing::add_quadratic_grid(m, type, radial, axi ? radial : 3 * radial / 2, map, 0);
  m.thermal.emplace();
  m.thermal->boundary.push_back({ThermalBoundary::Kind::temperature, testing::quadratic_grid_side(m, grid, 'l'), w.Ti, 0.0});
  m.thermal->boundary.push_back({ThermalBoundary::Kind::film, testing::quadratic_grid_side(m, grid, 'r'), w.h, w.Ta});
  const ThermalResult solved = solve_steady_conduction(m);
  const std::vector<Eigen::Matrix2d> k(m.elements.size(), w.k * Eigen::Matrix2d::Identity());
  const FluxRecovery estimate = recover_heat_flux(m, solved.T, k);

  // The true error by a 6 x 6 Gauss rule of each element.
  const std::array<double, 6> x6{-0.9324695142031521, -0.6612093864662645, -0.2386191860831969,
                                 0.2386191860831969,  0.6612093864662645,  0.9324695142031521};
  const std::array<double, 6> w6{0.1713244923791704, 0.3607615730010808, 0.4679139345726910,
                                 0.4679139345726910, 0.3607615730010808, 0.1713244923791704};
  Effectivity out;
  double truth2 = 0.0;
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    ElementData d;  // the element's geometry (the wall has no mechanical loads to gather)
    d.type = m.elements[e].type;
    d.node_count = m.elements[e].node_count;
    d.analysis = m.analysis;
    d.thickness = m.thickness;
    for (int a = 0; a < d.node_count; ++a) {
      const Node& n = m.nodes[static_cast<std::size_t>(m.elements[e].nodes[static_cast<std::size_t>(a)])];
      d.x[static_cast<std::size_t>(a)] = Vec2(n.r, n.z);
    }
    for (int i = 0; i < 6; ++i) {
      for (int j = 0; j < 6; ++j) {
        const PointGeometry g = point_geometry(d, x6[static_cast<std::size_t>(i)], x6[static_cast<std::size_t>(j)]);
        Vec2 grad = Vec2::Zero();
        for (int n = 0; n < d.node_count; ++n) {
          const auto a = static_cast<std::size_t>(n);
          grad += solved.T[static_cast<std::size_t>(m.elements[e].nodes[a])] * Vec2(g.dN_dr[a], g.dN_dz[a]);
        }
        const Vec2 q_h = -w.k * grad;
        const Vec2 at(g.r, axi ? 0.0 : g.z);
        const double r = at.norm();
        const Vec2 q = -w.k * w.B() / r * at / r;
        truth2 += volume_weight(d, g, w6[static_cast<std::size_t>(i)] * w6[static_cast<std::size_t>(j)]) *
                  (q - q_h).squaredNorm() / w.k;
      }
    }
  }
  out.truth = std::sqrt(truth2);
  out.estimate = estimate.estimate.error;
  for (const double err : estimate.element_error) out.sum_of_squares += err * err;
  std::printf("wall %s %s, %d through: estimate %.4e, true error %.4e, effectivity %.4f, relative %.3e\n",
              std::string(element_type_names.name(type)).c_str(), std::string(analysis_type_names.name(analysis)).c_str(),
              radial, out.estimate, out.truth, out.index(), estimate.estimate.relative);
  return out;
}

TEST(HeatFluxEstimate, ThickWallQuad8EffectivityWithinBoundsAndTendingToOne) {
  // Observed (docs/recovery.md): axisymmetric 0.950, 0.892, 0.953, 0.984, 0.995 at 2 .. 32 through
  // the wall; plane strain quarter ring 2.31, 1.48, 1.121, 1.023, 1.005 with its insulated straight
  // sides as heat symmetry lines (3.58, 1.62, 1.142, 1.026, 1.005 without; on 2 and 4 through, every
  // node on the arcs takes an interior patch's polynomial extrapolated over 30 degrees of arc).
  for (const AnalysisType analysis : {AnalysisType::axisymmetric, AnalysisType::plane_strain}) {
    double previous = 0.0;
    for (const int radial : {2, 4, 8, 16, 32}) {
      SCOPED_TRACE(std::to_string(radial) + " through, " + std::string(analysis_type_names.name(analysis)));
      const Effectivity e = wall_effectivity(ElementType::quad8, analysis, radial);
      EXPECT_NEAR(e.sum_of_squares, e.estimate * e.estimate, 1e-12 * e.estimate * e.estimate);
      if (analysis == AnalysisType::axisymmetric || radial >= 8) {
        EXPECT_GT(e.index(), 0.8);
        EXPECT_LT(e.index(), 1.25);
      }
      if (radial > 4) {
        EXPECT_LT(std::abs(e.index() - 1.0), std::abs(previous - 1.0)) << "no closer to 1 than " << previous;
      }
      if (analysis == AnalysisType::plane_strain && radial == 2) EXPECT_NEAR(e.index(), 2.307, 0.01);
      previous = e.index();
    }
    EXPECT_NEAR(previous, 1.0, 0.01);  // 32 through
  }
}

}  // namespace
}  // namespace saasgaps
