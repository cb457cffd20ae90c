// Answers that must not look trustworthy when they are not (issue 22): a body pulled off its gaps is
// a failed run with the reason, not "converged", and a gap angle along the gap is a bad model.
#include <functional>

#include "command_fixture.hpp"

namespace {

using saasgaps::testing::Outcome;

class ContactAnswers : public saasgaps::testing::CommandTest {
 protected:
  /// Report problem 1 with one change, written to model.json; returns its path.
  std::string problem1(const std::function<void(nlohmann::json&)>& change) const {
    nlohmann::json model = json_of(example("report-problem1.json"));
    change(model);
    std::ofstream(path("model.json")) << model.dump();
    return path("model.json");
  }
};

TEST_F(ContactAnswers, ABodyPulledOffItsGapsFailsInClassicModeWithTheReason) {
  const std::string model = problem1([](nlohmann::json& m) {
    for (auto& p : m["loads"]["pressures"]) p["normal"] = -p["normal"].get<double>();
  });
  const Outcome r = saasgaps("solve " + model + " -q -o " + path("result.json"));
  EXPECT_EQ(r.exit_code, 1) << r.err;  // docs/cli.md: a run that fails
  EXPECT_NE(r.err.find("error: the contact problem has no solution: 100."), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("% of the load is carried by the floor stiffness of gaps open at the floor modulus (gap "),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("converged"), std::string::npos) << r.err;
  const nlohmann::json result = json_of(path("result.json"));
  EXPECT_EQ(result["status"], "failed");
  EXPECT_NE(result["message"].get<std::string>().find("pushed away from every support"), std::string::npos);
}

TEST_F(ContactAnswers, AGapAngleAlongTheGapIsABadModelAtItsPointer) {
  // Gap 13 is horizontal (it closes along z): angle 0 runs along it.
  const std::string model = problem1([](nlohmann::json& m) { m["gaps"]["elements"][3]["angle"] = 0.0; });
  for (const std::string& command : {std::string("validate "), "solve -q -o " + path("result.json") + " "}) {
    const Outcome r = saasgaps(command + model);
    EXPECT_EQ(r.exit_code, 2) << command << r.err;
    EXPECT_NE(r.err.find("invalid model: 1 error\n/gaps/elements/3/angle: angle 0 does not run across gap element 13"),
              std::string::npos)
        << r.err;
  }
}

}  // namespace
