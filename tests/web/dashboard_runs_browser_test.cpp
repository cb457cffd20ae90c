// How the dashboard shows runs that are not the plain classic case, in headless Chromium against a
// real `saasgaps serve`: a convergence that carries a warning, an exact-mode run, a job followed live
// (placeholders, then its convergence drawn and redrawn while it runs), an assembly upload and a run
// with contact surfaces (a table per pair and the contact-pressure plot; with friction, its rows and
// columns on hand-made data), a transient heat conduction run (its thermal rows in a table), and a
// quad8 result (its contour plot drawn with curved edges, its error estimate shown).
// Screenshots land in build/tests/artifacts/.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <regex>
#include <sstream>
#include <filesystem>
#include <fstream>
#include <set>
#include <thread>

#include "service/job_client.hpp"
#include "service/long_job_model.hpp"
#include "service/server_process.hpp"
#include "support/transient_heating.hpp"
#include "web/browser_session.hpp"
#include "web/plain_block.hpp"

namespace saasgaps::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string base_url(const ServerProcess& server) { return "http://127.0.0.1:" + std::to_string(server.port()); }

/// Each test: a fresh directory named for it, a real server (one worker) on a database there, and
/// the server's client; the directory goes when the test ends.
class DashboardRuns : public ::testing::Test {
 protected:
  DashboardRuns() : server(dir / "jobs.db"), client(server.client()) {}

  const TempDirectory temp{"browser"};
  const fs::path dir = temp.path();
  ServerProcess server;
  httplib::Client client;
};

/// Opens the job's page and waits until it is usable.
void open_job(Browser& browser, const ServerProcess& server, std::int64_t job) {
  browser.open(base_url(server) + "/#/jobs/" + std::to_string(job));
  ASSERT_TRUE(wait_until(browser, "return document.body.dataset.ready === 'job';", std::chrono::seconds(30)));
}

TEST_F(DashboardRuns, AConvergedRunWithAWarningHasItsOwnBadgeAndTheListShowsTheMessage) {
  // The classic mode's stopping rule accepts gaps that are not closed yet carry load: it converges
  // with a warning (README). The quick-start block converges clean.
  const std::int64_t warned = submit_job(client, example_text("report-problem3-case1.json"));
  const json warned_job = wait_for_state(client, warned, {"converged", "not_converged", "failed"});
  ASSERT_EQ(warned_job["state"], "converged") << warned_job.dump();
  ASSERT_TRUE(warned_job.contains("warnings")) << warned_job.dump();
  ASSERT_EQ(warned_job["warnings"].size(), 1U) << warned_job["message"];
  const std::string warning = warned_job["warnings"][0].get<std::string>();
  EXPECT_EQ(warning.rfind("5 gaps are not closed", 0), 0U) << warning;
  EXPECT_NE(warned_job["message"].get<std::string>().find("; warning: " + warning), std::string::npos);
  const std::int64_t clean = submit_job(client, example_text("quickstart-plane-strain-block.json"));
  const json clean_job = wait_for_state(client, clean, {"converged", "not_converged", "failed"});
  ASSERT_EQ(clean_job["state"], "converged");
  EXPECT_EQ(clean_job["warnings"], json::array());
  // The list carries them too.
  EXPECT_EQ(get_json(client, "/v1/jobs")["jobs"][1]["warnings"], warned_job["warnings"]);

  Browser browser(dir / "chromium-profile");
  browser.open(base_url(server) + "/#/");
  ASSERT_TRUE(wait_until(browser, "return document.querySelectorAll('#jobs tbody tr').length === 2;", std::chrono::seconds(30)));
  // Per row: the badge's text, class and colour, the note under it and its class.
  const json rows = browser.run(
      "return [...document.querySelectorAll('#jobs tbody tr')].map(r => {"
      " const b = r.querySelector('.state'), n = r.querySelector('.reason');"
      " return {id: r.cells[0].textContent, badge: b.textContent, badge_class: b.className,"
      "         colour: getComputedStyle(b).backgroundColor, note: n ? n.textContent : '', note_class: n ? n.className : ''}; });");
  ASSERT_EQ(rows.size(), 2U);
  const json& w = rows[0]["id"] == std::to_string(warned) ? rows[0] : rows[1];
  const json& c = rows[0]["id"] == std::to_string(clean) ? rows[0] : rows[1];
  EXPECT_EQ(w["badge"], "converged with warning");
  EXPECT_NE(w["badge_class"].get<std::string>().find("warned"), std::string::npos) << w;
  EXPECT_EQ(c["badge"], "converged");
  EXPECT_EQ(c["badge_class"], "state converged");
  EXPECT_NE(w["colour"], c["colour"]) << "a warning must not wear the green of a clean convergence";
  EXPECT_EQ(w["note"], "warning: " + warning);
  EXPECT_NE(w["note_class"].get<std::string>().find("warning"), std::string::npos);
  EXPECT_EQ(c["note"], clean_job["message"]);
  save_artifact("dashboard-warning-list.png", browser.screenshot());

  open_job(browser, server, warned);
  EXPECT_EQ(browser.run("return document.querySelector('#job-state').textContent;"), "converged with warning");
  const json message = browser.run("const m = document.querySelector('#job-message'); return [m.textContent, m.className];");
  EXPECT_EQ(message[0], warned_job["message"]);
  EXPECT_EQ(message[1], "message warning");
  // The gap counts in the words of docs/results.md ("Gap words"): a classic row counts the report's
  // gaps past 100 %, not the closed ones, and the table heads it so, like the command line's.
  const json headers = browser.run("return [...document.querySelectorAll('#iterations thead th')].map(t => t.textContent);");
  for (const std::string name : {"> 100 %", "avg > 100 %", "max clos %"}) {
    EXPECT_NE(std::find(headers.begin(), headers.end(), json(name)), headers.end()) << name << " in " << headers;
  }
  EXPECT_EQ(std::find(headers.begin(), headers.end(), json("closed")), headers.end()) << headers;
  save_artifact("dashboard-warning-job.png", browser.screenshot());

  // A model without gap elements shows no gap columns and no gap convergence plot (issue 33).
  open_job(browser, server, clean);
  ASSERT_TRUE(wait_until(browser, "return document.querySelectorAll('#iterations tbody tr').length > 0;", std::chrono::seconds(30)));
  const json plain = browser.run("return [...document.querySelectorAll('#iterations thead th')].map(t => t.textContent);");
  for (const std::string name : {"E tension", "> 100 %", "non-conv", "avg > 100 %", "max clos %", "extrap."}) {
    EXPECT_EQ(std::find(plain.begin(), plain.end(), json(name)), plain.end()) << name << " in " << plain;
  }
  EXPECT_NE(std::find(plain.begin(), plain.end(), json("iter")), plain.end()) << plain;
  EXPECT_EQ(browser.run("return document.querySelector('#convergence-plot').parentElement.hidden;"), true);
}

TEST_F(DashboardRuns, ExactModeRunsShowTheirOwnColumnsAndConvergence) {
  const std::int64_t job = submit_job(client, example_text("report-problem3-case1-exact.json"));
  ASSERT_EQ(wait_for_state(client, job, {"converged", "not_converged", "failed"})["state"], "converged");
  const json history = get_json(client, "/v1/jobs/" + std::to_string(job) + "/iterations")["iterations"];
  ASSERT_FALSE(history.empty());
  const json& row = history.back();
  ASSERT_TRUE(row.contains("active_set_iterations")) << row.dump();

  Browser browser(dir / "chromium-profile");
  open_job(browser, server, job);
  const json headers = browser.run("return [...document.querySelectorAll('#iterations thead th')].map(t => t.textContent);");
  const auto has = [&headers](const std::string& name) { return std::find(headers.begin(), headers.end(), json(name)) != headers.end(); };
  for (const std::string name : {"iter", "closed", "contact pairs", "complementarity", "active sets"}) {
    EXPECT_TRUE(has(name)) << name << " in " << headers;
  }
  // The classic columns mean nothing here; the rows carry no load steps.
  for (const std::string name : {"E tension", "non-conv", "extrap.", "step", "increment"}) {
    EXPECT_FALSE(has(name)) << name << " in " << headers;
  }
  // The last row's cells under those headings, as the API gives them.
  const json cells = browser.run(
      "const heads = [...document.querySelectorAll('#iterations thead th')].map(t => t.textContent);"
      "const r = document.querySelector('#iterations tbody tr:last-child');"
      "return ['contact pairs', 'complementarity', 'active sets'].map(h => r.children[heads.indexOf(h)].textContent);");
  EXPECT_EQ(cells[0], std::to_string(row["contact_pairs"].get<int>()));
  EXPECT_NEAR(std::strtod(cells[1].get<std::string>().c_str(), nullptr), row["complementarity"].get<double>(),
              0.01 * row["complementarity"].get<double>());
  EXPECT_EQ(cells[2], std::to_string(row["active_set_iterations"].get<int>()));

  // The convergence figure: bars of the active sets and of the pairs per iteration, labelled with
  // their values, and the complementarity; not the classic plot's closures.
  const json figure = browser.run(
      "const box = document.querySelector('#exact-convergence');"
      "return [!box.checkVisibility(), !document.querySelector('#convergence-plot').checkVisibility(),"
      " [...box.querySelectorAll('rect.bar.active-sets')].length, [...box.querySelectorAll('rect.bar.pairs')].length,"
      " [...box.querySelectorAll('text')].map(t => t.textContent), box.querySelectorAll('circle.residual').length,"
      " document.querySelector('#convergence-caption').textContent];");
  EXPECT_FALSE(figure[0].get<bool>());
  EXPECT_TRUE(figure[1].get<bool>()) << "the classic convergence image is not shown for an exact run";
  EXPECT_EQ(figure[2].get<std::size_t>(), history.size());
  EXPECT_EQ(figure[3].get<std::size_t>(), history.size());
  const json& labels = figure[4];
  EXPECT_NE(std::find(labels.begin(), labels.end(), json(std::to_string(row["active_set_iterations"].get<int>()))), labels.end())
      << labels;
  EXPECT_NE(std::find(labels.begin(), labels.end(), json("complementarity")), labels.end()) << labels;
  EXPECT_EQ(figure[5].get<std::size_t>(), history.size());
  EXPECT_EQ(figure[6], "exact contact solve per iteration");
  EXPECT_FALSE(browser.run("return [...document.querySelectorAll('img')].some(i => i.checkVisibility() && i.naturalWidth === 0);")
                   .get<bool>())
      << "a broken image is shown";
  save_artifact("dashboard-exact-job.png", browser.screenshot());

  // Rows of a stepped load (other engineers' work: not produced yet) get their columns after iter,
  // and the convergence figure labels each group step.increment: the page's own functions.
  const json stepped = browser.run(
      "const row = Object.assign({}, " + row.dump() + ", {step: 2, increment: 3});"
      "const svg = exactConvergenceSvg([row]);"
      "return [columnsFor(row).map(c => c[0]), [...svg.querySelectorAll('text')].map(t => t.textContent)];");
  EXPECT_EQ(stepped[0][1], "step");
  EXPECT_EQ(stepped[0][2], "increment");
  EXPECT_NE(std::find(stepped[1].begin(), stepped[1].end(), json("2.3")), stepped[1].end()) << stepped[1];
}

TEST_F(DashboardRuns, ARunningJobShowsPlaceholdersThenItsConvergenceLive) {
  // One worker: the second job waits for the first.
  const std::int64_t blocker = submit_job(client, tilted_block_document(200).dump());
  const std::int64_t job = submit_job(client, tilted_block_document(200).dump());
  const std::string path = "/v1/jobs/" + std::to_string(job);

  Browser browser(dir / "chromium-profile");
  open_job(browser, server, job);
  // Queued: every figure says what it waits for; no image, broken or not, is shown. The friction
  // figure is for results with friction only: hidden here.
  ASSERT_EQ(get_json(client, path)["state"], "queued");
  EXPECT_FALSE(browser.run("return document.querySelector('#friction-plot').parentElement.checkVisibility();").get<bool>());
  const json queued = browser.run(
      "return [...document.querySelectorAll('.plots figure:not(:has(#friction-plot))')].map(f => [!f.checkVisibility(),"
      " !f.querySelector('.placeholder').checkVisibility(), f.querySelector('.placeholder').textContent,"
      " !f.querySelector('img').checkVisibility()]);");
  ASSERT_EQ(queued.size(), 4U);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_FALSE(queued[i][0].get<bool>()) << i;
    EXPECT_FALSE(queued[i][1].get<bool>()) << i;
    EXPECT_TRUE(queued[i][3].get<bool>()) << i;
  }
  EXPECT_EQ(queued[0][2], "drawn when the job has a result");
  EXPECT_EQ(queued[3][2], "drawn after the first iteration");
  save_artifact("dashboard-live-queued.png", browser.screenshot());
  // Before its first iteration the server has no convergence to draw; it says so.
  EXPECT_EQ(client.Get(path + "/plots/convergence.png")->status, 409);

  ASSERT_EQ(client.Post("/v1/jobs/" + std::to_string(blocker) + "/cancel", "", "application/json")->status, 202);
  // Followed to its end: what the convergence figure and the contour figure show at each look.
  std::set<std::string> live_pictures;  // convergence images shown while the job ran
  bool broken = false, contour_waits_while_live = true, live_answer = false;
  std::string state;
  int running_looks = 0;
  const auto started = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point first_running{}, last_running{};
  const auto deadline = started + std::chrono::seconds(180);
  while (std::chrono::steady_clock::now() < deadline) {
    const json look = browser.run(
        "const c = document.querySelector('#convergence-plot'), k = document.querySelector('#contour-plot');"
        "const shown = i => i.checkVisibility() && i.complete && i.naturalWidth > 0;"
        "return {state: document.querySelector('#job-state').textContent,"
        " broken: [...document.querySelectorAll('.plots img')].some(i => i.checkVisibility() && i.naturalWidth === 0),"
        " convergence: shown(c) ? c.src : '',"
        " contour_waits: k.parentElement.querySelector('.placeholder').checkVisibility() && !k.checkVisibility()};");
    state = look["state"].get<std::string>();
    broken = broken || look["broken"].get<bool>();
    if (state == "running") {
      const auto now = std::chrono::steady_clock::now();
      if (running_looks++ == 0) first_running = now;
      last_running = now;
      const std::string picture = look["convergence"].get<std::string>();
      if (!picture.empty() && live_pictures.insert(picture).second) {
        contour_waits_while_live = contour_waits_while_live && look["contour_waits"].get<bool>();
        if (live_pictures.size() == 1) save_artifact("dashboard-live-running.png", browser.screenshot());
        if (!live_answer) {
          const httplib::Result drawn = client.Get(path + "/plots/convergence.png");
          live_answer = drawn && drawn->status == 200 && drawn->body.substr(1, 3) == "PNG";
        }
      }
    }
    if (state.rfind("converged", 0) == 0 || state == "failed" || state == "not_converged") break;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  EXPECT_EQ(state.rfind("converged", 0), 0U) << state;
  EXPECT_FALSE(broken) << "a figure showed a broken image";
  EXPECT_TRUE(live_answer) << "the server drew no convergence for the running job";
  EXPECT_GE(live_pictures.size(), 2U) << "the convergence was not redrawn as iterations arrived";
  EXPECT_TRUE(contour_waits_while_live) << "the contour figure did not wait for the result with its placeholder";
  // Throttled: at most one drawing per 2 s of running (and the first).
  const double ran = std::chrono::duration<double>(last_running - first_running).count();
  EXPECT_LE(static_cast<double>(live_pictures.size()), ran / 2.0 + 2.0) << ran << " s";

  // Finished: the result's plots replace their placeholders.
  EXPECT_TRUE(wait_until(browser,
                         "return ['#contour-plot', '#convergence-plot'].map(s => document.querySelector(s)).every(i =>"
                         " i.checkVisibility() && i.complete && i.naturalWidth > 100 &&"
                         " !i.parentElement.querySelector('.placeholder').checkVisibility());",
                         std::chrono::seconds(60)));
  save_artifact("dashboard-live-finished.png", browser.screenshot());
}

TEST_F(DashboardRuns, AnAssemblyUploadImportsAndSubmitsOrListsItsErrorsAtTheirPointers) {
  const fs::path examples = fs::path(SAASGAPS_EXAMPLES_DIR) / "assemblies";
  // The ring fit with a region naming a group the mesh does not have.
  json bad = json::parse(example_text("assemblies/ring-fit.assembly.json"));
  bad["regions"][0]["group"] = "inner_rin";
  const fs::path bad_file = dir / "ring-fit.assembly.json";
  std::ofstream(bad_file) << bad.dump(1);

  Browser browser(dir / "chromium-profile");
  browser.open(base_url(server) + "/#/");
  ASSERT_TRUE(wait_until(browser, "return document.body.dataset.ready === 'list';", std::chrono::seconds(30)));
  browser.choose_files("#assembly-file", {bad_file});
  browser.choose_files("#assembly-parts", {examples / "ring-fit.geo"});
  browser.run("document.querySelector('#import-form button').click(); return true;");
  ASSERT_TRUE(wait_until(browser, "return !document.querySelector('#import-errors').hidden;", std::chrono::seconds(60)));
  const json errors = browser.run(
      "return [...document.querySelectorAll('#import-errors li')].map(l => [l.querySelector('code').textContent, l.textContent]);");
  ASSERT_EQ(errors.size(), 1U) << errors;
  EXPECT_EQ(errors[0][0], "/regions/0/group");
  EXPECT_NE(errors[0][1].get<std::string>().find("inner_rin"), std::string::npos) << errors;
  EXPECT_EQ(get_json(client, "/v1/jobs")["jobs"].size(), 0U) << "a bad assembly must not become a job";
  save_artifact("dashboard-import-errors.png", browser.screenshot());

  // The example as it is: imported, submitted, and its job page opens.
  browser.run("for (const s of ['#assembly-file', '#assembly-parts']) document.querySelector(s).value = ''; return true;");
  browser.choose_files("#assembly-file", {examples / "ring-fit.assembly.json"});
  browser.choose_files("#assembly-parts", {examples / "ring-fit.geo"});
  browser.run("document.querySelector('#import-form button').click(); return true;");
  ASSERT_TRUE(wait_until(browser, "return /^#\\/jobs\\/\\d+$/.test(location.hash) && document.body.dataset.ready === 'job';",
                         std::chrono::seconds(60)));
  const std::string hash = browser.run("return location.hash;").get<std::string>();
  const std::int64_t job = std::stoll(hash.substr(hash.rfind('/') + 1));
  const json finished = wait_for_state(client, job, {"converged", "not_converged", "failed"});
  EXPECT_EQ(finished["state"], "converged") << finished.dump();
  EXPECT_EQ(finished["title"], bad["title"]);
  EXPECT_TRUE(wait_until(browser, "return document.querySelector('#job-state').textContent.startsWith('converged') &&"
                                  " document.querySelectorAll('#iterations tbody tr').length > 0;",
                         std::chrono::seconds(30)));
  save_artifact("dashboard-import-job.png", browser.screenshot());
}

TEST_F(DashboardRuns, AContactRunShowsATablePerPairAndTheContactPressurePlot) {
  // The press fit on non-matching meshes: its exact face pair imports as contact surfaces.
  const httplib::MultipartFormDataItems parts{
      {"assembly", example_text("assemblies/ring-press-fit.assembly.json"), "ring-press-fit.assembly.json", "application/json"},
      {"mesh", example_text("assemblies/ring-press-fit.geo"), "ring-press-fit.geo", "text/plain"}};
  const httplib::Result submitted = client.Post("/v1/imports?submit=true", parts);
  ASSERT_TRUE(submitted);
  ASSERT_EQ(submitted->status, 202) << submitted->body;
  const auto job = json::parse(submitted->body)["id"].get<std::int64_t>();
  ASSERT_EQ(wait_for_state(client, job, {"converged", "not_converged", "failed"})["state"], "converged");
  const json contact = get_json(client, "/v1/jobs/" + std::to_string(job) + "/contact")["contact"];
  ASSERT_EQ(contact.size(), 1U) << contact.dump();
  const json& points = contact[0]["points"];
  std::size_t touching = 0;
  double peak = 0.0;
  for (const json& p : points) {
    touching += p["state"] != "open" ? 1 : 0;
    peak = std::max(peak, p["pressure"].get<double>());
  }
  ASSERT_GT(touching, 0U);

  Browser browser(dir / "chromium-profile");
  open_job(browser, server, job);
  ASSERT_TRUE(wait_until(browser, "return !document.querySelector('#contact-section').hidden;", std::chrono::seconds(30)));
  const json table = browser.run(
      "const t = [...document.querySelectorAll('#contact-pairs table.contact-pair')];"
      "const value = (table, key) => table.querySelector(`tr[data-key=\"${key}\"] td`).textContent;"
      "return t.map(table => [table.caption.textContent, value(table, 'points'), value(table, 'in-contact'),"
      " value(table, 'peak-pressure'), [...table.querySelectorAll('th')].map(h => h.textContent)]);");
  ASSERT_EQ(table.size(), 1U) << table;
  EXPECT_EQ(table[0][0], "Pair 1: hub_bore against shaft_outside");
  EXPECT_EQ(table[0][1], std::to_string(points.size()));
  EXPECT_EQ(table[0][2], std::to_string(touching));
  const std::string shown_peak = table[0][3].get<std::string>();
  EXPECT_NEAR(std::strtod(shown_peak.c_str(), nullptr), peak, 1e-4 * peak) << shown_peak;
  EXPECT_NE(table[0][4].dump().find("peak pressure [psi]"), std::string::npos) << table[0][4];
  EXPECT_NE(table[0][4].dump().find("largest gap [in]"), std::string::npos) << table[0][4];

  // The contact-pressure plot is shown, drawn from the pairs, and no figure shows a broken image.
  EXPECT_TRUE(wait_until(browser,
                         "const i = document.querySelector('#contact-plot');"
                         "return i.checkVisibility() && i.complete && i.naturalWidth > 100;",
                         std::chrono::seconds(60)));
  EXPECT_EQ(browser.run("return document.querySelector('#contact-caption').textContent;"),
            "contact pressure and gap along each contact pair");
  EXPECT_FALSE(browser.run("return [...document.querySelectorAll('img')].some(i => i.checkVisibility() && i.naturalWidth === 0);")
                   .get<bool>())
      << "a broken image is shown";
  const httplib::Result csv = client.Get("/v1/jobs/" + std::to_string(job) + "/plots/contact_pressure.csv");
  ASSERT_TRUE(csv);
  ASSERT_EQ(csv->status, 200) << csv->body;
  EXPECT_NE(csv->body.find("pair,point,x,r,z,pressure,gap,state"), std::string::npos) << csv->body;
  save_artifact("dashboard-contact-job.png", browser.screenshot());

  // Frictionless: no friction rows in the pair's table, no friction figure, no friction columns.
  EXPECT_EQ(table[0][4].dump().find("points slipping"), std::string::npos) << table[0][4];
  EXPECT_FALSE(browser.run("return document.querySelector('#friction-plot').parentElement.checkVisibility();").get<bool>());
  EXPECT_EQ(browser.run("return [...document.querySelectorAll('#iterations thead th')].some(h => h.textContent === 'stick');"),
            false);
  // A pair with friction (hand-made: no model gives one until the solver fills friction) gains mu,
  // the points that stick and slip, the peak shear and the largest slip; a row with friction
  // gains the stick, slip and residual columns.
  const json friction = browser.run(
      "const p = (r, pressure, shear, state, slip) => ({r, z: 1, gap: 0, pressure, shear, state, slip});"
      "const pair = {friction: 0.25, surfaces: ['block', 'base'], points: [p(0, 100, 10, 'stick', 0),"
      " p(1, 100, 20, 'stick', 0), p(2, 80, 20, 'slip', 0.125), p(3, 50, -22.5, 'slip', -0.25), p(4, 0, 0, 'open', 0)]};"
      "const t = contactPairTable(pair, 0, {stress: 'MPa', length: 'mm'});"
      "const value = key => t.querySelector(`tr[data-key=\"${key}\"] td`).textContent;"
      "const row = {iteration: 3, active_set_iterations: 2, contact_pairs: 4, complementarity: 0, closed_gaps: 0,"
      " stick_points: 2, slip_points: 2, friction_residual: 2.5e-14, attempt: 1, seconds: 0.1};"
      "const columns = columnsFor(row);"
      "return [value('friction'), value('sticking'), value('slipping'), value('peak-shear'), value('largest-slip'),"
      " [...t.querySelectorAll('th')].map(h => h.textContent), columns.map(c => c[0]), columns.map(c => c[2](row))];");
  EXPECT_EQ(friction[0], "0.25");
  EXPECT_EQ(friction[1], "2");
  EXPECT_EQ(friction[2], "2");
  EXPECT_EQ(friction[3], "-22.500 at (3.0000, 1.0000)");
  EXPECT_EQ(friction[4], "-0.2500 at (3.0000, 1.0000)");
  EXPECT_NE(friction[5].dump().find("peak shear [MPa]"), std::string::npos) << friction[5];
  EXPECT_NE(friction[5].dump().find("largest slip [mm]"), std::string::npos) << friction[5];
  const json headings = friction[6], cells = friction[7];
  const auto at = [&headings](const char* name) {
    return static_cast<std::size_t>(std::find(headings.begin(), headings.end(), json(name)) - headings.begin());
  };
  ASSERT_LT(at("friction residual"), headings.size()) << headings;
  EXPECT_EQ(cells[at("stick")], "2");
  EXPECT_EQ(cells[at("slip")], "2");
  EXPECT_EQ(cells[at("friction residual")], "2.50e-14");
}

}  // namespace
}  // namespace saasgaps::testing

namespace saasgaps::testing {
namespace {

// A transient heat conduction run: its heat conduction table has a row per output time, the times,
// steps and temperatures of GET /v1/jobs/{id}/thermal; a model without thermal shows no such table.
TEST_F(DashboardRuns, ThePressFitPushOutShowsTheSupportForceAndItsPlot) {
  // Issue 33 through the service: the .geo and the two-step assembly uploaded, imported, solved; the
  // job's progress line, then the pushed face's force (set_reactions of the history) in the
  // dashboard's force table and plot.
  const httplib::MultipartFormDataItems parts{
      {"assembly", example_text("assemblies/press-fit-push-out.assembly.json"), "press-fit-push-out.assembly.json",
       "application/json"},
      {"mesh", example_text("assemblies/press-fit-push-out.geo"), "press-fit-push-out.geo", "text/plain"}};
  const httplib::Result submitted = client.Post("/v1/imports?submit=true", parts);
  ASSERT_TRUE(submitted);
  ASSERT_EQ(submitted->status, 202) << submitted->body;
  const auto job = json::parse(submitted->body)["id"].get<std::int64_t>();
  const json done = wait_for_state(client, job, {"converged", "not_converged", "failed"});
  ASSERT_EQ(done["state"], "converged") << done.dump();
  const json shown = get_json(client, "/v1/jobs/" + std::to_string(job));
  const json& progress = shown["progress"];
  EXPECT_EQ(progress["steps"], 2);
  EXPECT_EQ(progress["step"], 2);
  EXPECT_EQ(progress["step_name"], "push");
  EXPECT_EQ(progress["increment"], 10);
  EXPECT_EQ(progress["fraction"], 1.0);
  EXPECT_NE(progress["text"].get<std::string>().find("step 2/2 \"push\", increment 10/10"), std::string::npos) << progress;
  const json result = get_json(client, "/v1/jobs/" + std::to_string(job) + "/result");
  ASSERT_EQ(result["set_reactions"].size(), 1U) << result["set_reactions"];
  const double fz = result["set_reactions"][0]["fz"].get<double>();
  EXPECT_NEAR(fz, 1469.0, 0.01 * 1469.0);  // mu p pi d L (PressFitPushOut)

  Browser browser(dir / "chromium-profile");
  open_job(browser, server, job);
  ASSERT_TRUE(wait_until(browser, "return !document.querySelector('#forces-section').hidden;", std::chrono::seconds(30)));
  const json table = browser.run(
      "return [...document.querySelectorAll('#forces tbody tr')].map(tr => [...tr.children].map(td => td.textContent));");
  ASSERT_EQ(table.size(), 2U) << table;  // the set and the contact pair
  EXPECT_EQ(table[0][0], "set pushed");
  EXPECT_NEAR(std::strtod(table[0][2].get<std::string>().c_str(), nullptr), fz, 0.01) << table;
  EXPECT_EQ(table[0][3], "step 2, increment 10");
  // The force plot: one point per increment's end (1 + 10) on the set's curve, rising then flat.
  const json values = browser.run(
      "const line = document.querySelector('#force-plot polyline[data-series=\"set pushed fz\"]');"
      "return line ? line.getAttribute('points').split(' ').length : 0;");
  EXPECT_EQ(values, 11);
  EXPECT_NE(browser.run("return document.querySelector('#job-progress').textContent;").get<std::string>().find("100 %"),
            std::string::npos);
  save_artifact("dashboard-press-fit-forces.png", browser.screenshot());
}

TEST_F(DashboardRuns, ATransientHeatRunShowsItsThermalRowsInATable) {
  const std::int64_t job = submit_job(client, transient_heating("ring-shrink-fit-plane-strain.json", {.hot = 400.0}).dump());
  ASSERT_EQ(wait_for_state(client, job, {"converged", "not_converged", "failed"})["state"], "converged");
  const json rows = get_json(client, "/v1/jobs/" + std::to_string(job) + "/thermal")["thermal"];
  ASSERT_EQ(rows.size(), 4u);

  Browser browser(dir / "chromium-profile");
  open_job(browser, server, job);
  EXPECT_EQ(browser.run("return document.querySelector('#thermal-section').hidden;"), false);
  const json headers = browser.run("return [...document.querySelectorAll('#thermal thead th')].map(t => t.textContent);");
  EXPECT_EQ(headers, json({"time", "steps", "max step |dT|", "min T", "max T"}));
  const json table = browser.run(
      "return [...document.querySelectorAll('#thermal tbody tr')].map(r => [...r.children].map(c => c.textContent));");
  ASSERT_EQ(table.size(), rows.size());
  for (std::size_t k = 0; k < rows.size(); ++k) {
    EXPECT_DOUBLE_EQ(std::strtod(table[k][0].get<std::string>().c_str(), nullptr), rows[k]["time"].get<double>());
    EXPECT_EQ(table[k][1], std::to_string(rows[k]["time_steps"].get<int>()));
    EXPECT_EQ(table[k][4], "400");  // the bore is held at 400
  }
  save_artifact("dashboard-thermal.png", browser.screenshot());

  const std::int64_t plain = submit_job(client, example_text("report-problem1.json"));
  wait_for_state(client, plain, {"converged", "not_converged", "failed"});
  open_job(browser, server, plain);
  EXPECT_EQ(browser.run("return document.querySelector('#thermal-section').hidden;"), true);
}

/// A quarter of a thick ring a = 1 .. b = 2 of quad8, `radial` x `around` elements, every node on the
/// map (the mid-side nodes of the arcs on the circles), under a bore pressure of 100 (plane strain,
/// held in z on the x axis and in r on the y axis; the plain block's units and material).
json quad8_quarter_ring(int radial, int around) {
  json nodes = json::array(), elements = json::array(), constraints = json::array(), pressures = json::array();
  const auto id = [radial](int I, int J) { return J * (2 * radial + 1) + I + 1; };
  for (int J = 0; J <= 2 * around; ++J) {
    for (int I = 0; I <= 2 * radial; ++I) {
      if (I % 2 == 1 && J % 2 == 1) continue;  // quad8: no centre node (its id stays unused)
      const double r = 1.0 + static_cast<double>(I) / (2 * radial), angle = std::numbers::pi / 2 * J / (2 * around);
      nodes.push_back({{"id", id(I, J)}, {"r", J == 2 * around ? 0.0 : r * std::cos(angle)}, {"z", r * std::sin(angle)}});
      if (J == 0) constraints.push_back({{"node", id(I, J)}, {"z", 0.0}});
      if (J == 2 * around) constraints.push_back({{"node", id(I, J)}, {"r", 0.0}});
    }
  }
  for (int j = 0; j < around; ++j) {
    for (int i = 0; i < radial; ++i) {
      const int I = 2 * i, J = 2 * j;
      elements.push_back({{"id", j * radial + i + 1},
                          {"nodes", {id(I, J), id(I + 2, J), id(I + 2, J + 2), id(I, J + 2), id(I + 1, J), id(I + 2, J + 1),
                                     id(I + 1, J + 2), id(I, J + 1)}},
                          {"material", 1}});
      if (i == 0) pressures.push_back({{"nodes", {id(0, J + 2), id(0, J)}}, {"normal", 100.0}});
    }
  }
  json doc = plain_block_document(1, 1);  // its units, analysis and material; the mesh and loads are the ring's
  doc["title"] = "quad8 quarter ring under bore pressure";
  doc["nodes"] = nodes;
  doc["elements"] = elements;
  doc["constraints"] = constraints;
  doc["loads"] = {{"pressures", pressures}};
  return doc;
}

TEST_F(DashboardRuns, AQuad8ResultIsDrawnWithCurvedEdgesAndItsErrorEstimate) {
  const std::int64_t job = submit_job(client, quad8_quarter_ring(2, 2).dump());
  ASSERT_EQ(wait_for_state(client, job, {"converged", "not_converged", "failed"})["state"], "converged");
  const json summary = get_json(client, "/v1/jobs/" + std::to_string(job));
  ASSERT_TRUE(summary.contains("error_estimate")) << summary.dump();

  Browser browser(dir / "chromium-profile");
  open_job(browser, server, job);
  // The contour plot (PNG by default) and the estimated stress error, worded as for any result.
  EXPECT_TRUE(wait_until(browser,
                         "const i = document.querySelector('#contour-plot');"
                         "return !i.hidden && i.complete && i.naturalWidth > 100;",
                         std::chrono::seconds(30)));
  char percent[32];
  std::snprintf(percent, sizeof percent, "%.2f %%", 100.0 * summary["error_estimate"]["relative"].get<double>());
  EXPECT_TRUE(wait_until(browser,
                         "const e = document.querySelector('#job-error-estimate');"
                         "return !e.hidden && e.textContent.startsWith('Estimated stress error " + std::string(percent) + "');",
                         std::chrono::seconds(10)))
      << browser.run("return document.querySelector('#job-error-estimate').textContent;");
  save_artifact("dashboard-quad8.png", browser.screenshot());

  // The analyst asks for SVG with the mesh: the picture the page loads draws the arcs of the quad8
  // edges as open polylines of several pieces that bow away from their chords (a chord of 45 degrees
  // has a sagitta of 0.076 r: observed 16 such polylines, the outer arc's bowing 48.5 px), not as
  // the chords of straight edges.
  browser.run("const f = document.querySelector('#plot-format'); f.value = 'svg'; f.dispatchEvent(new Event('change'));"
              "const m = document.querySelector('#plot-mesh'); m.checked = true; m.dispatchEvent(new Event('change'));"
              "return true;");
  ASSERT_TRUE(wait_until(browser, "return document.querySelector('#contour-plot').src.includes('.svg?');",
                         std::chrono::seconds(30)));
  const std::string svg = browser.run("return fetch(document.querySelector('#contour-plot').src).then(r => r.text());")
                              .get<std::string>();
  const std::regex stroked(R"re(<path style="fill:none;[^"]*" d="([^"]*)")re");
  int curved = 0;
  double bow = 0.0;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), stroked); it != std::sregex_iterator(); ++it) {
    std::istringstream d((*it)[1].str());
    std::vector<std::vector<std::array<double, 2>>> pieces;  // subpaths; a closed one ends with Z
    std::vector<bool> closed;
    std::string token;
    while (d >> token) {
      if (token == "M") {
        pieces.emplace_back();
        closed.push_back(false);
      } else if (token == "Z") {
        closed.back() = true;
      } else if (token != "L") {
        std::array<double, 2> point{std::stod(token), 0.0};
        d >> point[1];
        pieces.back().push_back(point);
      }
    }
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      const auto& line = pieces[k];
      if (closed[k] || line.size() < 5) continue;  // frames are closed; ticks and radial edges are 2 points
      const std::array<double, 2> a = line.front(), b = line.back();
      const double length = std::hypot(b[0] - a[0], b[1] - a[1]);
      double farthest = 0.0;
      for (const auto& q : line) {
        farthest = std::max(farthest, std::abs((b[0] - a[0]) * (q[1] - a[1]) - (b[1] - a[1]) * (q[0] - a[0])) / length);
      }
      if (farthest > 3.0) ++curved;
      bow = std::max(bow, farthest);
    }
  }
  // Four arcs of two edges each (the bore, the middle and the outer circle; the mesh and the outline).
  EXPECT_GE(curved, 6) << "largest bow " << bow << " px";
  std::printf("quad8 contour SVG: %d curved edge polylines, largest bow from the chord %.1f px\n", curved, bow);
  save_artifact("dashboard-quad8-mesh.png", browser.screenshot());
}

}  // namespace
}  // namespace saasgaps::testing
