// Elastic unloading of yielded elements across load steps (solver/materials/plastic_history.hpp), on a bar in
// plane stress under a uniform end load, where the bilinear curve gives everything in closed form:
//  - loaded past yield to sigma_max, it reaches eps_max = eps_y + (sigma_max - sigma_y) / (PEMR E);
//  - unloaded to zero load it keeps the permanent strain eps_max - sigma_max / E, along slope E;
//  - reloaded, it stays elastic (one iteration per increment) up to sigma_max, and beyond it follows
//    the bilinear curve again;
//  - a run stopped anywhere (mid-unload included) and resumed from its saved state equals the
//    uninterrupted run to the last digit, and a state saved before peaks were kept still resumes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "io/restart/state_codec.hpp"
#include "solver/analysis/analysis.hpp"
#include "solver/assembly/element_data.hpp"
#include "solver/base/errors.hpp"
#include "support/identical_solutions.hpp"
#include "support/mesh_builder.hpp"
#include "support/state_recorder.hpp"
#include "support/state_round_trip.hpp"

namespace saasgaps {
namespace {

constexpr double W = 1.0, H = 4.0, E = 30.0e6, nu = 0.3, yield = 30.0e3, pemr = 0.5;
constexpr double eps_y = yield / E;

using Recorder = testing::StateRecorder;

/// A bar W x H of 2 x 4 quads, held at z = 0 (and r = 0 at one corner), pulled along z by a uniform
/// stress on its top edge. Element 0 is watched: its stress is in every history row.
struct Bar {
  Model model;
  testing::Grid grid;

  /// Loads of a uniform stress sigma on the top edge (consistent nodal forces of each element edge).
  [[nodiscard]] Loads pulled(double sigma) const {
    Loads l;
    for (int i = 0; i < grid.ni; ++i) {
      const double half = 0.5 * sigma * W / grid.ni;
      l.nodal_forces.push_back({grid.at(i, grid.nj), 0.0, half});
      l.nodal_forces.push_back({grid.at(i + 1, grid.nj), 0.0, half});
    }
    return l;
  }
  [[nodiscard]] Step step(std::string name, int increments, double sigma) const {
    return {std::move(name), increments, pulled(sigma), {}};
  }
  /// Axial strain: the top's displacement over the height (the strain is uniform).
  [[nodiscard]] double strain(const RestartState& s) const {
    return s.displacement[2 * static_cast<std::size_t>(grid.at(1, grid.nj)) + 1] / H;
  }
};

Bar bar(double tolerance) {
  Bar b;
  Model& m = b.model;
  m.analysis = AnalysisType::plane_stress;
  Material steel = testing::isotropic_material(1, E, nu);
  steel.plasticity = {{0.0, yield, pemr}};
  m.materials.push_back(steel);
  b.grid = testing::add_grid(m, 2, 4, [](double s, double t) { return Vec2(W * s, H * t); }, 0);
  testing::fill_temperatures(m, 0.0);
  for (int i = 0; i <= b.grid.ni; ++i) {
    testing::constrain(m, b.grid.at(i, 0), i == 0 ? std::optional(0.0) : std::nullopt, 0.0);
  }
  m.output.watch_elements = {0};
  m.solver.plastic_tolerance = tolerance;
  m.solver.max_iterations = 200;
  return b;
}

/// The bilinear curve read backwards: the strain at effective stress sigma (sigma >= yield).
double curve_strain(double sigma) { return eps_y + (sigma - yield) / (pemr * E); }

/// What the run reached at the end of one increment, and how many iterations it took.
struct Reached {
  double stress = 0.0;
  double strain = 0.0;
  int iterations = 0;
  int yielded = 0;
};

std::vector<Reached> per_increment(const Bar& b, const Recorder& r) {
  std::vector<Reached> out;
  int iterations = 0;
  for (std::size_t k = 0; k < r.rows.size(); ++k) {
    ++iterations;
    const bool last = k + 1 == r.rows.size() || r.rows[k + 1].increment != r.rows[k].increment ||
                      r.rows[k + 1].step != r.rows[k].step;
    if (!last) continue;
    const IterationRecord& row = r.rows[k];
    out.push_back({row.watch_elements.at(0).sigma_z, b.strain(r.states[k]), iterations, row.yielded_elements});
    iterations = 0;
  }
  return out;
}

constexpr double sigma_max = 1.25 * yield;

TEST(PlasticUnloading, BarKeepsTheClosedFormPermanentStrainAndReloadsElasticallyToItsPeak) {
  // A tight tolerance: the secant iteration under a load converges linearly, and its answer is then
  // the curve's to 1e-12.
  Bar b = bar(1e-12);
  b.model.steps = {b.step("load", 2, sigma_max), b.step("unload", 2, 0.0), b.step("reload", 2, sigma_max),
                   b.step("beyond", 1, 1.5 * yield)};
  Recorder r;
  const Solution s = solve(b.model, &r);
  ASSERT_EQ(s.status, RunStatus::converged) << s.message;
  const std::vector<Reached> at = per_increment(b, r);
  ASSERT_EQ(at.size(), 7u);
  const Reached &peak = at[1], &half_off = at[2], &off = at[3], &half_on = at[4], &on = at[5], &beyond = at[6];

  // Loaded past yield: the curve's strain at sigma_max.
  const double eps_max = curve_strain(sigma_max);  // 1.5 eps_y
  EXPECT_NEAR(peak.stress, sigma_max, 1e-12 * sigma_max);
  EXPECT_NEAR(peak.strain, eps_max, 1e-10 * eps_max);
  EXPECT_EQ(peak.yielded, 8);

  // Unloaded to zero load: the permanent strain eps_max - sigma_max / E (0.25 eps_y), down slope E.
  EXPECT_NEAR(off.stress, 0.0, 1e-9 * yield);
  EXPECT_NEAR(off.strain, eps_max - sigma_max / E, 1e-10 * eps_max);
  EXPECT_NEAR((peak.stress - half_off.stress) / (peak.strain - half_off.strain), E, 1e-9 * E);
  EXPECT_NEAR((half_off.stress - off.stress) / (half_off.strain - off.strain), E, 1e-9 * E);
  EXPECT_EQ(off.yielded, 0);

  // Reloaded: the same elastic line, one iteration per increment, back to the peak.
  EXPECT_NEAR(half_on.strain, half_off.strain, 1e-12 * eps_max);
  EXPECT_NEAR(on.strain, peak.strain, 1e-12 * eps_max);
  EXPECT_NEAR(on.stress, sigma_max, 1e-12 * sigma_max);
  EXPECT_EQ(half_on.iterations, 1);
  EXPECT_EQ(on.iterations, 1);
  EXPECT_EQ(on.yielded, 8);  // YIELD? reads the effective stress, above sigma_y at the peak

  // Beyond the peak: the bilinear curve again (eps = 2 eps_y at 1.5 sigma_y).
  EXPECT_NEAR(beyond.stress, 1.5 * yield, 1e-12 * yield);
  EXPECT_NEAR(beyond.strain, curve_strain(1.5 * yield), 1e-10 * eps_max);
  EXPECT_GT(beyond.iterations, 1);

  // Every element unloaded the same way: the final field is uniform.
  for (const ElementResult& e : s.elements) EXPECT_NEAR(e.stress[zz], 1.5 * yield, 1e-9 * yield);
}

TEST(PlasticUnloading, ReversedToCompressionItStaysElasticWithinThePeakStress) {
  // From the peak down to -0.8 sigma_y: |sigma| below sigma_max all the way, so the whole path is the
  // elastic line through the permanent strain.
  Bar b = bar(1e-12);
  b.model.steps = {b.step("load", 2, sigma_max), b.step("push", 3, -0.8 * yield)};
  Recorder r;
  const Solution s = solve(b.model, &r);
  ASSERT_EQ(s.status, RunStatus::converged) << s.message;
  const std::vector<Reached> at = per_increment(b, r);
  ASSERT_EQ(at.size(), 5u);
  const double eps_p = curve_strain(sigma_max) - sigma_max / E;
  EXPECT_NEAR(at.back().strain, eps_p - 0.8 * yield / E, 1e-10 * eps_y);
  EXPECT_EQ(at.back().yielded, 0);
}

/// A thick cylinder in plane strain (quarter, a = 1, b = 2, 4 x 4 quads) under internal pressure p.
struct Cylinder {
  Model model;
  testing::Grid grid;
  static constexpr double a = 1.0, b = 2.0;

  [[nodiscard]] Loads pressed(double p) const {
    Loads l;
    for (int j = 0; j < grid.nj; ++j) l.pressures.push_back({grid.ni * j, grid.at(0, j), grid.at(0, j + 1), p, 0.0});
    return l;
  }
  /// Hoop stress of element (i, j) at its centre's angle.
  [[nodiscard]] double hoop(const Solution& s, int i, int j) const {
    const Element& el = model.elements[static_cast<std::size_t>(i + grid.ni * j)];
    Vec2 c = Vec2::Zero();
    for (const Vec2& x : corner_coordinates(model, el.nodes, el.node_count)) c += x / 4.0;
    const double t = std::atan2(c.y(), c.x());
    const Vec4& sg = s.elements[static_cast<std::size_t>(i + grid.ni * j)].stress;
    const double sn = std::sin(t), cs = std::cos(t);
    return sn * sn * sg[rr] + cs * cs * sg[zz] - 2.0 * sn * cs * sg[rz];
  }
};

Cylinder cylinder() {
  Cylinder c;
  Model& m = c.model;
  m.analysis = AnalysisType::plane_strain;
  Material steel = testing::isotropic_material(1, E, nu);
  steel.plasticity = {{0.0, yield, 0.1}};
  m.materials.push_back(steel);
  c.grid = testing::add_grid(
      m, 4, 4,
      [](double s, double t) {
        const double r = Cylinder::a + (Cylinder::b - Cylinder::a) * s;
        const double theta = 0.5 * std::numbers::pi * t;
        return Vec2(r * std::cos(theta), r * std::sin(theta));
      },
      0);
  testing::fill_temperatures(m, 0.0);
  for (int i = 0; i <= c.grid.ni; ++i) {
    testing::constrain(m, c.grid.at(i, 0), std::nullopt, 0.0);          // symmetry about the r axis
    testing::constrain(m, c.grid.at(i, c.grid.nj), 0.0, std::nullopt);  // and about the z axis
  }
  m.solver.max_iterations = 100;
  return c;
}

TEST(PlasticUnloading, PressedCylinderLoadsOnTheSecantLawAndUnloadsToAutofrettageStresses) {
  // Past the bore's yield (about 13 ksi here) in four increments, then back to zero pressure.
  Cylinder c = cylinder();
  c.model.steps = {{"press", 4, c.pressed(20.0e3), {}}, {"release", 2, c.pressed(0.0), {}}};
  Recorder r;
  const Solution s = solve(c.model, &r);
  ASSERT_EQ(s.status, RunStatus::converged) << s.message;

  // Pressing: every element's strain only grows, so none ever leaves the secant law (the run
  // computes exactly what the report's law computed), and the bore yields and keeps peaks.
  std::size_t k = 0;
  int yielded_at_full_pressure = 0;
  for (; k < r.rows.size() && r.rows[k].step == 1; ++k) {
    EXPECT_FALSE(std::count(r.states[k].materials.unloading.begin(), r.states[k].materials.unloading.end(), 1) > 0)
        << "iteration " << k + 1;
    yielded_at_full_pressure = r.rows[k].yielded_elements;
  }
  EXPECT_GT(yielded_at_full_pressure, 0);
  ASSERT_LT(k, r.rows.size());
  EXPECT_FALSE(r.states[k].materials.peaks.empty());

  // Released: the yielded bore unloads elastically and keeps its plastic strain, so the cylinder
  // holds self-equilibrated residual stresses, compressive hoop at the bore and tensile outside
  // (autofrettage). The secant law alone would have returned every stress to zero.
  const RestartState& released = r.states.back();
  EXPECT_TRUE(released.materials.unloads(0));  // the bore element next to the r axis
  EXPECT_EQ(r.rows.back().yielded_elements, 0);
  for (int j = 0; j < c.grid.nj; ++j) {
    EXPECT_LT(c.hoop(s, 0, j), -0.05 * yield) << "bore element, row " << j;
    EXPECT_GT(c.hoop(s, c.grid.ni - 1, j), 0.02 * yield) << "outer element, row " << j;
  }
}

/// Stops the run after every iteration k in turn, resumes through the JSON, CBOR and stored
/// (compressed CBOR) codecs, and expects the uninterrupted run to the last digit.
void expect_exact_resumes(const Model& model, const Recorder& all, const Solution& uninterrupted) {
  const std::string digest = "plastic-test";
  for (int k = 1; k < uninterrupted.iterations; ++k) {
    SCOPED_TRACE("stopped after iteration " + std::to_string(k));
    Recorder first(k);
    ASSERT_EQ(solve(model, &first).status, RunStatus::stopped);
    const RestartState& saved = first.states.back();
    EXPECT_EQ(saved.version, RestartState::plastic_steps_version);
    EXPECT_EQ(saved.materials, all.states[static_cast<std::size_t>(k - 1)].materials);
    for (const std::string_view codec : testing::state_codecs) {
      SCOPED_TRACE(codec);
      const RestartState from = testing::through_codec(codec, saved, digest);
      EXPECT_EQ(from.materials, saved.materials);
      testing::expect_identical(solve(model, nullptr, &from), uninterrupted);
    }
  }
}

TEST(PlasticUnloading, RunStoppedAnywhereResumesToTheLastDigit) {
  // The default tolerance keeps the run short; the unload's first increment switches every element
  // to the elastic branch, so stops fall before, at and after the switch.
  Bar b = bar(0.01);
  b.model.steps = {b.step("load", 2, sigma_max), b.step("unload", 2, 0.0), b.step("reload", 1, 1.5 * yield)};
  Recorder all;
  const Solution uninterrupted = solve(b.model, &all);
  ASSERT_EQ(uninterrupted.status, RunStatus::converged) << uninterrupted.message;
  // The run does go through the unloading branch and keeps peaks (else this proves nothing).
  int unloading_states = 0;
  for (const RestartState& s : all.states) {
    if (!s.materials.unloading.empty() && s.materials.unloads(0)) ++unloading_states;
  }
  EXPECT_GE(unloading_states, 2);
  expect_exact_resumes(b.model, all, uninterrupted);
}

TEST(PlasticUnloading, StateFromBeforePeaksWereKeptStillResumes) {
  // A version-2 state (no `plastic` member) of a plastic stepped model, saved in the first step where
  // no element has a peak yet, resumes and ends where the uninterrupted run ends.
  Bar b = bar(0.01);
  b.model.steps = {b.step("load", 2, sigma_max), b.step("unload", 1, 0.0)};
  const Solution uninterrupted = solve(b.model);
  Recorder first(1);
  solve(b.model, &first);
  nlohmann::json document = io::state_to_json(first.states.back(), "d");
  ASSERT_TRUE(document.contains("plastic"));
  ASSERT_TRUE(document.at("plastic").at("peaks").empty());
  document.erase("plastic");
  document["version"] = RestartState::stepped_version;
  const RestartState old = io::state_from_json(document, "d");
  EXPECT_EQ(old.version, RestartState::stepped_version);
  testing::expect_identical(solve(b.model, nullptr, &old), uninterrupted);
}

TEST(PlasticUnloading, MalformedPlasticMembersAreRefused) {
  Bar b = bar(0.01);
  b.model.steps = {b.step("load", 2, sigma_max), b.step("unload", 1, 0.0)};
  Recorder all;
  solve(b.model, &all);
  const RestartState& unloading = all.states.back();
  ASSERT_TRUE(unloading.materials.unloads(0));
  const nlohmann::json good = io::state_to_json(unloading, "d");
  ASSERT_EQ(good.at("plastic").at("peaks").size(), 8u);
  ASSERT_EQ(good.at("plastic").at("peaks").at(0).size(), 7u);

  const auto refused = [](nlohmann::json document, const std::string& why) {
    try {
      io::state_from_json(document, "d");
      ADD_FAILURE() << "accepted: " << why;
    } catch (const SolverError& e) {
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
  };
  nlohmann::json no_plastic = good;
  no_plastic.erase("plastic");
  refused(no_plastic, "malformed restart state");
  nlohmann::json short_peak = good;
  short_peak["plastic"]["peaks"][0].erase(6);
  refused(short_peak, "not 7 numbers");
  nlohmann::json far = good;
  far["plastic"]["unloading"].push_back(8);
  refused(far, "plastic material point index 8 out of range");
  nlohmann::json v2 = good;
  v2["version"] = RestartState::stepped_version;
  refused(v2, "version 2 has no plastic peaks");

  // Decoded, an element that unloads from no peak does not belong to the run.
  RestartState orphan = io::state_from_json(good, "d");
  orphan.materials.peaks[3] = PlasticPeak{};
  EXPECT_THROW(solve(b.model, nullptr, &orphan), SolverError);
  // A plain model takes no peaks.
  Bar plain = bar(0.01);
  plain.model.loads = plain.pulled(sigma_max);
  RestartState foreign = io::state_from_json(good, "d");
  foreign.version = RestartState::plain_version;
  foreign.position.reset();
  EXPECT_THROW(solve(plain.model, nullptr, &foreign), SolverError);
}

}  // namespace
}  // namespace saasgaps
