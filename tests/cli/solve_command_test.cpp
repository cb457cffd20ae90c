// The saasgaps command line as a user drives it: exit codes of docs/cli.md, the iteration table on
// stderr, and a run stopped and resumed through --state-out / --resume files.
#include "command_fixture.hpp"

#include <fstream>
#include <sstream>
#include <vector>

#include "support/transient_heating.hpp"

namespace {

using saasgaps::testing::Outcome;

class SolveCommand : public saasgaps::testing::CommandTest {
 protected:
  /// The result without wall times and attempt numbers: what must match between runs.
  static nlohmann::json numbers(nlohmann::json result) {
    for (auto& row : result["history"]) {
      row.erase("seconds");
      row.erase("attempt");
    }
    return result;
  }
};

TEST_F(SolveCommand, ConvergedRunPrintsTheTableAndExitsZero) {
  const Outcome r = saasgaps("solve " + example("report-problem2.json") + " -o " + path("result.json"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  for (const char* column : {"iter", "E tension", "> 100 %", "non-conv", "avg > 100 %", "max clos %", "yielded",
                             "N-L non-conv", "seconds"}) {
    EXPECT_NE(r.err.find(column), std::string::npos) << "missing column " << column << "\n" << r.err;
  }
  // The watched element and gap of the model's output: with --wide.
  const Outcome wide = saasgaps("solve " + example("report-problem2.json") + " --wide -o " + path("result.json"));
  EXPECT_EQ(wide.exit_code, 0) << wide.err;
  for (const char* column : {"gap 20 E_M", "gap 20 clos %", "el 9 s_r"}) {
    EXPECT_NE(wide.err.find(column), std::string::npos) << "missing column " << column << "\n" << wide.err;
  }
  EXPECT_NE(r.err.find("converged in 5 iterations"), std::string::npos) << r.err;
  const nlohmann::json result = json_of(path("result.json"));
  EXPECT_EQ(result["status"], "converged");
  EXPECT_EQ(result["history"].size(), 5U);
  EXPECT_EQ(result["gaps"].size(), 11U);
}

TEST_F(SolveCommand, ResultIsCompactUnlessPrettyAndTheSameEitherWay) {
  ASSERT_EQ(saasgaps("solve " + example("report-problem1.json") + " -q -o " + path("compact.json")).exit_code, 0);
  ASSERT_EQ(saasgaps("solve " + example("report-problem1.json") + " -q --pretty -o " + path("pretty.json")).exit_code, 0);
  ASSERT_EQ(saasgaps("solve " + example("report-problem1.json") + " -q --pretty").exit_code, 0);  // to stdout
  const std::string compact = read(path("compact.json"));
  const std::string pretty = read(path("pretty.json"));
  EXPECT_EQ(compact.find('\n'), compact.size() - 1) << "one line";
  EXPECT_EQ(compact.substr(0, 13), "{\"analysis\":\"");
  EXPECT_EQ(pretty.substr(0, 16), "{\n  \"analysis\": ");
  const std::string to_stdout = read(path("stdout.txt"));
  EXPECT_EQ(to_stdout.substr(0, 16), pretty.substr(0, 16));
  EXPECT_TRUE(numbers(nlohmann::json::parse(to_stdout)) == numbers(nlohmann::json::parse(pretty)));
  EXPECT_TRUE(numbers(nlohmann::json::parse(compact)) == numbers(nlohmann::json::parse(pretty)));
}

TEST_F(SolveCommand, StoppedThenResumedEqualsTheUninterruptedRun) {
  ASSERT_EQ(saasgaps("solve " + example("report-problem3-case3.json") + " -q -o " + path("full.json")).exit_code, 0);
  const Outcome stopped = saasgaps("solve " + example("report-problem3-case3.json") + " -q --stop-after 4 --state-out " +
                               path("state.json") + " -o " + path("partial.json"));
  EXPECT_EQ(stopped.exit_code, 3) << stopped.err;
  EXPECT_NE(stopped.err.find("stopped on request after iteration 4"), std::string::npos) << stopped.err;
  EXPECT_EQ(json_of(path("partial.json"))["status"], "not_converged");
  const Outcome resumed = saasgaps("solve " + example("report-problem3-case3.json") + " -q --resume " + path("state.json") +
                               " -o " + path("resumed.json"));
  EXPECT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_EQ(numbers(json_of(path("resumed.json"))), numbers(json_of(path("full.json"))));
}

TEST_F(SolveCommand, IterationLimitExitsThreeAndSaysWhatFails) {
  const Outcome r = saasgaps("solve " + example("report-problem3-case1.json") + " --max-iterations 3 -o " +
                         path("result.json"));
  EXPECT_EQ(r.exit_code, 3) << r.err;
  const nlohmann::json result = json_of(path("result.json"));
  EXPECT_EQ(result["status"], "not_converged");
  EXPECT_NE(result["message"].get<std::string>().find("overclosed"), std::string::npos) << result["message"];
}

TEST_F(SolveCommand, ResumeWithANewScheduleUsesIt) {
  ASSERT_EQ(saasgaps("solve " + example("report-problem3-case1.json") + " -q --stop-after 2 --state-out " +
                     path("state.json") + " -o " + path("partial.json")).exit_code, 3);
  const Outcome r = saasgaps("solve " + example("report-problem3-case1.json") + " -q --resume " + path("state.json") +
                         " --schedule 0.5,0.25 -o " + path("resumed.json"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json history = json_of(path("resumed.json"))["history"];
  EXPECT_EQ(history[2]["tensile_modulus"], 0.5);
  EXPECT_EQ(history[3]["tensile_modulus"], 0.25);
  EXPECT_EQ(history[2]["attempt"], 2);
}

TEST_F(SolveCommand, BadModelExitsTwoWithPointers) {
  std::ofstream(path("bad.json")) << R"({"schema_version": 1, "title": "x", "analysis": {"type": "plane_stres"},
    "nodes": [], "materials": [], "elements": [], "constraints": []})";
  const Outcome r = saasgaps("solve " + path("bad.json"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("/analysis/type"), std::string::npos) << r.err;
  EXPECT_EQ(saasgaps("validate " + path("bad.json")).exit_code, 2);
}

TEST_F(SolveCommand, SingularModelExitsTwoNamingTheNodes) {
  nlohmann::json model = json_of(example("report-beam-model-a.json"));
  model["constraints"] = nlohmann::json::array({{{"node", 2}, {"r", 0.0}}});
  std::ofstream(path("free.json")) << model.dump();
  const Outcome r = saasgaps("solve " + path("free.json") + " -o " + path("result.json"));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("not restrained"), std::string::npos) << r.err;
  EXPECT_EQ(json_of(path("result.json"))["status"], "failed");
}

TEST_F(SolveCommand, UnreadableFileExitsOne) {
  EXPECT_EQ(saasgaps("solve " + path("missing.json")).exit_code, 1);
  const Outcome garbage = saasgaps("solve " + example("report-problem1.json") + " --resume " + example("report-problem2.json"));
  EXPECT_EQ(garbage.exit_code, 1) << garbage.err;
  EXPECT_NE(garbage.err.find("not a SAASGAPS restart state"), std::string::npos) << garbage.err;
}

}  // namespace

TEST_F(SolveCommand, ExactModeSolvesAndItsResultPlotsAndExports) {
  const Outcome r = saasgaps("solve " + example("report-problem3-case1-exact.json") + " -o " + path("result.json"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("exact contact: 1 of 19 node pairs in contact"), std::string::npos) << r.err;
  for (const char* column : {"pairs", "complement.", "sets"}) EXPECT_NE(r.err.find(column), std::string::npos) << column;
  const nlohmann::json result = json_of(path("result.json"));
  EXPECT_EQ(result["history"][0]["contact_pairs"], 1);
  EXPECT_LT(result["history"][0]["complementarity"].get<double>(), 1e-12);
  for (const auto& gap : result["gaps"]) EXPECT_EQ(gap["state"], gap["id"] == 81 ? "closed" : "open") << gap["id"];
  for (const char* field : {"closure", "effective", "convergence"}) {
    EXPECT_EQ(saasgaps("plot " + path("result.json") + " --field " + field + " -o " + path(std::string(field) + ".png")).exit_code, 0)
        << field;
  }
  EXPECT_EQ(saasgaps("export-vtu " + path("result.json") + " -o " + path("result.vtu")).exit_code, 0);
}

TEST_F(SolveCommand, ClassicRunWithLoadedGapsShortOfContactSuggestsTheExactMethod) {
  const Outcome beam = saasgaps("solve " + example("report-problem3-case1.json") + " -q -o " + path("beam.json"));
  EXPECT_EQ(beam.exit_code, 0) << beam.err;
  EXPECT_NE(beam.err.find("\"method\": \"exact\""), std::string::npos) << beam.err;
  EXPECT_NE(json_of(path("beam.json"))["message"].get<std::string>().find("are not closed"), std::string::npos);
  // Problem 1 ends with every loaded gap at 99 % closure: nothing to warn about.
  const Outcome block = saasgaps("solve " + example("report-problem1.json") + " -q -o " + path("block.json"));
  EXPECT_EQ(block.exit_code, 0) << block.err;
  EXPECT_EQ(block.err.find("exact"), std::string::npos) << block.err;
}

TEST_F(SolveCommand, ExactModeGapWhoseMIsNotAcrossItIsABadModel) {
  nlohmann::json model = json_of(example("report-problem3-case1-exact.json"));
  model["gaps"]["elements"][2]["angle"] = 45.0;  // no two opposite edges across M
  std::ofstream(path("unpairable.json")) << model.dump();
  const Outcome r = saasgaps("validate " + path("unpairable.json"));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("/gaps/elements/2/angle: angle 45 does not run across gap element 83"), std::string::npos)
      << r.err;
}

namespace {

/// Report problem 3 case 2 (a plastic beam on a foundation, classic gaps) with a load path: loaded in
/// 3 increments, unloaded in 2, reloaded in 2. Its increments take several iterations each.
nlohmann::json stepped_beam(const nlohmann::json& model) {
  nlohmann::json m = model;
  m["steps"] = nlohmann::json::array({{{"name", "load"}, {"increments", 3}},
                                      {{"name", "unload"}, {"increments", 2}, {"loads", nlohmann::json::object()}},
                                      {{"name", "reload"}, {"increments", 2}, {"loads", model["loads"]}}});
  return m;
}

}  // namespace

TEST_F(SolveCommand, SteppedRunShowsStepsAndResumesMidStepToTheLastDigit) {
  std::ofstream(path("stepped.json")) << stepped_beam(json_of(example("report-problem3-case2.json"))).dump();
  const Outcome full = saasgaps("solve " + path("stepped.json") + " -o " + path("full.json"));
  ASSERT_EQ(full.exit_code, 0) << full.err;
  EXPECT_NE(full.err.find("step/inc"), std::string::npos) << full.err;
  std::istringstream table(full.err);
  for (std::string line; std::getline(table, line);) {
    if (line.rfind("converged", 0) != 0) {
      EXPECT_LE(line.size(), 120U) << line;
    }
  }
  const nlohmann::json result = json_of(path("full.json"));
  ASSERT_EQ(result["steps"].size(), 3U);
  for (const auto& step : result["steps"]) EXPECT_EQ(step["status"], "converged") << step;
  EXPECT_EQ(result["steps"][0], (nlohmann::json{{"name", "load"}, {"increments", 3}, {"status", "converged"}}));
  // Rows carry step and increment; iterations count over the whole run.
  const nlohmann::json& history = result["history"];
  ASSERT_GE(history.size(), 7U);
  for (std::size_t k = 0; k < history.size(); ++k) {
    EXPECT_EQ(history[k]["iteration"], k + 1);
    EXPECT_TRUE(history[k].contains("step") && history[k].contains("increment")) << history[k];
  }
  EXPECT_EQ(history.back()["step"], 3);
  EXPECT_EQ(history.back()["increment"], 2);

  // Stopped inside step 2 (after the first iteration that belongs to it, inside its first increment),
  // resumed from the file.
  int k = 0;
  while (history[static_cast<std::size_t>(k)]["step"] != 2) ++k;
  const int stop_after = k + 1;
  const Outcome stopped = saasgaps("solve " + path("stepped.json") + " -q --stop-after " + std::to_string(stop_after) +
                                   " --state-out " + path("state.json") + " -o " + path("stopped.json"));
  EXPECT_EQ(stopped.exit_code, 3) << stopped.err;
  const nlohmann::json state = json_of(path("state.json"));
  EXPECT_EQ(state["version"], 3);  // steps and a plastic material: the position and the plastic peaks
  EXPECT_TRUE(state.contains("plastic"));
  EXPECT_EQ(state["position"]["step"], 1);  // 0-based in the state
  EXPECT_EQ(state["position"]["increment"], 1);
  EXPECT_EQ(state["position"]["iterations"], 1);
  ASSERT_EQ(history[static_cast<std::size_t>(k + 1)]["step"], 2);  // the increment had more to do
  ASSERT_EQ(history[static_cast<std::size_t>(k + 1)]["increment"], 1);
  const nlohmann::json partial = json_of(path("stopped.json"));
  EXPECT_EQ(partial["steps"][0]["status"], "converged");
  EXPECT_EQ(partial["steps"][1]["status"], "not_converged");
  const Outcome resumed = saasgaps("solve " + path("stepped.json") + " -q --resume " + path("state.json") + " -o " +
                                   path("resumed.json"));
  EXPECT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_EQ(numbers(json_of(path("resumed.json"))), numbers(result));

  // A model without steps refuses the stepped state, and the reverse.
  const Outcome foreign = saasgaps("solve " + example("report-problem3-case2.json") + " -q --resume " +
                                   path("state.json"));
  EXPECT_NE(foreign.exit_code, 0);
}

namespace {

/// The quickstart block with its temperatures computed: its bottom edge held at 500, a film to 70 on
/// its top, a source in the steel.
nlohmann::json thermal_quickstart(const nlohmann::json& quickstart) {
  nlohmann::json model = quickstart;
  model["loads"].erase("temperatures");
  model["materials"][0]["table"][0]["k"] = 0.6;
  model["thermal"] = nlohmann::json::parse(R"({"type": "steady",
    "boundary": [{"edges": [[1, 2], [2, 3]], "temperature": 500}],
    "sources": [{"material": 1, "power_density": 2.0}]})");
  return model;
}

}  // namespace

TEST_F(SolveCommand, ThermalRunWritesComputedTemperaturesAndHeatFluxThatPlotAndExport) {
  std::ofstream(path("thermal.json")) << thermal_quickstart(json_of(example("quickstart-plane-strain-block.json"))).dump();
  const Outcome r = saasgaps("solve " + path("thermal.json") + " -q -o " + path("result.json"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json result = json_of(path("result.json"));
  // Held at 500 along the bottom, heated inside, insulated elsewhere: every node at 500 or hotter,
  // and the heat leaves through the bottom (q_z < 0) in every element.
  for (const auto& node : result["nodes"]) {
    EXPECT_GE(node["T"].get<double>(), 500.0 - 1e-9) << node["id"];
    if (node["z"].get<double>() == 0.0) {
      EXPECT_EQ(node["T"], 500.0);
    }
  }
  for (const auto& element : result["elements"]) EXPECT_LT(element["q_z"].get<double>(), 0.0) << element["id"];
  EXPECT_EQ(saasgaps("plot " + path("result.json") + " --field temperature -o " + path("T.png")).exit_code, 0);
  EXPECT_EQ(saasgaps("plot " + path("result.json") + " --field heat_flux -o " + path("q.png")).exit_code, 0);
  EXPECT_GT(std::filesystem::file_size(path("q.png")), 0U);
  ASSERT_EQ(saasgaps("export-vtu " + path("result.json") + " -o " + path("result.vtu")).exit_code, 0);
  std::ifstream vtu(path("result.vtu"));
  const std::string text((std::istreambuf_iterator<char>(vtu)), std::istreambuf_iterator<char>());
  // A plane model's VTU names the flux in its axes (docs/vtu.md): q_x, q_y.
  EXPECT_NE(text.find("Name=\"q_x\""), std::string::npos);
}

namespace {

/// A transient heating of the shrink-fit rings (tests/support/transient_heating.hpp): four output
/// times, each a load step of the stress analysis.
TEST_F(SolveCommand, TransientHeatRunShowsItsThermalRowsAndResumesMidWayToTheLastDigit) {
  std::ofstream(path("heated.json"))
      << saasgaps::testing::transient_heating("ring-shrink-fit-plane-strain.json", {.hot = 400.0}).dump();
  const Outcome full = saasgaps("solve " + path("heated.json") + " -o " + path("full.json"));
  ASSERT_EQ(full.exit_code, 0) << full.err;
  // A line per output time before the iteration table; steps of 0.05 to t = 0.25, 0.5, ...
  // (docs/model.md quotes the second line.)
  for (const char* line : {"thermal t = 0.25: 5 steps, max step |dT| ",
                           "thermal t = 0.5: 10 steps, max step |dT| 25.2263, T 0 .. 400\n", "thermal t = 1: 20 steps"}) {
    EXPECT_NE(full.err.find(line), std::string::npos) << line << "\n" << full.err;
  }
  EXPECT_LT(full.err.find("thermal t = 1: 20 steps"), full.err.find("iter"));
  const int iterations = json_of(path("full.json"))["iterations"].get<int>();
  ASSERT_GT(iterations, 4);
  // The temperature history: each output time's step carries the time and the node temperatures,
  // the last of them the nodes' T.
  const nlohmann::json result = json_of(path("full.json"));
  const std::vector<double> times = {0.25, 0.5, 0.75, 1.0};
  ASSERT_EQ(result["steps"].size(), times.size());
  for (std::size_t k = 0; k < times.size(); ++k) {
    EXPECT_DOUBLE_EQ(result["steps"][k]["time"].get<double>(), times[k]);
    EXPECT_EQ(result["steps"][k]["T"].size(), result["nodes"].size());
  }
  for (std::size_t n = 0; n < result["nodes"].size(); ++n) {
    EXPECT_EQ(result["steps"].back()["T"][n], result["nodes"][n]["T"]) << n;
  }
  EXPECT_NE(result["steps"][0]["T"], result["steps"].back()["T"]);  // it heats up
  // Stopped two iterations before the end, past the first output time (position.step is 0-based), resumed.
  const Outcome stopped = saasgaps("solve " + path("heated.json") + " -q --stop-after " + std::to_string(iterations - 2) +
                                   " --state-out " + path("state.json") + " -o " + path("partial.json"));
  EXPECT_EQ(stopped.exit_code, 3) << stopped.err;
  EXPECT_GE(json_of(path("state.json"))["position"]["step"].get<int>(), 1);
  const Outcome resumed = saasgaps("solve " + path("heated.json") + " -q --resume " + path("state.json") + " -o " +
                                   path("resumed.json"));
  EXPECT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_EQ(numbers(json_of(path("resumed.json"))), numbers(json_of(path("full.json"))));
}

}  // namespace

namespace {

/// The same heating with conducting gaps: each interval's conductances come from the stress step
/// before it (solver/thermal/transient_coupling.hpp), and a resume mid-way recomputes them.
TEST_F(SolveCommand, TransientHeatRunWithConductingGapsResumesMidWayToTheLastDigit) {
  nlohmann::json document = saasgaps::testing::transient_heating("ring-shrink-fit-plane-strain.json", {.hot = 400.0});
  document["gaps"]["conductance"] = {{"closed", 20.0}, {"gas_conductivity", 0.0005}};
  std::ofstream(path("coupled.json")) << document.dump();
  const Outcome full = saasgaps("solve " + path("coupled.json") + " -q -o " + path("full.json"));
  ASSERT_EQ(full.exit_code, 0) << full.err;
  const int iterations = json_of(path("full.json"))["iterations"].get<int>();
  ASSERT_GT(iterations, 4);
  const Outcome stopped = saasgaps("solve " + path("coupled.json") + " -q --stop-after " +
                                   std::to_string(iterations - 2) + " --state-out " + path("state.json") + " -o " +
                                   path("partial.json"));
  EXPECT_EQ(stopped.exit_code, 3) << stopped.err;
  EXPECT_GE(json_of(path("state.json"))["position"]["step"].get<int>(), 1);
  const Outcome resumed = saasgaps("solve " + path("coupled.json") + " -q --resume " + path("state.json") + " -o " +
                                   path("resumed.json"));
  EXPECT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_EQ(numbers(json_of(path("resumed.json"))), numbers(json_of(path("full.json"))));
}

// ---- an assembly given to solve: imported and solved in one command; with adapt, the loop

TEST_F(SolveCommand, AnAssemblyIsImportedAndSolvedAsItsModelIs) {
  const std::string assembly = example("assemblies/ring-press-fit.assembly.json");
  ASSERT_EQ(saasgaps("import " + assembly + " -o " + path("model.json")).exit_code, 0);
  ASSERT_EQ(saasgaps("solve -q " + path("model.json") + " -o " + path("two-steps.json")).exit_code, 0);
  const Outcome r = saasgaps("solve -q " + assembly + " -o " + path("one-step.json"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("imported " + assembly), std::string::npos) << r.err;
  const nlohmann::json one = numbers(json_of(path("one-step.json")));
  EXPECT_FALSE(one.contains("adaptation"));
  EXPECT_EQ(one, numbers(json_of(path("two-steps.json"))));
  // Restart states belong to a model's text.
  const Outcome state = saasgaps("solve -q " + assembly + " --state-out " + path("s.json") + " -o " + path("x.json"));
  EXPECT_EQ(state.exit_code, 64);
  EXPECT_NE(state.err.find("is an assembly; restart states belong to a model"), std::string::npos) << state.err;
}

TEST_F(SolveCommand, AnAdaptiveAssemblyWritesItsCyclesAndSaysWhenALimitStoppedIt) {
  nlohmann::json a = json_of(example("assemblies/le1-adapt.assembly.json"));
  a["mesh"] = example("assemblies/le1.geo");
  a["adapt"] = {{"target_error", 0.03}, {"max_cycles", 4}};
  std::ofstream(path("le1.json")) << a.dump();
  const Outcome r = saasgaps("solve -q " + path("le1.json") + " -o " + path("le1-result.json"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("adapt cycle 2: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(" s, estimate "), std::string::npos) << r.err;  // the time split, per cycle
  const nlohmann::json result = json_of(path("le1-result.json"));
  ASSERT_TRUE(result.contains("adaptation"));
  const nlohmann::json& rows = result["adaptation"];
  ASSERT_GE(rows.size(), 2U);
  EXPECT_EQ(rows.back()["nodes"], result["nodes"].size());
  EXPECT_EQ(rows.back()["relative_error"], result["error_estimate"]["relative"]);
  EXPECT_LE(rows.back()["relative_error"].get<double>(), 0.03);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    EXPECT_EQ(rows[k]["cycle"], k + 1);
    for (const char* part : {"mesh", "import", "solve", "estimate", "sizes"}) {
      EXPECT_GE(rows[k]["seconds"][part].get<double>(), 0.0) << part;
    }
    EXPECT_GT(rows[k]["seconds"]["estimate"].get<double>(), 0.0);
  }
  EXPECT_NE(result["message"].get<std::string>().find("adaptation reached relative error"), std::string::npos);

  a["adapt"] = {{"target_error", 0.001}, {"max_cycles", 2}};
  std::ofstream(path("le1.json")) << a.dump();
  const Outcome limit = saasgaps("solve -q " + path("le1.json") + " -o " + path("le1-result.json"));
  EXPECT_EQ(limit.exit_code, 3) << limit.err;
  const nlohmann::json stopped = json_of(path("le1-result.json"));
  EXPECT_EQ(stopped["status"], "converged");
  EXPECT_EQ(stopped["adaptation"].size(), 2U);
  EXPECT_NE(stopped["message"].get<std::string>().find("adaptation stopped at the limit max_cycles = 2 with relative error"),
            std::string::npos)
      << stopped["message"];

  a["mesh"] = example("assemblies/two_blocks.msh");
  std::ofstream(path("le1.json")) << a.dump();
  const Outcome msh = saasgaps("solve -q " + path("le1.json") + " -o " + path("le1-result.json"));
  EXPECT_EQ(msh.exit_code, 2) << msh.err;
  EXPECT_NE(msh.err.find("/adapt: adapt re-meshes the geometry"), std::string::npos) << msh.err;
}

}  // namespace

namespace {

/// The README's worked example from the command line: import the two-step press fit, solve it, and
/// plot the pushed face's force against the load path as a table (plot --field force --set).
TEST_F(SolveCommand, PressFitForcePlotReadsThePushOutOffTheHistory) {
  const std::string model = path("press-fit.json"), result = path("press-fit-result.json"), table = path("force.csv");
  ASSERT_EQ(saasgaps("import " + example("assemblies/press-fit-push-out.assembly.json") + " -o " + model).exit_code, 0);
  ASSERT_EQ(saasgaps("solve " + model + " -q -o " + result).exit_code, 0);
  const Outcome r = saasgaps("plot " + result + " --field force --set pushed -o " + table);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // increment,step,step_increment,fr,fz,px,py_fr,py_fz: one row per increment's end (1 + 10).
  std::ifstream in(table);
  std::string line;
  std::vector<std::string> rows;
  while (std::getline(in, line)) {
    if (!line.empty() && line[0] != '#' && line.rfind("increment,", 0) != 0) rows.push_back(line);
  }
  ASSERT_EQ(rows.size(), 11u);
  std::vector<std::string> cells;
  std::stringstream last(rows.back());
  for (std::string c; std::getline(last, c, ',');) cells.push_back(c);
  ASSERT_GE(cells.size(), 5u);
  EXPECT_EQ(cells[1], "2");
  EXPECT_EQ(cells[2], "10");
  EXPECT_NEAR(std::stod(cells[4]), 1469.0, 0.01 * 1469.0);  // mu p pi d L, p by Lame (PressFitPushOut)
}

}  // namespace
