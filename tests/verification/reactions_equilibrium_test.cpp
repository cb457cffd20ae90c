// Global equilibrium of the support reactions (solver/analysis/reactions.hpp) on every example model of
// schemas/examples, as given and, when it has classic gaps, with "gaps.method": "exact": the
// reactions and the applied loads (nodal forces, edge tractions, body forces) sum to zero within
// 1e-9 of the loads, along r and z in plane analyses and along z in axisymmetric ones (radial loads
// are carried by hoop stress). A temperature change alone (report problem 2) is held by reactions
// that sum to zero within 1e-9 of their own size. The result document's `reaction_sum` is the sum
// checked here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

#include "io/model/model_reader.hpp"
#include "io/results/result_writer.hpp"
#include "solver/analysis/analysis.hpp"
#include "solver/analysis/solid_materials.hpp"
#include "solver/assembly/element_data.hpp"
#include "solver/assembly/stiffness_system.hpp"
#include "solver/thermal/thermal_analysis.hpp"
#include "support/examples.hpp"

namespace saasgaps {
namespace {

namespace fs = std::filesystem;

struct ExampleRun {
  std::string file;
  bool exact = false;
};

void PrintTo(const ExampleRun& run, std::ostream* os) { *os << run.file << (run.exact ? " (exact)" : ""); }

std::vector<ExampleRun> runs() {
  std::vector<ExampleRun> out;
  for (const auto& [file, exact] : testing::example_runs()) out.push_back({file, exact});
  return out;
}

/// Sum and sum of magnitudes of a set of forces.
struct Totals {
  Vec2 sum = Vec2::Zero();
  double magnitude = 0.0;
  void add(const Vec2& f) {
    sum += f;
    magnitude += std::abs(f.x()) + std::abs(f.y());
  }
};

/// The applied loads: nodal forces, edge tractions and the elements' body forces. The elements'
/// thermal loads are self-equilibrated (they sum to zero) and are left out: the element loads are
/// taken at the reference temperature.
Totals applied_loads(const Model& model) {
  Totals t;
  for_each_external_load(model, [&t](int, const Vec2& f) { t.add(f); });
  Model cold = model;
  std::fill(cold.loads.node_temperature.begin(), cold.loads.node_temperature.end(), model.reference_temperature);
  const SolidMaterials materials(cold);
  const MaterialState elastic = materials.initial();
  for (std::size_t e = 0; e < cold.elements.size(); ++e) {
    const ElementMatrices m = element_matrices(solid_element_data(cold, e, materials.law(e, elastic)));
    for (int a = 0; a < cold.elements[e].node_count; ++a) t.add(Vec2(m.f[2 * a], m.f[2 * a + 1]));
  }
  return t;
}

class ReactionEquilibrium : public ::testing::TestWithParam<ExampleRun> {};

TEST_P(ReactionEquilibrium, ReactionsBalanceTheAppliedLoads) {
  nlohmann::json doc = testing::example_document(GetParam().file);
  if (GetParam().exact) doc["gaps"]["method"] = "exact";
  const Model model = io::read_model(doc);
  // Models with `thermal` compute their temperatures first (solve_with_heat is solve() without it).
  const Solution s = solve_with_heat(model);
  ASSERT_EQ(s.status, RunStatus::converged) << s.message;

  // The nodes the top-level constraints or any step's hold (a step may prescribe nodes of its own).
  std::set<int> held;
  for (const Constraint& c : model.constraints) {
    if (c.u_r || c.u_z) held.insert(c.node);
  }
  for (const Step& step : model.steps) {
    for (const Constraint& c : step.constraints) {
      if (c.u_r || c.u_z) held.insert(c.node);
    }
  }
  const std::size_t constrained = held.size();
  ASSERT_FALSE(s.reactions.empty());
  EXPECT_LE(s.reactions.size(), constrained);
  Totals reactions;
  for (const NodeReaction& r : s.reactions) reactions.add(Vec2(r.f_r, r.f_z));
  const Totals loads = applied_loads(model);
  // The result document's reaction_sum is that sum, to the last bit (the writer sums in node order
  // too, and doubles read back exactly): the balance below holds for the written figure.
  const nlohmann::json written = nlohmann::json::parse(io::result_text(model, s))["reaction_sum"];
  EXPECT_EQ(written["fr"].get<double>(), reactions.sum.x());
  EXPECT_EQ(written["fz"].get<double>(), reactions.sum.y());

  const bool axisymmetric = model.analysis == AnalysisType::axisymmetric;
  if (loads.magnitude == 0.0) {
    // A temperature change alone: the supports hold the body, and their forces cancel.
    ASSERT_GT(reactions.magnitude, 0.0) << "a restrained thermal expansion needs the supports";
    EXPECT_NEAR(reactions.sum.y(), 0.0, 1e-9 * reactions.magnitude);
    if (!axisymmetric) {
      EXPECT_NEAR(reactions.sum.x(), 0.0, 1e-9 * reactions.magnitude);
    }
    return;
  }
  const Vec2 balance = reactions.sum + loads.sum;
  EXPECT_NEAR(balance.y(), 0.0, 1e-9 * loads.magnitude) << "reactions " << reactions.sum.y() << ", loads " << loads.sum.y();
  if (!axisymmetric) {
    EXPECT_NEAR(balance.x(), 0.0, 1e-9 * loads.magnitude) << "reactions " << reactions.sum.x() << ", loads " << loads.sum.x();
  }
}

INSTANTIATE_TEST_SUITE_P(Examples, ReactionEquilibrium, ::testing::ValuesIn(runs()),
                         [](const ::testing::TestParamInfo<ExampleRun>& run) {
                           std::string name = fs::path(run.param.file).stem().string() + (run.param.exact ? "_method_exact" : "");
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

}  // namespace
}  // namespace saasgaps
