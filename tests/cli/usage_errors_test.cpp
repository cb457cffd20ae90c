// Mistakes a user makes on the command line, one test each: the exit code docs/cli.md documents and
// a message that names the mistake (and, for a usage error, one line and where the help is).
#include <filesystem>

#include "command_fixture.hpp"

namespace {

using saasgaps::testing::Outcome;

class UsageErrors : public saasgaps::testing::CommandTest {
 protected:
  static constexpr int usage = 64;

  /// A small solved result, for the commands that read one.
  std::string solved_result() const {
    const std::string result = path("result.json");
    EXPECT_EQ(saasgaps("solve " + example("report-problem1.json") + " -q -o " + result).exit_code, 0);
    return result;
  }
};

#define EXPECT_CONTAINS(text, part) EXPECT_NE((text).find(part), std::string::npos) << (text)

TEST_F(UsageErrors, MistypedCommandIsNamedWithTheNearestOne) {
  const Outcome r = saasgaps("solv " + example("report-problem1.json"));
  EXPECT_EQ(r.exit_code, usage);
  EXPECT_EQ(r.err, "saasgaps: unknown command 'solv'; did you mean 'solve'?\n"
                   "run 'saasgaps --help' for the commands\n");
}

TEST_F(UsageErrors, NoCommandListsTheCommands) {
  const Outcome r = saasgaps("");
  EXPECT_EQ(r.exit_code, usage);
  EXPECT_CONTAINS(r.err, "a command is required (solve, study, validate, ");
  EXPECT_CONTAINS(r.err, "serve, worker, plot, probe, export-vtu");
}

TEST_F(UsageErrors, MistypedOptionIsOneLineWithTheNearestOneAndAHint) {
  const Outcome r = saasgaps("solve --max-iteration 5 " + example("report-problem1.json"));
  EXPECT_EQ(r.exit_code, usage);
  // One line and the hint, not the fifty lines of the help that would bury it.
  EXPECT_EQ(r.err, "saasgaps solve: unknown option '--max-iteration'; did you mean '--max-iterations'?\n"
                   "run 'saasgaps solve --help' for its options\n");
}

TEST_F(UsageErrors, MissingArgumentIsAUsageError) {
  const Outcome r = saasgaps("plot " + example("report-problem1.json"));
  EXPECT_EQ(r.exit_code, usage);
  EXPECT_CONTAINS(r.err, "saasgaps plot: --output is required");
  EXPECT_CONTAINS(r.err, "run 'saasgaps plot --help' for its options");
  EXPECT_EQ(r.err.find("Usage:"), std::string::npos) << r.err;
}

TEST_F(UsageErrors, ImageSideHasTheServicesLimit) {
  // One range for both ways of asking for a plot: 16 .. 4000 px, as GET .../plots?width= (the
  // service test refuses width=4001 there).
  const std::string result = solved_result();
  for (const char* option : {"--width", "--height"}) {
    const Outcome r = saasgaps("plot " + result + " --field effective -o " + path("p.png") + " " + option + " 4001");
    EXPECT_EQ(r.exit_code, usage) << option;
    EXPECT_CONTAINS(r.err, "4001");
    EXPECT_CONTAINS(r.err, "4000");
  }
}

TEST_F(UsageErrors, BadOptionValueNamesTheValue) {
  const Outcome r = saasgaps("solve " + example("report-problem1.json") + " --max-iterations many");
  EXPECT_EQ(r.exit_code, usage);
  EXPECT_CONTAINS(r.err, "--max-iterations: must be an integer from 1 to 100000, got \"many\"");
  const Outcome beyond = saasgaps("solve " + example("report-problem1.json") + " --max-iterations 100001");
  EXPECT_EQ(beyond.exit_code, usage);
  EXPECT_CONTAINS(beyond.err, "--max-iterations: must be an integer from 1 to 100000, got \"100001\"");
  // XFACT may be 0 but not 1: the rule in words, not "not in range 0.000000 to 1.000000".
  const Outcome one = saasgaps("solve " + example("report-problem1.json") + " --extrapolation 1");
  EXPECT_EQ(one.exit_code, usage);
  EXPECT_CONTAINS(one.err, "--extrapolation: must be a number at least 0 and below 1, got \"1\"");
  EXPECT_EQ(one.err.find("0.000000"), std::string::npos) << one.err;
  const Outcome schedule = saasgaps("solve " + example("report-problem1.json") + " --schedule 2,-1");
  EXPECT_EQ(schedule.exit_code, usage);
  EXPECT_CONTAINS(schedule.err, "--schedule: must be a number > 0, got \"-1\"");
}

TEST_F(UsageErrors, ScheduleOrFactorForAModelWithoutGapsIsRefusedNotIgnored) {
  // A schedule the run would not use is a mistake to say, not to ignore (the HTTP body says so too).
  const Outcome schedule = saasgaps("solve -o - --schedule 5,6 " + example("report-beam-model-a.json"));
  EXPECT_EQ(schedule.exit_code, usage);
  EXPECT_EQ(schedule.err, "saasgaps solve --schedule: the model has no gaps, so it has no tensile schedule\n");
  EXPECT_EQ(schedule.out, "");
  const Outcome factor = saasgaps("solve -o - --extrapolation 0.5 " + example("report-beam-model-a.json"));
  EXPECT_EQ(factor.exit_code, usage);
  EXPECT_EQ(factor.err, "saasgaps solve --extrapolation: the model has no gaps, so nothing to extrapolate\n");
}

TEST_F(UsageErrors, VersionAndHelpExitZero) {
  const Outcome version = saasgaps("--version");
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_EQ(version.out.rfind("saasgaps ", 0), 0U) << version.out;
  const Outcome help = saasgaps("solve --help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_CONTAINS(help.out, "--resume");
}

TEST_F(UsageErrors, MissingOutputDirectoryFailsBeforeTheSolve) {
  // Problem 3 case 3 takes 13 iterations; the check must come before the first one.
  const Outcome r = saasgaps("solve " + example("report-problem3-case3.json") + " -o " + path("missing/result.json"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_CONTAINS(r.err, "-o " + path("missing/result.json") + ": the directory " + path("missing") + " does not exist");
  EXPECT_EQ(r.err.find("iter"), std::string::npos) << "the solve started:\n" << r.err;
  const Outcome state = saasgaps("solve " + example("report-problem1.json") + " --state-out " + path("missing/s.json"));
  EXPECT_EQ(state.exit_code, 1);
  EXPECT_CONTAINS(state.err, "--state-out " + path("missing/s.json") + ": the directory");
}

TEST_F(UsageErrors, UnwritableOutputDirectoryFailsBeforeTheSolve) {
  if (::geteuid() == 0) GTEST_SKIP() << "root writes into read-only directories";
  std::filesystem::create_directories(path("locked"));
  std::filesystem::permissions(path("locked"), std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
  const Outcome r = saasgaps("solve " + example("report-problem1.json") + " -o " + path("locked/result.json"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_CONTAINS(r.err, "is not writable");
}

TEST_F(UsageErrors, DirectoryAsOutputIsNamed) {
  const Outcome r = saasgaps("solve " + example("report-problem1.json") + " -o " + dir_.string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_CONTAINS(r.err, "-o " + dir_.string() + ": is a directory; give a file name");
}

TEST_F(UsageErrors, DirectoryAsModelIsNamed) {
  const Outcome r = saasgaps("solve " + dir_.string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_CONTAINS(r.err, "cannot read " + dir_.string() + ": it is a directory, not a file");
  EXPECT_EQ(r.err.find("JSON"), std::string::npos) << r.err;
}

TEST_F(UsageErrors, ModelHandedToPlotOrExportSaysRunSolveFirst) {
  for (const std::string command : {"plot", "export-vtu"}) {
    const Outcome r = saasgaps(command + " " + example("report-problem1.json") + " -o " + path("out.png"));
    EXPECT_EQ(r.exit_code, 1) << command;
    EXPECT_CONTAINS(r.err, example("report-problem1.json") + " is a model, not a result; run solve first");
    EXPECT_EQ(r.err.find("json.exception"), std::string::npos) << r.err;
  }
}

TEST_F(UsageErrors, ResultHandedToSolveOrValidateSaysSo) {
  const std::string result = solved_result();
  for (const std::string command : {"solve", "validate"}) {
    const Outcome r = saasgaps(command + " " + result);
    EXPECT_EQ(r.exit_code, 2) << command;
    EXPECT_CONTAINS(r.err, "invalid model: 1 error\n(document): this is a result document");
  }
}

TEST_F(UsageErrors, RestartStateHandedToSolveSaysSo) {
  ASSERT_EQ(saasgaps("solve " + example("report-problem1.json") + " -q --state-out " + path("state.json") + " -o " +
                     path("result.json")).exit_code, 0);
  const Outcome r = saasgaps("solve " + path("state.json"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_CONTAINS(r.err, "this is a restart state");
  EXPECT_CONTAINS(r.err, "--resume");
}

TEST_F(UsageErrors, FetchRefusesAPlotIntoAFileOfAnotherFormat) {
  // Checked before any connection: no server listens on port 9.
  const std::string csv = path("job9-cp.csv");
  const Outcome r = saasgaps("fetch 9 --plot contact_pressure -o " + csv + " --server http://127.0.0.1:9");
  EXPECT_EQ(r.exit_code, usage);
  EXPECT_CONTAINS(r.err, "PNG or SVG");
  EXPECT_CONTAINS(r.err, "job9-cp.csv");
  EXPECT_FALSE(std::filesystem::exists(csv));
  const Outcome mixed = saasgaps("fetch 9 --plot closure.svg -o " + path("c.png") + " --server http://127.0.0.1:9");
  EXPECT_EQ(mixed.exit_code, usage);
  EXPECT_CONTAINS(mixed.err, "the plot is svg but FILE ends in .png");
}

TEST_F(UsageErrors, AlongIsRefusedByEveryPlotWithoutARow) {
  const std::string result = solved_result();
  for (const char* field : {"friction", "effective", "convergence", "force"}) {
    const Outcome r = saasgaps("plot " + result + " --field " + std::string(field) + " --along z -o " + path("p.png"));
    EXPECT_NE(r.exit_code, 0) << field;
    EXPECT_CONTAINS(r.err, "--along z: only the closure and contact_pressure plots");
  }
}

TEST_F(UsageErrors, ForcePlotNamesTheSetsThereAre) {
  const std::string result = solved_result();  // report problem 1: no set names a constraint
  const Outcome none = saasgaps("plot " + result + " --field force --set pushed -o " + path("f.png"));
  EXPECT_NE(none.exit_code, 0);
  EXPECT_CONTAINS(none.err, "no reactions of set 'pushed'");
  const Outcome unset = saasgaps("plot " + result + " --field effective --set pushed -o " + path("f.png"));
  EXPECT_NE(unset.exit_code, 0);
  EXPECT_CONTAINS(unset.err, "only --field force");
}

}  // namespace
