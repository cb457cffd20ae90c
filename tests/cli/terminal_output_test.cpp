// What a person at a terminal sees: the iteration table fits 120 columns (all of it with --wide),
// exact-mode runs show their own columns, a result document is never poured onto the screen, counts
// read "1 material", and the limits of a run's settings are the same on every way in.
#include <pty.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "command_fixture.hpp"

namespace {

using saasgaps::testing::Outcome;

#define EXPECT_CONTAINS(text, part) EXPECT_NE((text).find(part), std::string::npos) << (text)

class TerminalOutput : public saasgaps::testing::CommandTest {
 protected:
  /// Runs saasgaps in the scratch directory with stdout and stderr on a pseudo-terminal; `out`
  /// holds everything the terminal showed.
  [[nodiscard]] Outcome on_terminal(const std::vector<std::string>& arguments) const {
    int terminal = -1;
    const pid_t child = ::forkpty(&terminal, nullptr, nullptr, nullptr);
    if (child == 0) {
      if (::chdir(dir_.c_str()) != 0) ::_exit(126);
      std::vector<char*> argv{const_cast<char*>(SAASGAPS_BINARY)};
      for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
      argv.push_back(nullptr);
      ::execv(SAASGAPS_BINARY, argv.data());
      ::_exit(127);
    }
    Outcome r;
    if (child < 0) return r;
    char buffer[4096];
    for (;;) {
      const ssize_t n = ::read(terminal, buffer, sizeof buffer);
      if (n > 0) {
        r.out.append(buffer, static_cast<std::size_t>(n));
      } else if (n < 0 && errno == EINTR) {
        continue;
      } else {
        break;  // EIO: the child closed the terminal
      }
    }
    ::close(terminal);
    int status = 0;
    ::waitpid(child, &status, 0);
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
  }

  /// The table's lines on stderr: the header and the rows under it (not the closing message).
  static std::vector<std::string> table_lines(const std::string& err) {
    std::vector<std::string> lines;
    std::istringstream in(err);
    bool in_table = false;
    for (std::string line; std::getline(in, line);) {
      if (line.find(" iter ") != std::string::npos || line.rfind(" iter", 0) == 0) in_table = true;
      else if (in_table && (line.size() < 5 || line[0] != ' ')) in_table = false;
      if (in_table) lines.push_back(line);
    }
    return lines;
  }

  static std::size_t widest(const std::vector<std::string>& lines) {
    std::size_t width = 0;
    for (const std::string& line : lines) width = std::max(width, line.size());
    return width;
  }
};

TEST_F(TerminalOutput, CompactTableFitsOneHundredTwentyColumnsAndWideShowsTheWatchedItems) {
  // Problem 3 watches one element and two gaps: nine more columns, about 220 characters in all.
  const Outcome compact = saasgaps("solve " + example("report-problem3-case1.json") + " -o " + path("r.json"));
  ASSERT_EQ(compact.exit_code, 0) << compact.err;
  const std::vector<std::string> lines = table_lines(compact.err);
  ASSERT_GE(lines.size(), 3U) << compact.err;
  EXPECT_LE(widest(lines), 120U) << compact.err;
  EXPECT_CONTAINS(lines.front(), "E tension");
  EXPECT_EQ(lines.front().find("el "), std::string::npos) << lines.front();

  const Outcome wide = saasgaps("solve " + example("report-problem3-case1.json") + " --wide -o " + path("r.json"));
  ASSERT_EQ(wide.exit_code, 0) << wide.err;
  const std::vector<std::string> wide_lines = table_lines(wide.err);
  ASSERT_EQ(wide_lines.size(), lines.size());
  EXPECT_GT(widest(wide_lines), 120U);
  EXPECT_CONTAINS(wide_lines.front(), " s_th");
  EXPECT_CONTAINS(wide_lines.front(), " clos %");
}

TEST_F(TerminalOutput, GapCountsSayWhatTheyCountAndNoMeanOfNothing) {
  // docs/results.md, "Gap words": "closed" is the gap state (touching). The classic table counts the
  // report's gaps past 100 % instead, and says so; its mean over none of them is "-", not 0.0.
  std::size_t rows_without_any = 0, rows_with_some = 0;
  for (const char* model : {"report-problem2.json", "report-problem3-case1.json"}) {
    const Outcome r = saasgaps(std::string("solve ") + example(model) + " -o " + path("r.json"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::vector<std::string> lines = table_lines(r.err);
    ASSERT_GE(lines.size(), 2U) << r.err;
    EXPECT_CONTAINS(lines.front(), " > 100 %");
    EXPECT_CONTAINS(lines.front(), " avg > 100 %");
    EXPECT_EQ(lines.front().find("closed"), std::string::npos) << lines.front();
    for (std::size_t k = 1; k < lines.size(); ++k) {
      std::istringstream in(lines[k]);
      std::string iteration, modulus, count, nonconverged, average;
      in >> iteration >> modulus >> count >> nonconverged >> average;
      if (count == "0") {
        ++rows_without_any;
        EXPECT_EQ(average, "-") << lines[k];
      } else {
        ++rows_with_some;
        EXPECT_NE(average, "-") << lines[k];
        EXPECT_GT(std::stod(average), 100.0) << lines[k];
      }
    }
  }
  EXPECT_GT(rows_without_any, 0U) << "no row shows the empty mean";
  EXPECT_GT(rows_with_some, 0U);
  // The exact mode counts the closed (touching) gaps, and heads the column so.
  const Outcome exact = saasgaps("solve " + example("report-problem3-case1-exact.json") + " -o " + path("e.json"));
  ASSERT_EQ(exact.exit_code, 0) << exact.err;
  EXPECT_CONTAINS(table_lines(exact.err).front(), " closed");
  EXPECT_CONTAINS(table_lines(exact.err).front(), " avg clos %");
}

TEST_F(TerminalOutput, ExactModeTableShowsTheExactColumnsNotTheClassicOnes) {
  const Outcome r = saasgaps("solve " + example("report-problem3-case1-exact.json") + " -o " + path("r.json"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> lines = table_lines(r.err);
  ASSERT_GE(lines.size(), 2U) << r.err;
  EXPECT_LE(widest(lines), 120U) << r.err;
  EXPECT_CONTAINS(lines.front(), "pairs");
  EXPECT_CONTAINS(lines.front(), "complement.");
  EXPECT_EQ(lines.front().find("E tension"), std::string::npos) << lines.front();
  // Only the plastic "N-L non-conv" column: the gaps' non-convergence is a classic-mode notion.
  EXPECT_EQ(lines.front().find("non-conv"), lines.front().find("N-L non-conv") + 4) << lines.front();
  EXPECT_EQ(lines.front().find("non-conv", lines.front().find("non-conv") + 1), std::string::npos) << lines.front();
}

TEST_F(TerminalOutput, SolveWithoutOutputOnATerminalWritesTheResultNextToTheModel) {
  std::filesystem::copy_file(example("report-problem1.json"), path("block.json"));
  const Outcome r = on_terminal({"solve", "block.json", "-q"});
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_CONTAINS(r.out, "result written to block.result.json");
  EXPECT_EQ(r.out.find("\"status\""), std::string::npos) << "the result went to the screen:\n" << r.out;
  EXPECT_EQ(json_of(path("block.result.json"))["status"], "converged");
}

TEST_F(TerminalOutput, DashOutputIsStandardOutputEvenOnATerminal) {
  std::filesystem::copy_file(example("report-problem1.json"), path("block.json"));
  const Outcome r = on_terminal({"solve", "block.json", "-q", "-o", "-"});
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_CONTAINS(r.out, "\"status\":\"converged\"");
  EXPECT_FALSE(std::filesystem::exists(path("block.result.json")));
}

TEST_F(TerminalOutput, CountsOfOneAreSingular) {
  const Outcome r = saasgaps("validate " + example("report-problem1.json"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_CONTAINS(r.out, " elements, ");
  EXPECT_CONTAINS(r.out, ", 1 material\n");
  std::ofstream(path("bad.json")) << "{}";
  const Outcome bad = saasgaps("validate " + path("bad.json"));
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_EQ(bad.err.find(" 1 errors"), std::string::npos) << bad.err;
}

TEST_F(TerminalOutput, ModelIterationLimitIsTheCommandLinesLimit) {
  nlohmann::json model = json_of(example("report-problem1.json"));
  model["solver"]["max_iterations"] = 1000000000;
  std::ofstream(path("model.json")) << model.dump();
  const Outcome r = saasgaps("validate " + path("model.json"));
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_CONTAINS(r.err, "/solver/max_iterations");
  EXPECT_CONTAINS(r.err, "max_iterations <= 100000");
  model["solver"]["max_iterations"] = 100000;
  std::ofstream(path("model.json")) << model.dump();
  EXPECT_EQ(saasgaps("validate " + path("model.json")).exit_code, 0);
}

}  // namespace
