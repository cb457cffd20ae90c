// The model of the README's service walk-through, `python3 schemas/examples/make_block_model.py 120`,
// is what the README says: "a 120 x 120 block on a row of 120 gaps, about 29,000 unknowns, 21
// iterations". The script is run as the README runs it (Debian's python3), its output read and solved.
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <string>

#include "io/model/model_reader.hpp"
#include "solver/analysis/analysis.hpp"
#include "solver/assembly/dof_map.hpp"
#include "support/quoted_figure.hpp"

namespace saasgaps {
namespace {

std::string output_of(const std::string& command) {
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  if (!pipe) throw std::runtime_error("cannot run " + command);
  std::string out;
  char buffer[65536];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe.get())) > 0;) out.append(buffer, n);
  return out;
}

TEST(WalkthroughBlock, SizeAndIterationsAsTheReadmeSays) {
  const std::string text =
      output_of(std::string(SAASGAPS_PYTHON3) + " " + SAASGAPS_EXAMPLES_DIR + "/make_block_model.py 120");
  const Model m = io::read_model(nlohmann::json::parse(text));
  EXPECT_EQ(m.elements.size(), 120U * 120U);
  EXPECT_EQ(m.gaps->elements.size(), 120U);
  EXPECT_TRUE(testing::rounds_to(static_cast<double>(DofMap(m).size()) / 1000.0, "29"));
  const Solution s = solve(m);
  EXPECT_EQ(s.status, RunStatus::converged) << s.message;
  EXPECT_EQ(s.iterations, 21);
}

}  // namespace
}  // namespace saasgaps
