// The MHW-like heat shield of schemas/examples/assemblies (imported from its .geo with the VTU
// temperature field) solves as docs/import.md says: "The run converges in 6 iterations", with the
// cap's rim closing across its clearance.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "analysis.hpp"
#include "io/assembly_reader.hpp"
#include "io/model_reader.hpp"

namespace saasgaps {
namespace {

TEST(ImportedHeatShield, ConvergesInSixIterations) {
  const std::filesystem::path dir = std::filesystem::path(SAASGAPS_EXAMPLES_DIR) / "assemblies";
  std::ifstream in(dir / "mhw-heat-shield.assembly.json");
  ASSERT_TRUE(in);
  const Model m = io::read_model(io::import_assembly(nlohmann::json::parse(in), dir));
  const Solution s = solve(m);
  ASSERT_EQ(s.status, RunStatus::converged) << s.message;
  EXPECT_EQ(s.iterations, 6);
  int touching = 0;
  for (const GapResult& g : s.gaps) touching += g.state == GapState::closed;
  EXPECT_GT(touching, 0);
}

}  // namespace
}  // namespace saasgaps
