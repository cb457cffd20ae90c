// The progress table (cli/common/progress_table.hpp) on hand-made rows: the friction columns of a run with
// friction, nothing new for a frictionless run, the 120-column limit with every column a run can
// show, and the live line of `saasgaps watch`.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "cli/common/progress_table.hpp"

namespace saasgaps::cli {
namespace {

/// A stepped exact-contact row (every compact column but the classic ones).
IterationRecord exact_row(int iteration) {
  IterationRecord r;
  r.iteration = iteration;
  r.step = 2;
  r.increment = 13;
  r.closed_gaps = 4;
  r.average_closure = 100.0;
  r.max_closure = 100.0;
  r.contact_pairs = 17;
  r.complementarity = 2.0e-15;
  r.active_set_iterations = 3;
  r.seconds = 0.3;
  return r;
}

IterationRecord friction_row(int iteration) {
  IterationRecord r = exact_row(iteration);
  r.stick_points = 11;
  r.slip_points = 6;
  r.friction_residual = 3.0e-13;
  return r;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

/// The words of a line, split at runs of spaces.
std::vector<std::string> words(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream in(line);
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

TEST(ProgressTable, FrictionRowsShowStickSlipAndTheResidual) {
  std::ostringstream out;
  ProgressTable table(out, false, true);
  table.print(friction_row(1));
  table.print(friction_row(2));
  const std::vector<std::string> lines = lines_of(out.str());
  ASSERT_EQ(lines.size(), 3U) << out.str();
  const std::vector<std::string> head = words(lines[0]);
  const std::vector<std::string> row = words(lines[1]);
  // "avg clos %" and "max clos %" are three words each, "N-L non-conv" two.
  ASSERT_EQ(head.size(), row.size() + 5) << lines[0];
  // The friction columns sit before the seconds: stick, slip, friction.
  EXPECT_EQ(std::vector<std::string>(head.end() - 4, head.end()),
            (std::vector<std::string>{"stick", "slip", "friction", "seconds"}));
  EXPECT_EQ(std::vector<std::string>(row.end() - 4, row.end()),
            (std::vector<std::string>{"11", "6", "3.0e-13", "0.300"}));
  // Every column a compact table can show (stepped, exact, friction) still fits 120 characters.
  for (const std::string& line : lines) EXPECT_LE(line.size(), static_cast<std::size_t>(compact_table_width)) << line;
  // Right-aligned under their headings: each value ends where its heading ends.
  for (const char* heading : {"stick", "slip", "friction"}) {
    const std::size_t end = lines[0].find(heading) + std::string(heading).size();
    EXPECT_NE(lines[1][end - 1], ' ') << heading << "\n" << lines[0] << "\n" << lines[1];
    EXPECT_EQ(lines[1][end], ' ') << heading << "\n" << lines[0] << "\n" << lines[1];
  }
}

TEST(ProgressTable, FrictionlessRowsHaveNoFrictionColumns) {
  std::ostringstream out;
  ProgressTable table(out);
  table.print(exact_row(1));
  table.print(exact_row(2));
  EXPECT_EQ(out.str().find("stick"), std::string::npos) << out.str();
  EXPECT_EQ(out.str().find("friction"), std::string::npos) << out.str();
  EXPECT_EQ(lines_of(out.str()).size(), 3U);
  // The same rows under a table told of friction differ only by the friction columns.
  std::ostringstream with;
  ProgressTable friction_table(with, false, true);
  friction_table.print(exact_row(1));
  const std::vector<std::string> plain = lines_of(out.str()), told = lines_of(with.str());
  EXPECT_EQ(told[1], plain[1].substr(0, plain[1].size() - 9) + "     0    0  0.0e+00" +
                         plain[1].substr(plain[1].size() - 9));
}

TEST(ProgressTable, AWatchedRunShowsFrictionColumnsFromTheFirstRowThatHasThem) {
  // `saasgaps watch` does not know the model: the first rows of a run with friction may have no
  // touching point yet; the columns come with the first row that has them, under a new header.
  std::ostringstream out;
  ProgressTable table(out);
  table.print(exact_row(1));
  table.print(friction_row(2));
  table.print(exact_row(3));  // later rows keep the columns (all open again: 0 0)
  const std::vector<std::string> lines = lines_of(out.str());
  ASSERT_EQ(lines.size(), 5U) << out.str();
  EXPECT_EQ(lines[0].find("stick"), std::string::npos);
  EXPECT_NE(lines[2].find("stick"), std::string::npos) << lines[2];
  EXPECT_EQ(lines[2], table.header_text(friction_row(2)));
  EXPECT_NE(lines[3].find("    11    6  3.0e-13"), std::string::npos) << lines[3];
  EXPECT_NE(lines[4].find("     0    0  0.0e+00"), std::string::npos) << lines[4];
}

TEST(ProgressTable, LiveSummaryAddsFrictionOnlyWhenTheRunHasIt) {
  EXPECT_EQ(live_summary(exact_row(5)),
            "  step 2 increment 13  closed 4  pairs 17  complement. 2.0e-15  max clos 100.0 %  0.30 s");
  EXPECT_EQ(live_summary(friction_row(5)),
            "  step 2 increment 13  closed 4  pairs 17  complement. 2.0e-15  max clos 100.0 %  0.30 s"
            "  stick 11  slip 6  friction 3.0e-13");
  IterationRecord classic;
  classic.iteration = 1;
  classic.tensile_modulus = 20.0;
  classic.closed_gaps = 92;
  classic.max_closure = 486.5;
  classic.seconds = 0.5;
  EXPECT_EQ(live_summary(classic), "  E tension 20  closed 92  non-conv -  max clos 486.5 %  0.50 s");
}

TEST(ProgressTable, AModelWithoutGapsHasNoGapColumns) {
  // Issue 33: a plain model's rows hold 0 in every gap column ("E tension 0", "max clos 0.0"),
  // which read as measurements; its table has no such columns.
  IterationRecord plain;
  plain.iteration = 1;
  plain.yielded_elements = 2;
  plain.seconds = 0.25;
  std::ostringstream out;
  ProgressTable table(out);
  table.print(plain);
  const std::string text = out.str();
  for (const char* gone : {"E tension", "> 100 %", "max clos", "avg"}) {
    EXPECT_EQ(text.find(gone), std::string::npos) << gone << " in\n" << text;
  }
  EXPECT_EQ(text.find("non-conv"), text.rfind("non-conv")) << "only N-L non-conv in\n" << text;
  EXPECT_NE(text.find("yielded"), std::string::npos) << text;
  EXPECT_EQ(live_summary(plain), "  yielded 2  0.25 s");
  // A row with gaps keeps them.
  IterationRecord gapped = plain;
  gapped.tensile_modulus = 20.0;
  gapped.gap_closures = {50.0};
  std::ostringstream with;
  ProgressTable(with).print(gapped);
  EXPECT_NE(with.str().find("E tension"), std::string::npos) << with.str();
}

}  // namespace
}  // namespace saasgaps::cli
