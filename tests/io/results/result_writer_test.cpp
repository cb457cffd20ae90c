/// The streamed result document (io/result_writer.hpp) against the tree writer it replaced
/// (result_tree_reference.hpp): for the report problems and for a random solution, the compact text
/// read back keeping its key order prints exactly as the tree does (same keys, same order, same
/// doubles to the last bit), and --pretty is the same document indented. Also the writer's number
/// and string formats on their own.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/json/json_writer.hpp"
#include "io/json/parallel_items.hpp"
#include "io/results/history_json.hpp"
#include "io/results/result_tree_reference.hpp"
#include "io/results/result_writer.hpp"
#include "solver/analysis/analysis.hpp"
#include "support/examples.hpp"

namespace saasgaps::io {
namespace {

using nlohmann::json;
using nlohmann::ordered_json;

std::string streamed(const Model& model, const Solution& solution, bool pretty) {
  std::string text;
  JsonWriter out(string_sink(text), pretty);
  write_result(out, model, solution);
  out.flush();
  return text;
}

/// The text without the whitespace between tokens (string literals kept as they are).
std::string without_layout(const std::string& text) {
  std::string out;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      out += c;
      if (c == '\\') {
        out += text[++i];
      } else if (c == '"') {
        in_string = false;
      }
    } else if (c == '"') {
      in_string = true;
      out += c;
    } else if (c != ' ' && c != '\n') {
      out += c;
    }
  }
  return out;
}

/// The streamed text, read back with its key order kept and printed by nlohmann, equals the tree
/// printed by nlohmann: keys, key order and values all agree (nlohmann's own digits on both sides:
/// its Grisu2 is not always the shortest, the streamed text is). Compact has no layout; pretty is
/// the same text with line breaks and indentation only, laid out as nlohmann's dump(2).
void expect_same_document(const Model& model, const Solution& solution) {
  const std::string expected = reference::result_document(model, solution).dump();
  const std::string compact = streamed(model, solution, false);
  EXPECT_EQ(ordered_json::parse(compact).dump(), expected);
  EXPECT_EQ(without_layout(compact), compact);
  const std::string pretty = streamed(model, solution, true);
  EXPECT_EQ(without_layout(pretty), compact);
  EXPECT_EQ(pretty.substr(0, 16), "{\n  \"analysis\": ");
  EXPECT_EQ(result_text(model, solution), compact);
}

class ReportProblem : public ::testing::TestWithParam<const char*> {};

TEST_P(ReportProblem, StreamedResultIsTheTreeWritersDocument) {
  const Model model = testing::example_model(GetParam());
  const Solution solution = solve(model);
  ASSERT_FALSE(solution.history.empty());
  expect_same_document(model, solution);
}

INSTANTIATE_TEST_SUITE_P(Examples, ReportProblem,
                         ::testing::Values("report-problem1.json", "report-problem2.json",
                                           "report-problem3-case1.json", "report-problem3-case3.json",
                                           "report-beam-model-a.json"));

/// Arrays longer than a piece (io/parallel_items.hpp: 256 items) are formatted on several threads:
/// the ring's 384 elements and 450 nodes, written so, are still the tree writer's document.
TEST(ResultWriter, ArraysFormattedInParallelAreTheTreeWritersDocument) {
  const Model model = testing::example_model("ring-shrink-fit-plane-strain.json");
  ASSERT_GT(model.elements.size(), ItemPieces{}.items);
  ASSERT_GT(model.nodes.size(), ItemPieces{}.items);
  expect_same_document(model, solve(model));
}

/// Doubles of every magnitude and sign, from random bit patterns (never nan or inf here).
double random_double(std::mt19937_64& rng) {
  for (;;) {
    const std::uint64_t bits = rng();
    double v = 0.0;
    std::memcpy(&v, &bits, sizeof v);
    if (std::isfinite(v)) return v;
  }
}

/// A value of the kinds a result holds: round numbers, decimals, tiny and huge, -0.0, subnormals.
double random_value(std::mt19937_64& rng) {
  switch (rng() % 6) {
    case 0: return static_cast<double>(static_cast<int>(rng() % 2001) - 1000);
    case 1: return std::uniform_real_distribution<double>(-1e4, 1e4)(rng);
    case 2: return random_double(rng);
    case 3: return std::ldexp(std::uniform_real_distribution<double>(-1.0, 1.0)(rng), static_cast<int>(rng() % 120) - 60);
    case 4: return -0.0;
    default: return std::numeric_limits<double>::denorm_min() * static_cast<double>(rng() % 1000);
  }
}

IterationRecord random_row(std::mt19937_64& rng, int iteration, std::size_t gaps) {
  IterationRecord r;
  r.iteration = iteration;
  r.tensile_modulus = random_value(rng);
  r.closed_gaps = static_cast<int>(rng() % 50);
  r.nonconverged_gaps = static_cast<int>(rng() % 50);
  r.average_closure = random_value(rng);
  r.max_closure = random_value(rng);
  r.yielded_elements = static_cast<int>(rng() % 7);
  r.nonconverged_plastic = static_cast<int>(rng() % 7);
  r.bimodulus_changes = static_cast<int>(rng() % 3);
  r.extrapolated = rng() % 2 == 0;
  for (int k = 0; k < 2; ++k) {
    r.watch_elements.push_back({k + 1, random_value(rng), random_value(rng), random_value(rng), random_value(rng),
                                random_value(rng)});
    r.watch_gaps.push_back({k + 7, random_value(rng), random_value(rng), random_value(rng)});
  }
  for (std::size_t g = 0; g < gaps; ++g) r.gap_closures.push_back(random_value(rng));
  r.seconds = random_value(rng);
  r.attempt = 1 + static_cast<int>(rng() % 3);
  if (iteration % 2 == 0) {  // an exact-contact row: three more members
    r.active_set_iterations = 1 + static_cast<int>(rng() % 5);
    r.contact_pairs = static_cast<int>(rng() % 100);
    r.complementarity = random_value(rng);
  }
  if (iteration % 3 == 0) {  // a row of a run with friction: three more members
    r.stick_points = static_cast<int>(rng() % 40);
    r.slip_points = 1 + static_cast<int>(rng() % 40);
    r.friction_residual = random_value(rng);
  }
  return r;
}

TEST(ResultWriter, RandomSolutionIsTheTreeWritersDocument) {
  Model model = testing::example_model("report-problem3-case1.json");
  // Text that needs escaping: quotes, backslashes, control characters, non-ASCII.
  model.title = "tab\there \"quoted\" back\\slash \x01\x1f new\nline \xc3\xa9t\xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80";
  // Some unit names given, one not: only the given ones are written.
  model.units.length = "in";
  model.units.stress = "lb/in\u00b2";
  model.units.temperature = "\u00b0F";
  std::mt19937_64 rng(20261123);
  Solution s;
  s.status = RunStatus::not_converged;
  s.iterations = 3;
  s.message = "stopped: \"3\" iterations\r\n";
  for (int i = 1; i <= 3; ++i) s.history.push_back(random_row(rng, i, model.gap_count()));
  for (const Node& n : model.nodes) s.nodes.push_back({n.id, random_value(rng), random_value(rng)});
  for (const Element& e : model.elements) {
    ElementResult r;
    r.id = e.id;
    for (int c = 0; c < 4; ++c) {
      r.stress[c] = random_value(rng);
      r.strain[c] = random_value(rng);
    }
    r.principal = {random_value(rng), random_value(rng), random_value(rng)};
    r.effective = random_value(rng);
    r.yielded = rng() % 2 == 0;
    r.plastic_converged = rng() % 2 == 0;
    s.elements.push_back(r);
  }
  for (const GapElement& g : model.gaps->elements) {
    GapResult r;
    r.id = g.id;
    r.eps_m = random_value(rng);
    r.closure = random_value(rng);
    r.modulus = random_value(rng);
    r.sigma_m = random_value(rng);
    r.state = static_cast<GapState>(rng() % 4);
    r.converged = rng() % 2 == 0;
    r.failure = r.converged ? GapFailure::none : GapFailure::overclosed;
    s.gaps.push_back(r);
  }
  for (const Constraint& c : model.constraints) {
    s.reactions.push_back({model.nodes[static_cast<std::size_t>(c.node)].id, random_value(rng), random_value(rng)});
  }
  expect_same_document(model, s);
  const nlohmann::json written = nlohmann::json::parse(result_text(model, s));
  EXPECT_EQ(written["units"], (nlohmann::json{{"length", "in"}, {"stress", "lb/in\u00b2"}, {"temperature", "\u00b0F"}}));
  for (std::size_t g = 0; g < s.gaps.size(); ++g) {
    EXPECT_EQ(written["gaps"][g]["contact_pressure"].get<double>(), s.gaps[g].sigma_m < 0.0 ? -s.gaps[g].sigma_m : 0.0);
  }
  // A nan or inf (which JSON cannot hold) is null in both.
  s.nodes[0].u_r = std::nan("");
  s.elements[0].effective = std::numeric_limits<double>::infinity();
  expect_same_document(model, s);
}

TEST(ResultWriter, ContactPairsAreWrittenForModelsWithContactOnly) {
  Model model = testing::example_model("report-problem3-case1.json");
  Solution s;
  s.status = RunStatus::converged;
  EXPECT_FALSE(nlohmann::json::parse(result_text(model, s)).contains("contact"));
  model.contact.emplace();
  ContactPairResult pair;
  pair.surfaces = {"shaft", "hub"};
  pair.points.push_back({1.5, 0.25, 0.0, 1234.5, 0.0, 0.0, ContactPointState::stick});
  pair.points.push_back({1.5, 0.5, 0.002, 0.0, 0.0, 0.0, ContactPointState::open});
  pair.force = Vec2(-0.25, 4321.5);
  s.contact = {pair};
  s.reactions = {{7, 1.5, -2.0}, {9, 0.25, 8.0}};
  const std::string text = result_text(model, s);
  const nlohmann::json written = nlohmann::json::parse(text);
  ASSERT_EQ(written["contact"].size(), 1u);
  EXPECT_EQ(written["contact"][0]["surfaces"], (nlohmann::json{"shaft", "hub"}));
  EXPECT_EQ(written["contact"][0]["force"], (nlohmann::json{{"fr", -0.25}, {"fz", 4321.5}}));
  EXPECT_EQ(written["reaction_sum"], (nlohmann::json{{"fr", 1.75}, {"fz", 6.0}}));
  EXPECT_EQ(written["contact"][0]["points"][0],
            (nlohmann::json{{"r", 1.5}, {"z", 0.25}, {"gap", 0.0}, {"pressure", 1234.5}, {"shear", 0.0},
                            {"slip", 0.0}, {"state", "stick"}}));
  EXPECT_EQ(written["contact"][0]["points"][1]["state"], "open");
  // Keys in alphabetical order, as everywhere in the document.
  EXPECT_LT(text.find("\"gap\""), text.find("\"pressure\""));
  EXPECT_LT(text.find("\"analysis\""), text.find("\"contact\""));
  EXPECT_LT(text.find("\"contact\""), text.find("\"elements\""));
  EXPECT_LT(text.find("\"force\""), text.find("\"points\""));
  EXPECT_LT(text.find("\"reaction_sum\""), text.find("\"reactions\""));
  // A frictionless pair has no friction member (the document is as before friction existed) ...
  EXPECT_FALSE(written["contact"][0].contains("friction"));
  // ... a pair with friction gives its mu (the friction plot draws mu x pressure), first in the pair.
  model.contact->pairs.push_back({{0, 1}, 0.3, std::nullopt});
  const std::string with_friction = result_text(model, s);
  EXPECT_EQ(nlohmann::json::parse(with_friction)["contact"][0]["friction"], 0.3);
  EXPECT_LT(with_friction.find("\"friction\""), with_friction.find("\"points\""));
}

/// A stepped model's result is the state at the end of its last step: the nodes' T and the
/// elements' temperature (the mean of their nodes') both come from the last step's loads, not the
/// top-level loads the first step starts from.
TEST(ResultWriter, SteppedModelWritesTheLastStepsTemperaturesForNodesAndElements) {
  Model model = testing::example_model("report-problem3-case1.json");
  Loads hot = model.loads;
  for (std::size_t n = 0; n < hot.node_temperature.size(); ++n) hot.node_temperature[n] = 400.0 + static_cast<double>(n);
  model.steps.push_back({"cold", 1, std::nullopt, {}});
  model.steps.push_back({"hot", 1, hot, {}});
  Solution s;
  s.status = RunStatus::converged;
  for (const Node& n : model.nodes) s.nodes.push_back({n.id, 0.0, 0.0});
  for (const Element& e : model.elements) {
    ElementResult r;
    r.id = e.id;
    s.elements.push_back(r);
  }
  const nlohmann::json written = nlohmann::json::parse(result_text(model, s));
  for (std::size_t n = 0; n < model.nodes.size(); ++n) {
    EXPECT_EQ(written["nodes"][n]["T"].get<double>(), hot.node_temperature[n]) << "node " << model.nodes[n].id;
  }
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const Element& el = model.elements[e];
    double mean = 0.0;
    for (int a = 0; a < el.node_count; ++a) mean += hot.node_temperature[static_cast<std::size_t>(el.nodes[a])];
    EXPECT_DOUBLE_EQ(written["elements"][e]["temperature"].get<double>(), mean / el.node_count) << "element " << el.id;
  }
}

/// A transient heat run's steps are its output times: each step it reached carries its time and
/// the node temperatures there (the temperature history); a step it did not reach, and every step
/// of a run without a transient, carries neither.
TEST(ResultWriter, TransientStepsCarryTheirTimeAndNodeTemperatures) {
  const Model model = testing::example_model("report-problem3-case1.json");
  Solution s;
  s.status = RunStatus::not_converged;
  for (const Node& n : model.nodes) s.nodes.push_back({n.id, 0.0, 0.0});
  for (const Element& e : model.elements) {
    ElementResult r;
    r.id = e.id;
    s.elements.push_back(r);
  }
  s.steps = {{"t1", 1, StepStatus::converged}, {"t2", 1, StepStatus::converged}, {"t3", 1, StepStatus::not_converged}};
  ThermalResult heat;
  heat.times = {0.5, 1.25};
  for (const double scale : {1.0, 2.0}) {
    std::vector<double> T;
    for (std::size_t n = 0; n < model.nodes.size(); ++n) T.push_back(scale * (100.0 + static_cast<double>(n)));
    heat.history.push_back(T);
  }
  heat.T = heat.history.back();
  heat.flux.assign(model.elements.size(), Vec2(0.0, 0.0));
  s.thermal = heat;
  const std::string text = result_text(model, s);
  const nlohmann::json written = nlohmann::json::parse(text);
  ASSERT_EQ(written["steps"].size(), 3U);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(written["steps"][k]["time"].get<double>(), heat.times[k]);
    EXPECT_EQ(written["steps"][k]["T"].get<std::vector<double>>(), heat.history[k]);
  }
  EXPECT_FALSE(written["steps"][2].contains("T"));
  EXPECT_FALSE(written["steps"][2].contains("time"));
  // Keys in alphabetical order, as everywhere in the document: T, increments, name, status, time.
  const std::size_t steps = text.find("\"steps\"");
  EXPECT_LT(text.find("\"T\"", steps), text.find("\"increments\"", steps));
  EXPECT_LT(text.find("\"status\"", steps), text.find("\"time\"", steps));
  // A steady run (no output times): the steps are as before.
  s.thermal->times.clear();
  s.thermal->history.clear();
  const nlohmann::json steady = nlohmann::json::parse(result_text(model, s));
  for (const auto& step : steady["steps"]) EXPECT_FALSE(step.contains("T") || step.contains("time"));
}

TEST(ResultWriter, FailedDocumentAndHistoryRowsMatchTheirTrees) {
  std::string text;
  JsonWriter out(string_sink(text));
  write_failed_result(out, "the model is singular at node 4");
  out.flush();
  EXPECT_EQ(ordered_json::parse(text).dump(), reference::failed_result_document("the model is singular at node 4").dump());
  EXPECT_EQ(failed_result_text("x"), reference::failed_result_document("x").dump());

  std::mt19937_64 rng(7);
  for (int i = 0; i < 50; ++i) {
    const IterationRecord row = random_row(rng, i + 1, static_cast<std::size_t>(i));
    EXPECT_EQ(ordered_json::parse(history_row_text(row)).dump(), history_row_json(row).dump());
  }
}

TEST(JsonWriter, DoublesReadBackExactlyInNlohmannsLayout) {
  // The layout: a '.' or an exponent always, fixed notation for decimal exponents -4 < n <= 15.
  for (const double v : {1.0, -1.0, 0.0, 0.1, 1e-4, 1e-5, 123.456, 1e15, 1e16, 1.5e16, 1e100, 1e-100, 5e-324,
                         std::numeric_limits<double>::max(), 999999999999999.9, 0.30000000000000004}) {
    EXPECT_EQ(format_double(v), json(v).dump()) << v;
  }
  EXPECT_EQ(format_double(-0.0), "-0.0");
  EXPECT_EQ(format_double(std::nan("")), "null");
  EXPECT_EQ(format_double(-std::numeric_limits<double>::infinity()), "null");
  // Every double reads back to itself; the text is nlohmann's wherever its Grisu2 digits are the
  // shortest (nearly always).
  std::mt19937_64 rng(42);
  int same_text = 0;
  constexpr int count = 100000;
  for (int i = 0; i < count; ++i) {
    const double v = random_double(rng);
    const std::string text = format_double(v);
    ASSERT_EQ(json::parse(text).get<double>(), v) << text;
    same_text += text == json(v).dump() ? 1 : 0;
  }
  EXPECT_GT(same_text, count * 99 / 100);
}

TEST(JsonWriter, StringsAreEscapedAndInvalidUtf8IsReplaced) {
  std::string text;
  JsonWriter out(string_sink(text));
  out.begin_array()
      .value("a\"b\\c\b\f\n\r\t\x01\x7f")
      .value(std::string_view("nul\0byte", 8))
      .value("bad \xff\xfe, cut \xe2\x82, overlong \xc0\xaf, surrogate \xed\xa0\x80, ok \xe2\x82\xac")
      .end_array();
  out.flush();
  EXPECT_EQ(text,
            "[\"a\\\"b\\\\c\\b\\f\\n\\r\\t\\u0001\x7f\",\"nul\\u0000byte\","
            "\"bad \xef\xbf\xbd\xef\xbf\xbd, cut \xef\xbf\xbd\xef\xbf\xbd, overlong \xef\xbf\xbd\xef\xbf\xbd, "
            "surrogate \xef\xbf\xbd\xef\xbf\xbd\xef\xbf\xbd, ok \xe2\x82\xac\"]");
  const json parsed = json::parse(text);  // valid UTF-8 JSON
  EXPECT_EQ(parsed[0], "a\"b\\c\b\f\n\r\t\x01\x7f");
}

TEST(JsonWriter, LargeDocumentsGoOutInPiecesThroughTheSink) {
  std::vector<std::size_t> pieces;
  std::string text;
  JsonWriter out([&](std::string_view piece) {
    pieces.push_back(piece.size());
    text.append(piece);
  });
  out.begin_array();
  for (int i = 0; i < 100000; ++i) out.value(i * 0.5);
  out.end_array();
  out.flush();
  EXPECT_GT(pieces.size(), 5U);
  for (const std::size_t size : pieces) EXPECT_LE(size, (1U << 16) + 64);
  EXPECT_EQ(out.bytes(), text.size());
  EXPECT_EQ(json::parse(text).size(), 100000U);
}

}  // namespace
}  // namespace saasgaps::io
