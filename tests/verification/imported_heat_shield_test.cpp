// The MHW-like heat shield of schemas/examples/assemblies, imported from its .geo: its parts touch on
// contact surfaces (exact face pairs, no gap elements, so no gap can carry load without touching) and
// its temperatures come from the steady conduction solve its thermal section asks for, with heat
// across the contact pairs. Every figure README.md and docs/import.md quote of it is pinned here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <filesystem>
#include <fstream>

#include "io/import/assembly_reader.hpp"
#include "io/model/model_reader.hpp"
#include "solver/assembly/stiffness_system.hpp"
#include "solver/thermal/thermal_analysis.hpp"
#include "support/examples.hpp"
#include "support/quoted_figure.hpp"

namespace saasgaps {
namespace {

using testing::rounds_to;

struct HeatShield {
  Model model;
  Solution solution;
};

const HeatShield& heat_shield() {
  static const HeatShield run = [] {
    const std::filesystem::path dir = std::filesystem::path(SAASGAPS_EXAMPLES_DIR) / "assemblies";
    std::ifstream in(dir / "mhw-heat-shield.assembly.json");
    HeatShield h{io::read_model(io::import_assembly(nlohmann::json::parse(in), dir)), {}};
    h.solution = solve_with_heat(h.model);
    return h;
  }();
  return run;
}

const ContactPairResult& pair_of(const Solution& s, const std::string& side_a) {
  const auto it = std::find_if(s.contact.begin(), s.contact.end(),
                               [&](const ContactPairResult& p) { return p.surfaces[0] == side_a; });
  if (it == s.contact.end()) throw std::runtime_error("no contact pair with side A " + side_a);
  return *it;
}

TEST(ImportedHeatShield, PartsTouchOnContactSurfacesNotGapElements) {
  const auto& [model, s] = heat_shield();
  ASSERT_EQ(s.status, RunStatus::converged) << s.message;
  EXPECT_EQ(s.iterations, 1);  // "converges in 1 iteration"
  EXPECT_FALSE(model.gaps);
  EXPECT_TRUE(s.gaps.empty());
  ASSERT_TRUE(model.contact);
  ASSERT_EQ(s.contact.size(), 2u);
  // The hot retainer grows into the barrel's bore and touches it over its whole height, hardest at
  // its lower edge ("2250 psi").
  const ContactPairResult& retainer = pair_of(s, "retainer_outside");
  ASSERT_EQ(retainer.points.size(), 6u);
  for (const ContactPointResult& p : retainer.points) {
    EXPECT_NE(p.state, ContactPointState::open) << "z = " << p.z;
    EXPECT_GT(p.pressure, 0.0) << "z = " << p.z;
  }
  const auto peak = std::max_element(retainer.points.begin(), retainer.points.end(),
                                     [](const auto& a, const auto& b) { return a.pressure < b.pressure; });
  EXPECT_EQ(peak->z, 0.5);
  EXPECT_TRUE(rounds_to(peak->pressure, "2250"));
  // The cap rests on the barrel's inner edge (r = 2.0, "601 psi"); the rest of the end stays open,
  // up to "0.0011 in" at the outer edge.
  const ContactPairResult& cap = pair_of(s, "barrel_end");
  int touching = 0;
  for (const ContactPointResult& p : cap.points) {
    if (p.state == ContactPointState::open) continue;
    ++touching;
    EXPECT_EQ(p.r, 2.0);
    EXPECT_TRUE(rounds_to(p.pressure, "601"));
  }
  EXPECT_EQ(touching, 1);
  double widest = 0.0;
  for (const ContactPointResult& p : cap.points) widest = std::max(widest, p.gap);
  EXPECT_TRUE(rounds_to(widest, "0.0011"));
}

TEST(ImportedHeatShield, TemperaturesComeFromTheConductionSolve) {
  const auto& [model, s] = heat_shield();
  ASSERT_TRUE(s.thermal);
  const std::vector<double>& T = s.thermal->T;
  ASSERT_EQ(T.size(), model.nodes.size());
  // "800 degF at the barrel's base to 2963 degF at the cap": held at 800 below, the film's 3000
  // degF boundary layer above, which the surface approaches but never reaches.
  const auto [low, high] = std::minmax_element(T.begin(), T.end());
  EXPECT_EQ(*low, 800.0);
  EXPECT_TRUE(rounds_to(*high, "2963"));
  EXPECT_LT(*high, 3000.0);
  for (std::size_t n = 0; n < T.size(); ++n) {
    // The retainer's bore is held at 2000 degF; it is the only node set at r = 1.7.
    if (model.nodes[n].r == 1.7) {
      EXPECT_EQ(T[n], 2000.0) << "node " << model.nodes[n].id;
    }
  }
}

// ReactionEquilibrium's check for this example (which that test also runs on the committed import,
// schemas/examples/mhw-heat-shield.json): along z the supports carry the 15 psi on the cap, the computed temperatures'
// loads being self-equilibrated; along r an axisymmetric ring's radial loads are hoop stress.
TEST(ImportedHeatShield, ReactionsBalanceThePressureOnTheCap) {
  const auto& [model, s] = heat_shield();
  ASSERT_FALSE(s.reactions.empty());
  double applied = 0.0, applied_size = 0.0;
  for_each_external_load(model, [&](int, const Vec2& f) {
    applied += f.y();
    applied_size += std::abs(f.y());
  });
  // 15 psi over the cap's full top, r = 0 .. 2.25 in: 15 pi 2.25^2 lbf downwards.
  EXPECT_NEAR(applied, -15.0 * std::numbers::pi * 2.25 * 2.25, 1e-9 * applied_size);
  double reactions = 0.0;
  for (const NodeReaction& r : s.reactions) reactions += r.f_z;
  EXPECT_NEAR(reactions + applied, 0.0, 1e-9 * applied_size) << "reactions " << reactions << ", loads " << applied;
}

// The example models' copy (schemas/examples/mhw-heat-shield.json, which the tests that walk the
// examples solve) is the import of the assembly as it stands: regenerate it with
//   build/saasgaps import schemas/examples/assemblies/mhw-heat-shield.assembly.json -o schemas/examples/mhw-heat-shield.json
TEST(ImportedHeatShield, TheExampleModelIsTheAssemblysImport) {
  const std::filesystem::path dir = std::filesystem::path(SAASGAPS_EXAMPLES_DIR) / "assemblies";
  std::ifstream in(dir / "mhw-heat-shield.assembly.json");
  EXPECT_EQ(io::import_assembly(nlohmann::json::parse(in), dir), testing::example_document("mhw-heat-shield.json"));
}

}  // namespace
}  // namespace saasgaps
