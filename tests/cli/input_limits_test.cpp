// Issue 17: files nested 10^5 deep made `saasgaps import` die with SIGSEGV (exit 139). Every command
// that reads a document refuses one deeper than 64 levels with a message naming the place and the
// limit: a model or an assembly is a bad model (exit 2), a restart state or a result file a file that
// does not fit (exit 1). Never a signal.
#include "command_fixture.hpp"

namespace {

using saasgaps::testing::Outcome;

constexpr int deep = 100000;

class InputLimits : public saasgaps::testing::CommandTest {
 protected:
  /// Writes `text` to a file of the scratch directory; returns its path.
  [[nodiscard]] std::string file(const std::string& name, const std::string& text) const {
    std::ofstream(path(name)) << text;
    return path(name);
  }
  /// The example model with 10^5 nested arrays as its first node.
  [[nodiscard]] std::string deep_model() const {
    std::string model = read(example("report-problem1.json"));
    model.replace(model.find("\"nodes\": ["), 10,
                  "\"nodes\": [" + std::string(deep, '[') + std::string(deep, ']') + ",");
    return file("deep-model.json", model);
  }
};

void expect_refused(const Outcome& r, int exit_code, const std::string& pointer_start) {
  EXPECT_EQ(r.exit_code, exit_code) << r.err;
  EXPECT_NE(r.err.find(pointer_start), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("deeper than 64 levels"), std::string::npos) << r.err;
}

TEST_F(InputLimits, DeepModelsAreBadModels) {
  const std::string model = deep_model();
  expect_refused(saasgaps("validate " + model), 2, "/nodes/0/0/0/");
  expect_refused(saasgaps("solve " + model + " -o " + path("result.json")), 2, "/nodes/0/0/0/");
}

TEST_F(InputLimits, DeepAssembliesAreBadModels) {
  // The import of issue 17: the assembly is `[` x 10^5.
  expect_refused(saasgaps("import " + file("deep.assembly.json", std::string(deep, '[')) + " -o " + path("m.json")), 2,
                 "/0/0/0/");
  // Objects in a real assembly's member.
  std::string assembly = read(example("assemblies/ring-fit.assembly.json"));
  std::string nested;
  for (int k = 0; k < deep; ++k) nested += "{\"a\":";
  nested += "1" + std::string(deep, '}');
  assembly.replace(0, 1, "{\"title\": " + nested + ",");
  expect_refused(saasgaps("import " + file("ring-fit.assembly.json", assembly) + " -o " + path("m.json")), 2,
                 "/title/a/a/");
}

TEST_F(InputLimits, DeepRestartStatesAndResultsAreFilesThatDoNotFit) {
  const std::string nested = std::string(deep, '[') + std::string(deep, ']');
  expect_refused(saasgaps("solve " + example("report-problem1.json") + " --resume " +
                          file("state.json", "{\"format\": " + nested + "}") + " -o " + path("result.json")),
                 1, "/format/0/0/");
  expect_refused(saasgaps("plot " + file("result.json", "{\"status\": " + nested + "}") + " -o " + path("p.png")), 1,
                 "/status/0/0/");
}

}  // namespace
