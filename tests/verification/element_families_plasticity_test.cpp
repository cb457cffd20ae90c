// Bilinear plasticity and exact restarts on the quadratic element families (quad8, full 3 x 3 and
// reduced 2 x 2 integration), where the material state lives at 9 or 4 material points per element
// (solver/fe/material_points.hpp). Every model is a JSON document read through io::read_model.
//
// 1. A bar W x H in plane stress, 2 x 4 quad8 (straight-edged rectangles, and a distorted mesh:
//    interior corners moved, interior edges curved), held at z = 0 and pulled by a prescribed top
//    displacement, so the axial strain eps is known and the stress uniaxial and uniform:
//      - loaded to eps = 2 eps_y: sigma = sigma_y + PEMR E (eps - eps_y) = 1.5 sigma_y, every element
//        yielded;
//      - unloaded to zero displacement: elastic along slope E from the peak, sigma = E (0 - eps_p)
//        with eps_p = eps_max - sigma_max / E = 0.5 eps_y, so sigma = -0.5 sigma_y, none yielded;
//      - reloaded to eps = 2.5 eps_y: back up the elastic line and on along the curve, 1.75 sigma_y.
// 2. A run of that bar stopped after every iteration k and resumed from its state through the JSON,
//    CBOR and stored codecs equals the uninterrupted run to the last digit; the state's
//    dimensions carry material_points = 9 (full) or 4 (reduced) x elements, and a state of the
//    report's 4-node elements has no such member.
// 3. A state of the full-integration model resumed on the reduced one (same nodes and elements,
//    other material points) is refused with "dimensions differ".
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/model/model_reader.hpp"
#include "io/restart/state_codec.hpp"
#include "solver/analysis/analysis.hpp"
#include "solver/base/errors.hpp"
#include "support/identical_solutions.hpp"
#include "support/state_recorder.hpp"
#include "support/state_round_trip.hpp"

namespace saasgaps {
namespace {

using nlohmann::json;
using Recorder = testing::StateRecorder;

constexpr double W = 1.0, H = 4.0, E = 30.0e6, nu = 0.3, yield = 30.0e3, pemr = 0.5;
constexpr double eps_y = yield / E;
constexpr int ni = 2, nj = 4;

/// The bilinear curve: the uniaxial stress at strain eps >= eps_y on first loading.
double curve_stress(double eps) { return yield + pemr * E * (eps - eps_y); }

enum class Shape { rectangles, distorted };

/// The bar's mesh: node coordinates, which nodes are on the bottom (z = 0) and top (z = H), and the
/// cells (quad8: corners counter-clockwise, then the mid-side nodes of edges 1-2, 2-3, 3-4, 4-1;
/// 4-node: corners only).
struct BarMesh {
  std::vector<Vec2> x;
  std::vector<bool> bottom, top;
  std::vector<std::vector<int>> cells;
};

BarMesh bar_mesh(bool quadratic, Shape shape) {
  BarMesh m;
  const double dx = W / ni, dy = H / nj;
  const auto corner_at = [&](int i, int j) {
    Vec2 p(dx * i, dy * j);
    if (shape == Shape::distorted && j > 0 && j < nj) {
      // Side corners slide along their side; interior corners move both ways.
      const double along = (j % 2 == 0 ? 1.0 : -1.0) * 0.2 * dy;
      p.y() += (i == 0 ? 0.5 : i == ni ? -0.3 : 1.0) * along;
      if (i > 0 && i < ni) p.x() += (j % 2 == 0 ? -0.12 : 0.18) * dx;
    }
    return p;
  };
  std::vector<std::vector<int>> corner(ni + 1, std::vector<int>(nj + 1));
  std::vector<std::vector<int>> horizontal(ni, std::vector<int>(nj + 1)), vertical(ni + 1, std::vector<int>(nj));
  const auto add = [&](Vec2 p, bool on_bottom, bool on_top) {
    m.x.push_back(p);
    m.bottom.push_back(on_bottom);
    m.top.push_back(on_top);
    return static_cast<int>(m.x.size()) - 1;
  };
  /// The mid-side node of a-b; an interior edge of the distorted mesh bulges across by 8 % of its length.
  const auto mid = [&](Vec2 a, Vec2 b, bool interior, double side, bool on_bottom, bool on_top) {
    Vec2 p = 0.5 * (a + b);
    if (shape == Shape::distorted && interior) p += side * 0.08 * Vec2(-(b - a).y(), (b - a).x());
    return add(p, on_bottom, on_top);
  };
  for (int j = 0; j <= nj; ++j) {
    for (int i = 0; i <= ni; ++i) corner[i][j] = add(corner_at(i, j), j == 0, j == nj);
  }
  if (quadratic) {
    for (int j = 0; j <= nj; ++j) {
      for (int i = 0; i < ni; ++i) {
        horizontal[i][j] = mid(corner_at(i, j), corner_at(i + 1, j), j > 0 && j < nj, (i + j) % 2 ? 1.0 : -1.0, j == 0,
                               j == nj);
      }
    }
    for (int j = 0; j < nj; ++j) {
      for (int i = 0; i <= ni; ++i) {
        vertical[i][j] = mid(corner_at(i, j), corner_at(i, j + 1), i > 0 && i < ni, (i + j) % 2 ? -1.0 : 1.0, false, false);
      }
    }
  }
  for (int j = 0; j < nj; ++j) {
    for (int i = 0; i < ni; ++i) {
      std::vector<int> cell{corner[i][j], corner[i + 1][j], corner[i + 1][j + 1], corner[i][j + 1]};
      if (quadratic) {
        cell.insert(cell.end(), {horizontal[i][j], vertical[i + 1][j], horizontal[i][j + 1], vertical[i][j]});
      }
      m.cells.push_back(cell);
    }
  }
  return m;
}

/// A load step that prescribes the top nodes' u_z to the axial strain eps (times H).
json step(const BarMesh& m, const std::string& name, int increments, double eps) {
  json constraints = json::array();
  for (std::size_t n = 0; n < m.x.size(); ++n) {
    if (m.top[n]) constraints.push_back({{"node", n + 1}, {"z", eps * H}});
  }
  return {{"name", name}, {"increments", increments}, {"constraints", constraints}};
}

/// The plane-stress bar of `type` ("quad8" or "saas") and `integration` ("" for none), held along
/// z on the bottom and along r at the bottom-left corner, plastic with the bilinear curve.
json bar_document(const BarMesh& m, const std::string& type, const std::string& integration, double tolerance) {
  json doc = {{"schema_version", 1}, {"title", "plastic bar: " + type + " " + integration}};
  doc["analysis"] = {{"type", "plane_stress"}, {"thickness", 1.0}};
  json nodes = json::array();
  for (std::size_t i = 0; i < m.x.size(); ++i) nodes.push_back({{"id", i + 1}, {"r", m.x[i].x()}, {"z", m.x[i].y()}});
  doc["nodes"] = nodes;
  doc["materials"] = json::array({{{"id", 1},
                                   {"elastic", "isotropic"},
                                   {"table", json::array({{{"T", 0.0}, {"E", E}, {"nu", nu}, {"alpha", 0.0}}})},
                                   {"plasticity", {{"yield_stress", yield}, {"hardening_ratio", pemr}}}}});
  json elements = json::array();
  for (std::size_t e = 0; e < m.cells.size(); ++e) {
    json ids = json::array();
    for (const int n : m.cells[e]) ids.push_back(n + 1);
    json element = {{"id", e + 1}, {"nodes", ids}, {"material", 1}, {"type", type}};
    if (!integration.empty()) element["integration"] = integration;
    elements.push_back(element);
  }
  doc["elements"] = elements;
  json constraints = json::array();
  for (std::size_t n = 0; n < m.x.size(); ++n) {
    if (!m.bottom[n]) continue;
    json c = {{"node", n + 1}, {"z", 0.0}};
    if (m.x[n].x() == 0.0) c["r"] = 0.0;
    constraints.push_back(c);
  }
  doc["constraints"] = constraints;
  doc["loads"] = json::object();
  doc["solver"] = {{"plastic_tolerance", tolerance}, {"max_iterations", 200}};
  return doc;
}

// ---- 1. The closed form.

struct ClosedFormCase {
  const char* integration;
  Shape shape;
  const char* name;
};

class FamiliesPlasticQuad8Bar : public ::testing::TestWithParam<ClosedFormCase> {};

/// The largest deviation of every element's centre stress from the uniaxial sigma_z = `expected`
/// (the other components 0), and checks every element's YIELD? flag.
double worst_deviation(const Solution& s, double expected, bool yielded, const char* where) {
  double worst = 0.0;
  for (const ElementResult& e : s.elements) {
    const Vec4 exact(0.0, expected, 0.0, 0.0);
    worst = std::max(worst, (e.stress - exact).cwiseAbs().maxCoeff());
    EXPECT_EQ(e.yielded, yielded) << where << ", element " << e.id;
  }
  return worst;
}

TEST_P(FamiliesPlasticQuad8Bar, LoadUnloadReloadFollowTheBilinearCurveAndTheElasticLine) {
  const ClosedFormCase& c = GetParam();
  const BarMesh m = bar_mesh(true, c.shape);
  const double eps_max = 2.0 * eps_y, sigma_max = curve_stress(eps_max);  // 1.5 sigma_y
  const double eps_p = eps_max - sigma_max / E;                           // 0.5 eps_y
  const double eps_beyond = 2.5 * eps_y;
  const json loaded = step(m, "load", 2, eps_max), unloaded = step(m, "unload", 2, 0.0),
             reloaded = step(m, "reload", 2, eps_beyond);
  const auto run = [&](json steps) {
    json doc = bar_document(m, "quad8", c.integration, 1e-12);
    doc["steps"] = std::move(steps);
    const Solution s = solve(io::read_model(doc));
    EXPECT_EQ(s.status, RunStatus::converged) << s.message;
    return s;
  };
  const Solution peak = run({loaded});
  const Solution off = run({loaded, unloaded});
  const Solution beyond = run({loaded, unloaded, reloaded});
  ASSERT_EQ(peak.elements.size(), 8u);

  const double at_peak = worst_deviation(peak, sigma_max, true, "peak");
  const double at_off = worst_deviation(off, E * (0.0 - eps_p), false, "unloaded");  // -0.5 sigma_y
  const double at_beyond = worst_deviation(beyond, curve_stress(eps_beyond), true, "reloaded");  // 1.75 sigma_y
  std::printf("quad8 %s bar: worst stress error of sigma_y at the peak %.2e, unloaded %.2e, reloaded %.2e "
              "(iterations %d, %d, %d)\n",
              c.name, at_peak / yield, at_off / yield, at_beyond / yield, peak.iterations, off.iterations,
              beyond.iterations);
  // Observed at most 2.4e-14 sigma_y (reduced, distorted, at the peak); the secant law alone would be
  // off by 0.5 sigma_y after the unload (it returns to zero stress at zero strain).
  EXPECT_LT(at_peak, 1e-12 * yield);
  EXPECT_LT(at_off, 1e-12 * yield);
  EXPECT_LT(at_beyond, 1e-12 * yield);
  // The top is where it was prescribed and the bottom did not move along z: a uniform strain.
  for (std::size_t n = 0; n < m.x.size(); ++n) {
    if (m.top[n]) {
      EXPECT_DOUBLE_EQ(beyond.nodes[n].u_z, eps_beyond * H);
    }
  }
}

std::string closed_form_name(const ::testing::TestParamInfo<ClosedFormCase>& info) { return info.param.name; }

INSTANTIATE_TEST_SUITE_P(ElementFamiliesPlasticity, FamiliesPlasticQuad8Bar,
                         ::testing::Values(ClosedFormCase{"full", Shape::rectangles, "full_rectangles"},
                                           ClosedFormCase{"full", Shape::distorted, "full_distorted"},
                                           ClosedFormCase{"reduced", Shape::rectangles, "reduced_rectangles"},
                                           ClosedFormCase{"reduced", Shape::distorted, "reduced_distorted"}),
                         closed_form_name);

// ---- 2. Exact restarts.

/// The restart bar: loaded past yield in two increments, unloaded in one and reloaded beyond the
/// peak in one, at the default tolerance (short increments), on the distorted mesh.
json restart_document(bool quadratic, const std::string& type, const std::string& integration) {
  const BarMesh m = bar_mesh(quadratic, Shape::distorted);
  json doc = bar_document(m, type, integration, 0.01);
  doc["steps"] = {step(m, "load", 2, 2.0 * eps_y), step(m, "unload", 1, 0.5 * eps_y), step(m, "reload", 1, 2.5 * eps_y)};
  return doc;
}

class FamiliesPlasticQuad8Restart : public ::testing::TestWithParam<const char*> {};

TEST_P(FamiliesPlasticQuad8Restart, StoppedAnywhereResumesToTheLastDigit) {
  const std::string integration = GetParam();
  const json doc = restart_document(true, "quad8", integration);
  const Model model = io::read_model(doc);
  const std::string digest = io::model_digest(doc);
  const std::size_t points_per_element = integration == "full" ? 9 : 4;
  Recorder all;
  const Solution uninterrupted = solve(model, &all);
  ASSERT_EQ(uninterrupted.status, RunStatus::converged) << uninterrupted.message;
  ASSERT_GE(uninterrupted.iterations, 4);
  // The run does unload elastically (else the peaks' restart proves little).
  int unloading_states = 0;
  for (const RestartState& s : all.states) {
    if (!s.materials.unloading.empty() && s.materials.unloads(0)) ++unloading_states;
  }
  EXPECT_GE(unloading_states, 1);
  std::printf("quad8 %s restart: %d iterations, %d states unloading at point 0\n", integration.c_str(),
              uninterrupted.iterations, unloading_states);

  for (int k = 1; k < uninterrupted.iterations; ++k) {
    SCOPED_TRACE("stopped after iteration " + std::to_string(k));
    Recorder first(k);
    const Solution stopped = solve(model, &first);
    ASSERT_EQ(stopped.status, RunStatus::stopped);
    const RestartState& saved = first.states.back();
    EXPECT_EQ(saved.materials, all.states[static_cast<std::size_t>(k - 1)].materials);
    const json encoded = io::state_to_json(saved, digest);
    ASSERT_TRUE(encoded.at("dimensions").contains("material_points"));
    EXPECT_EQ(encoded.at("dimensions").at("material_points").get<std::size_t>(), points_per_element * 8);
    EXPECT_EQ(encoded.at("dimensions").at("elements").get<std::size_t>(), 8u);
    EXPECT_EQ(saved.materials.secant_ratio.size(), points_per_element * 8);
    for (const std::string_view codec : testing::state_codecs) {
      SCOPED_TRACE(codec);
      const RestartState from = testing::through_codec(codec, saved, digest);
      EXPECT_EQ(from.material_point_count, points_per_element * 8);
      EXPECT_EQ(from.materials, saved.materials);
      testing::expect_identical(solve(model, nullptr, &from), uninterrupted);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(ElementFamiliesPlasticity, FamiliesPlasticQuad8Restart, ::testing::Values("full", "reduced"));

TEST(FamiliesPlasticSaasRestart, StateOfTheReportsElementsHasNoMaterialPointsMember) {
  const json doc = restart_document(false, "saas", "");
  const Model model = io::read_model(doc);
  const std::string digest = io::model_digest(doc);
  Recorder first(3);
  ASSERT_EQ(solve(model, &first).status, RunStatus::stopped);
  const RestartState& saved = first.states.back();
  EXPECT_EQ(saved.material_point_count, saved.element_count);
  const json encoded = io::state_to_json(saved, digest);
  EXPECT_FALSE(encoded.at("dimensions").contains("material_points")) << encoded.at("dimensions").dump();
  // Its bytes as before material points: the dimensions written as they always were.
  json before = encoded;
  before["dimensions"] = {{"nodes", model.nodes.size()}, {"elements", model.elements.size()}, {"gaps", 0}};
  EXPECT_EQ(io::state_to_cbor(saved, digest), json::to_cbor(before));
  // And it resumes to the last digit.
  const Solution uninterrupted = solve(model);
  for (const std::string_view codec : testing::state_codecs) {
    SCOPED_TRACE(codec);
    const RestartState from = testing::through_codec(codec, saved, digest);
    testing::expect_identical(solve(model, nullptr, &from), uninterrupted);
  }
}

// ---- 3. A state of other material points.

TEST(FamiliesPlasticQuad8Restart, StateOfOtherMaterialPointsIsRefusedNotCrashed) {
  const json full = restart_document(true, "quad8", "full"), reduced = restart_document(true, "quad8", "reduced");
  const auto state_of = [](const json& doc) {
    Recorder first(3);
    EXPECT_EQ(solve(io::read_model(doc), &first).status, RunStatus::stopped);
    return first.states.back();
  };
  const auto expect_refused = [](const json& doc, const RestartState& from) {
    try {
      solve(io::read_model(doc), nullptr, &from);
      ADD_FAILURE() << "resumed";
    } catch (const SolverError& e) {
      EXPECT_NE(std::string(e.what()).find("dimensions differ"), std::string::npos) << e.what();
    }
  };
  const auto refused = [&](const json& doc, const RestartState& state, const char* what) {
    for (const std::string_view codec : testing::state_codecs) {
      SCOPED_TRACE(std::string(what) + ", " + std::string(codec));
      // Decoded without a digest, as a resume past the digest check would: the solver must refuse it.
      expect_refused(doc, testing::through_codec(codec, state, ""));
    }
  };
  refused(reduced, state_of(full), "full state, reduced model");
  refused(full, state_of(reduced), "reduced state, full model");
  // A state whose vectors fit the model but whose dimensions name another count of material points
  // (in memory: the codec would read its vectors at that length) is refused as well.
  RestartState mislabelled = state_of(full);
  ASSERT_EQ(mislabelled.materials.secant_ratio.size(), 9u * 8u);
  mislabelled.material_point_count = 4 * 8;
  SCOPED_TRACE("full state labelled with 32 points");
  expect_refused(full, mislabelled);
}

}  // namespace
}  // namespace saasgaps
