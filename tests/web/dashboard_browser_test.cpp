// The dashboard in a real browser: Debian's headless Chromium, driven through chromedriver's WebDriver
// protocol, against a real `saasgaps serve`. Submit a job, open its page, watch the iteration table
// grow from the event stream, see the plots appear, and save a screenshot as a test artefact.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <thread>

#include "service/long_job_model.hpp"
#include "service/server_process.hpp"
#include "web/browser_session.hpp"
#include "web/plain_block.hpp"

namespace saasgaps::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

TEST(Dashboard, FailedJobsSayWhyAndJobsCanBeDeleted) {
  const TempDirectory temp("browser-fail");
  const fs::path& dir = temp.path();
  ServerProcess server(dir / "jobs.db");
  httplib::Client client = server.client();
  // Valid, but a mechanism: a held square and a second square hinged to it at one corner. The
  // model passes validation (its one body is restrained); the solver finds it singular.
  json model = plain_block_document(1, 1);
  model["nodes"].push_back({{"id", 5}, {"r", 2.0}, {"z", 1.0}});
  model["nodes"].push_back({{"id", 6}, {"r", 2.0}, {"z", 2.0}});
  model["nodes"].push_back({{"id", 7}, {"r", 1.0}, {"z", 2.0}});
  model["elements"].push_back({{"id", 2}, {"nodes", {4, 5, 6, 7}}, {"material", 1}});
  const httplib::Result submitted = client.Post("/v1/jobs", model.dump(), "application/json");
  ASSERT_EQ(submitted->status, 202) << submitted->body;
  const auto job = json::parse(submitted->body)["id"].get<std::int64_t>();
  const json failed = wait_for_state(client, job, {"failed", "converged"});
  ASSERT_EQ(failed["state"], "failed");
  const std::string error = failed["error"].get<std::string>();

  Browser browser(dir / "chromium-profile");
  const std::string base = "http://127.0.0.1:" + std::to_string(server.port());
  browser.open(base + "/#/");
  ASSERT_TRUE(wait_until(browser, "return !!document.querySelector('#jobs tbody .reason');", std::chrono::seconds(10)));
  EXPECT_EQ(browser.run("return document.querySelector('#jobs tbody .reason').title;").get<std::string>(), error);
  browser.open(base + "/#/jobs/" + std::to_string(job));
  ASSERT_TRUE(wait_until(browser, "return document.body.dataset.ready === 'job';", std::chrono::seconds(10)));
  EXPECT_EQ(browser.run("const e = document.querySelector('#job-error'); return e.hidden ? '' : e.textContent;")
                .get<std::string>(),
            "Failed: " + error);
  EXPECT_TRUE(browser.run("return document.querySelector('#job-error-estimate').hidden;").get<bool>())
      << "a failed job has no error estimate";
  save_artifact("dashboard-failed-job.png", browser.screenshot());

  // Delete asks first: refused, nothing happens; confirmed, the job is gone and the list shows.
  browser.run("window.confirm = () => false; document.querySelector('#delete').click(); return true;");
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  EXPECT_EQ(client.Get("/v1/jobs/" + std::to_string(job))->status, 200);
  browser.run("window.confirm = () => true; document.querySelector('#delete').click(); return true;");
  ASSERT_TRUE(wait_until(browser, "return location.hash === '#/' && document.body.dataset.ready === 'list';",
                         std::chrono::seconds(10)));
  EXPECT_EQ(client.Get("/v1/jobs/" + std::to_string(job))->status, 404);
  fs::remove_all(dir);
}

TEST(Dashboard, FollowsARunningJobAndShowsItsPlots) {
  const TempDirectory temp("browser-follow");
  const fs::path& dir = temp.path();
  ServerProcess server(dir / "jobs.db");
  httplib::Client client = server.client();
  json model = tilted_block_document(200);
  model["output"] = {{"watch_elements", {1}}, {"watch_gaps", {model["gaps"]["elements"][0]["id"]}}};
  const httplib::Result submitted = client.Post("/v1/jobs", model.dump(), "application/json");
  ASSERT_EQ(submitted->status, 202);
  const auto job = json::parse(submitted->body)["id"].get<std::int64_t>();

  Browser browser(dir / "chromium-profile");
  const std::string base = "http://127.0.0.1:" + std::to_string(server.port());
  browser.open(base + "/#/jobs/" + std::to_string(job));

  // The table grows while the job runs: rows arrive through the event stream, not by reloading.
  std::vector<int> counts;
  std::string state;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (std::chrono::steady_clock::now() < deadline) {
    const json seen = browser.run(
        "return [document.querySelectorAll('#iterations tbody tr').length,"
        " ((document.querySelector('#job-state') || {}).dataset || {}).state || ''];");
    const int rows = seen[0].get<int>();
    state = seen[1].get<std::string>();
    if (counts.empty() || rows != counts.back()) counts.push_back(rows);
    if (state == "converged" || state == "failed" || state == "not_converged") break;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  EXPECT_EQ(state, "converged");
  ASSERT_GE(counts.size(), 3U) << "the table did not grow while the job ran";
  EXPECT_TRUE(std::is_sorted(counts.begin(), counts.end()));
  const int iterations = get_json(client, "/v1/jobs/" + std::to_string(job))["iteration"].get<int>();

  // Once the job has a result, the plots load.
  bool plots = false;
  for (int attempt = 0; attempt < 200 && !plots; ++attempt) {
    plots = browser.run(
                       "const img = ['#contour-plot', '#closure-plot'].map(s => document.querySelector(s));"
                       "return img.every(i => i && !i.hidden && i.complete && i.naturalWidth > 100);")
                .get<bool>();
    if (!plots) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  EXPECT_TRUE(plots) << "the contour and closure plots did not appear";
  // The finished result's estimated stress error, worded as the command line's summary (issue 32).
  const double relative = get_json(client, "/v1/jobs/" + std::to_string(job))["error_estimate"]["relative"].get<double>();
  char percent[32];
  std::snprintf(percent, sizeof percent, "%.2f %%", 100.0 * relative);
  EXPECT_TRUE(wait_until(browser,
                         "const e = document.querySelector('#job-error-estimate');"
                         "return !e.hidden && e.textContent.startsWith('Estimated stress error " + std::string(percent) +
                             " in the energy norm');",
                         std::chrono::seconds(10)))
      << browser.run("return document.querySelector('#job-error-estimate').textContent;");
  EXPECT_EQ(browser.run("return document.querySelectorAll('#iterations tbody tr').length;").get<int>(), iterations);
  // The watched element and gap have their columns, as the CLI prints them, with the row's values.
  const std::string gap_id = std::to_string(model["gaps"]["elements"][0]["id"].get<int>());
  const json headers = browser.run("return [...document.querySelectorAll('#iterations thead th')].map(t => t.textContent);");
  for (const std::string& name : std::vector<std::string>{"el 1 s_r", "el 1 s_th", "el 1 eff", "gap " + gap_id + " E_M", "gap " + gap_id + " clos %",
                                 "gap " + gap_id + " s_M"}) {
    EXPECT_NE(std::find(headers.begin(), headers.end(), json(name)), headers.end()) << name << " in " << headers;
  }
  const json last = get_json(client, "/v1/jobs/" + std::to_string(job))["last_row"];
  char closure[32];
  std::snprintf(closure, sizeof closure, "%.2f", last["watch"]["gaps"][0]["closure"].get<double>());
  EXPECT_EQ(browser.run("const r = document.querySelector('#iterations tbody tr:last-child');"
                        "return r.children[r.children.length - 2].textContent;")
                .get<std::string>(),
            closure);
  // The analyst picks the gap row and its axis: the contact plot is drawn again for them; a gap the
  // model does not have is named in the note.
  const std::string row = gap_id + "-" + std::to_string(std::stoi(gap_id) + 9);
  browser.run("const g = document.querySelector('#plot-gaps'); g.value = '" + row + "';"
              "const a = document.querySelector('#plot-along'); a.value = 'position';"
              "a.dispatchEvent(new Event('change')); return true;");
  EXPECT_TRUE(wait_until(browser,
                         "const i = document.querySelector('#contact-plot');"
                         "return i.src.includes('gaps=" + row + "') && i.src.includes('along=position') &&"
                         " i.complete && i.naturalWidth > 0 && !i.hidden;",
                         std::chrono::seconds(30)));
  browser.run("const g = document.querySelector('#plot-gaps'); g.value = '7';"
              "g.dispatchEvent(new Event('change')); return true;");
  EXPECT_TRUE(wait_until(browser, "return document.querySelector('#plot-note').textContent.includes('gap 7 is not a gap element');",
                         std::chrono::seconds(30)));
  // The contact pressure's numbers, the model's units (none named), the VTU in either form.
  const httplib::Result table = client.Get("/v1/jobs/" + std::to_string(job) + "/plots/contact_pressure.csv?gaps=" + gap_id);
  ASSERT_EQ(table->status, 200);
  EXPECT_EQ(table->get_header_value("Content-Type").rfind("text/csv", 0), 0U);
  EXPECT_NE(table->body.find("\n" + gap_id + ","), std::string::npos) << table->body;
  EXPECT_EQ(get_json(client, "/v1/jobs/" + std::to_string(job) + "/units"), json::object());
  EXPECT_EQ(client.Get("/v1/jobs/" + std::to_string(job) + "/plots/effective.csv")->status, 409);
  EXPECT_EQ(client.Get("/v1/jobs/" + std::to_string(job) + "/plots/contact_pressure.png?gaps=x")->status, 400);
  EXPECT_EQ(client.Get("/v1/jobs/" + std::to_string(job) + "/result.vtu?format=ascii")->status, 200);
  EXPECT_EQ(client.Get("/v1/jobs/" + std::to_string(job) + "/result.vtu?format=text")->status, 400);
  // The job carries its per-gap closures; the job list does not.
  EXPECT_EQ(last["gap_closures"].size(), model["gaps"]["elements"].size());
  const httplib::Result list = client.Get("/v1/jobs");
  EXPECT_EQ(list->body.find("gap_closures"), std::string::npos);
  EXPECT_TRUE(json::parse(list->body)["jobs"][0]["last_row"].contains("watch"));

  // The artefact: a screenshot of the finished job page.
  const std::string png = browser.screenshot();
  ASSERT_GT(png.size(), 10000U);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  save_artifact("dashboard-job.png", png);

  // The job list shows the job with its state (the badge's words say more when the run warns:
  // tests/web/dashboard_runs_browser_test.cpp).
  browser.open(base + "/#/");
  std::string listed;
  for (int attempt = 0; attempt < 50 && listed.empty(); ++attempt) {
    listed = browser.run("const badge = document.querySelector('#jobs tbody tr td:nth-child(3) .state');"
                         "return badge ? badge.dataset.state : '';")
                 .get<std::string>();
    if (listed.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  EXPECT_EQ(listed, "converged");
  save_artifact("dashboard-list.png", browser.screenshot());
  fs::remove_all(dir);
}

}  // namespace
}  // namespace saasgaps::testing
