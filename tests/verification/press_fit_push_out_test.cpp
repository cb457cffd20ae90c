// The press fit then push-out of issue 33, from a .geo and one assembly with two steps, imported and
// solved with no script (schemas/examples/assemblies/press-fit-push-out.assembly.json): two steel
// cylinders, inner ID 20 / OD 40.005 mm in outer ID 40 / OD 60 mm, 19 mm long, mu = 0.1. Step 1
// presses, step 2 pushes the inner cylinder out by a prescribed z on its face's node set "pushed".
// The face's set_reactions fz, read from the history at the end of every increment, rises while
// the interface sticks and holds at mu p pi d L within 1 % once every point slips, p by Lame.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "io/import/assembly_reader.hpp"
#include "io/model/model_reader.hpp"
#include "solver/analysis/analysis.hpp"

namespace saasgaps {
namespace {

/// Lame's interference pressure of two cylinders of one material (E), bore a, interface b, outside
/// c, radial interference delta: p = E delta / b * (b^2 - a^2)(c^2 - b^2) / (2 b^2 (c^2 - a^2)).
double lame_pressure(double E, double a, double b, double c, double delta) {
  return E * delta / b * (b * b - a * a) * (c * c - b * b) / (2.0 * b * b * (c * c - a * a));
}

const SetReaction* find_set(const std::vector<SetReaction>& sums, const std::string& name) {
  for (const SetReaction& s : sums) {
    if (s.set == name) return &s;
  }
  return nullptr;
}

TEST(PressFitPushOut, PushedFaceForceReachesCoulombLimitFromTheHistory) {
  const std::filesystem::path dir = std::filesystem::path(SAASGAPS_EXAMPLES_DIR) / "assemblies";
  std::ifstream in(dir / "press-fit-push-out.assembly.json");
  ASSERT_TRUE(in);
  const nlohmann::json document = io::import_assembly(nlohmann::json::parse(in), dir);
  // The groups the assembly uses survive as named sets; the push names the face's node set.
  ASSERT_TRUE(document.contains("sets"));
  EXPECT_TRUE(document["sets"]["nodes"].contains("pushed"));
  EXPECT_TRUE(document["sets"]["edges"].contains("pushed"));
  EXPECT_TRUE(document["sets"]["elements"].contains("inner"));
  EXPECT_EQ(document["steps"][1]["constraints"][0], (nlohmann::json{{"set", "pushed"}, {"z", 0.001}}));
  const Model m = io::read_model(document);
  ASSERT_EQ(m.reaction_groups.size(), 1u);
  EXPECT_EQ(m.reaction_groups[0].name, "pushed");
  EXPECT_EQ(m.reaction_groups[0].nodes.size(), document["sets"]["nodes"]["pushed"].size());

  const Solution s = solve(m);
  ASSERT_EQ(s.status, RunStatus::converged) << s.message;

  const double p = lame_pressure(210000.0, 10.0, 20.0, 30.0, 0.0025);
  EXPECT_NEAR(p, 6.152, 0.001);  // the figure
  const double limit = 0.1 * p * std::numbers::pi * 40.0 * 19.0;
  EXPECT_NEAR(limit, 1469.0, 1.0);

  // The end of every increment of the push, in order, from the history alone.
  std::vector<double> force;
  std::vector<int> sticking;
  for (const IterationRecord& row : s.history) {
    if (row.set_reactions.empty()) continue;
    ASSERT_EQ(row.pair_forces.size(), 1u);  // a pair force at every increment's end too
    if (row.step != 2) continue;
    const SetReaction* pushed = find_set(row.set_reactions, "pushed");
    ASSERT_NE(pushed, nullptr);
    force.push_back(pushed->f_z);
    sticking.push_back(row.stick_points);
  }
  ASSERT_EQ(force.size(), 10u);
  // Rises over the first increments (the first sticks in part), then flat at mu p pi d L.
  EXPECT_GT(force.front(), 0.0);
  EXPECT_LT(force.front(), 0.9 * limit);
  std::size_t all_slip = force.size();
  for (std::size_t k = 0; k < force.size(); ++k) {
    if (sticking[k] == 0 && all_slip == force.size()) all_slip = k;
    if (k > 0 && k <= all_slip) EXPECT_GT(force[k], force[k - 1]) << "increment " << k + 1;
  }
  ASSERT_LT(all_slip, force.size() - 2) << "every point slips before the last increments";
  for (std::size_t k = all_slip; k < force.size(); ++k) {
    EXPECT_NEAR(force[k], limit, 0.01 * limit) << "increment " << k + 1;
    EXPECT_NEAR(force[k], force.back(), 1e-3 * limit) << "flat once every point slips";
  }
  std::printf("push-out force %.2f N at increment %zu, %.2f N at the end; mu p pi d L = %.2f N\n",
              force[all_slip], all_slip + 1, force.back(), limit);
  // The result's set_reactions are the last increment's.
  ASSERT_EQ(s.set_reactions.size(), 1u);
  EXPECT_EQ(s.set_reactions[0].f_z, force.back());
}

}  // namespace
}  // namespace saasgaps
