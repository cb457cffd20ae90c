// The recovery reads what the solve computed (solver/recovery/stress_recovery.cpp): every family
// samples its material points' states from its geometry alone, and the error pass reads an
// isoparametric element's states in place. Those paths must give exactly (bit for bit) what
// evaluating the element again gives, on a distorted axisymmetric element, heated, with a field
// that is not linear.
#include <gtest/gtest.h>

#include <cmath>

#include "solver/fe/element_kernel.hpp"
#include "solver/recovery/error_estimate.hpp"
#include "solver/recovery/sampling_points.hpp"

namespace saasgaps {
namespace {

/// A law with every entry of D distinct and a thermal term.
Constitutive law(double scale) {
  ElasticConstants c;
  c.E1 = 200.0e3 * scale;
  c.E2 = 150.0e3 * scale;
  c.E3 = 120.0e3 * scale;
  c.nu12 = 0.3;
  c.nu13 = 0.25;
  c.nu23 = 0.2;
  c.G12 = 60.0e3 * scale;
  c.alpha1 = c.alpha2 = c.alpha3 = 1.2e-5;
  return constitutive(c, AnalysisType::axisymmetric, 20.0);
}

ElementData element(ElementType type, int nodes) {
  ElementData e;
  e.type = type;
  e.node_count = nodes;
  e.analysis = AnalysisType::axisymmetric;
  const std::array<Vec2, 4> corner{Vec2(1.0, 0.0), Vec2(2.1, 0.2), Vec2(2.3, 1.4), Vec2(0.9, 1.1)};
  for (int a = 0; a < std::min(nodes, 4); ++a) e.x[static_cast<std::size_t>(a)] = corner[static_cast<std::size_t>(a)];
  if (nodes == 3) e.x[2] = corner[2];
  if (nodes == 8) {
    for (std::size_t a = 0; a < 4; ++a) e.x[4 + a] = 0.5 * (corner[a] + corner[(a + 1) % 4]) + Vec2(0.03 * double(a), -0.02);
  }
  for (int a = 0; a < nodes; ++a) e.dT[static_cast<std::size_t>(a)] = 10.0 + 7.0 * a;
  return e;
}

struct Evaluated {
  ElementData data;
  std::vector<double> u;
  std::array<Vec4, max_element_nodes> nodal{};
};

Evaluated evaluated(ElementType type, int nodes) {
  Evaluated v{element(type, nodes), {}, {}};
  for (int a = 0; a < nodes; ++a) {
    const Vec2& x = v.data.x[static_cast<std::size_t>(a)];
    v.u.push_back(1e-3 * x.x() * x.x() - 2e-4 * x.y());
    v.u.push_back(3e-4 * x.x() * x.y() + 1e-4);
    v.nodal[static_cast<std::size_t>(a)] = Vec4(10.0 + a, -5.0 * a, 2.0 + 0.5 * a, 7.0 - a);
  }
  return v;
}

void expect_same(const ElementError& a, const ElementError& b) {
  EXPECT_EQ(a.error2, b.error2);
  EXPECT_EQ(a.norm2, b.norm2);
  EXPECT_GT(a.error2, 0.0);
}

TEST(SharedEvaluation, AReportElementIsSampledAtItsCentreWithItsMaterialPointsStress) {
  for (const int nodes : {4, 3}) {
    Evaluated v = evaluated(nodes == 4 ? ElementType::saas : ElementType::tri3, nodes);
    v.data.law = law(1.0);
    const ElementStates states = element_states(v.data, v.u);
    ASSERT_EQ(states.point_count, 1);
    ElementData geometry = v.data;
    geometry.law = Constitutive{};  // the sampling pass's geometry has no law
    geometry.dT = {};
    const ElementSamples samples = stress_samples(geometry, std::span<const ElementState>(states.point).first(1));
    ASSERT_EQ(samples.count, 1);
    Vec2 centre = Vec2::Zero();
    for (int a = 0; a < nodes; ++a) centre += v.data.x[static_cast<std::size_t>(a)];
    EXPECT_LT((samples.point[0].x - centre / nodes).norm(), 1e-15);
    EXPECT_EQ(samples.point[0].value, states.point[0].stress);
    // Its error integrates over its triangles, solved from its displacements: not its centre value.
    const std::span<const Vec4> nodal = std::span<const Vec4>(v.nodal).first(static_cast<std::size_t>(nodes));
    expect_same(element_error(v.data, states, v.u, nodal), report_element_error(v.data, v.u, nodal));
  }
}

TEST(SharedEvaluation, AnIsoparametricElementsErrorFromItsPointStatesIsTheSame) {
  Evaluated v = evaluated(ElementType::quad8, 8);
  // A law per material point, two of them: the compliance changes between points.
  std::array<Constitutive, max_material_points> per_point;
  for (std::size_t p = 0; p < per_point.size(); ++p) per_point[p] = law(p % 3 == 0 ? 1.0 : 1.5);
  v.data.point_laws = per_point;
  const ElementStates states = element_states(v.data, v.u);
  ASSERT_EQ(states.point_count, 9);
  const std::span<const ElementState> points = std::span<const ElementState>(states.point).first(9);
  const std::span<const Vec4> nodal = std::span<const Vec4>(v.nodal).first(8);
  ElementData geometry = v.data;
  geometry.point_laws = {};
  const ElementSamples samples = stress_samples(geometry, points);
  const ElementSamples before = stress_samples(v.data, points);
  ASSERT_EQ(samples.count, before.count);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(samples.point[k].x, before.point[k].x);
    EXPECT_EQ(samples.point[k].value, before.point[k].value);
  }
  expect_same(element_error(v.data, states, v.u, nodal), element_error(geometry, per_point, points, nodal));
}

}  // namespace
}  // namespace saasgaps
