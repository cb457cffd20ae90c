// The job page of a 100,000-element result in headless Chromium: interactive within two seconds of
// the navigation's start, measured by the page's own clock. It runs alone (RUN_SERIAL): the figure is
// a page's time on an unloaded machine (0.7 s here), not its time beside a solve of another test on
// the same two cores (over 2 s when it ran beside one).
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <regex>

#include "service/long_job_model.hpp"
#include "service/server_process.hpp"
#include "web/browser_session.hpp"
#include "web/plain_block.hpp"

namespace saasgaps::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

TEST(Dashboard, LargeResultPageIsInteractiveWithinTwoSeconds) {
  const TempDirectory temp("browser-large");
  const fs::path& dir = temp.path();
  ServerProcess server(dir / "jobs.db");
  httplib::Client client = server.client();
  client.set_read_timeout(std::chrono::seconds(120));
  const json model = plain_block_document(317, 316);  // 100172 elements
  const httplib::Result submitted = client.Post("/v1/jobs", model.dump(), "application/json");
  ASSERT_TRUE(submitted);
  ASSERT_EQ(submitted->status, 202) << submitted->body;
  const auto job = json::parse(submitted->body)["id"].get<std::int64_t>();
  ASSERT_EQ(wait_for_state(client, job, {"converged", "failed"})["state"], "converged");
  const auto started = std::chrono::steady_clock::now();
  const auto seconds = [&started] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  };
  std::cout << "solved and stored\n";

  Browser browser(dir / "chromium-profile");
  const std::string base = "http://127.0.0.1:" + std::to_string(server.port());
  // Open the list first, so that the job page is measured as a user reaches it: a new page load.
  browser.open(base + "/#/");
  ASSERT_TRUE(wait_until(browser, "return document.body.dataset.ready === 'list';", std::chrono::seconds(30)));
  browser.open(base + "/?large#/jobs/" + std::to_string(job));
  // Waited for generously: the measure is the page's own clock below, not this wait.
  ASSERT_TRUE(wait_until(browser, "return document.body.dataset.ready === 'job';", std::chrono::seconds(30)));
  // From the start of navigation to the job's state, table and controls shown (performance.now()
  // counts from the navigation's start).
  const double ready_ms = browser.run("return window.saasgapsReadyAt;").get<double>();
  std::cout << "job page of a " << model["elements"].size() << "-element result interactive after " << ready_ms
            << " ms\n";
  EXPECT_LT(ready_ms, 2000.0);
  EXPECT_EQ(browser.run("return document.querySelector('#job-state').textContent;").get<std::string>(), "converged");
  EXPECT_EQ(browser.run("return document.querySelectorAll('#iterations tbody tr').length;").get<int>(), 1);
  EXPECT_EQ(browser.run("return document.querySelector('#job-units').textContent;").get<std::string>(),
            "force lbf, length in, stress psi, temperature degF");
  // Times in the browser's zone, named (this machine's browser runs in UTC unless TZ says otherwise).
  const std::string created = browser.run("return document.querySelector('#job-created').textContent;").get<std::string>();
  EXPECT_TRUE(std::regex_search(created, std::regex(R"(\d{2}:\d{2}:\d{2}.*[A-Z]{2,})"))) << created;

  // The contour plot arrives as a PNG drawn for its figure's width (device pixels), not as SVG.
  ASSERT_TRUE(wait_until(browser,
                         "const i = document.querySelector('#contour-plot');"
                         "return !i.hidden && i.complete && i.naturalWidth > 0;",
                         std::chrono::seconds(90)))
      << "the contour plot did not load";
  std::cout << "contour plot shown " << seconds() << " s after the job converged\n";
  const json plot = browser.run(
      "const i = document.querySelector('#contour-plot');"
      "return [i.src, i.naturalWidth, Math.round(i.parentElement.clientWidth * devicePixelRatio),"
      " document.querySelector('#contact-plot').parentElement.hidden];");
  EXPECT_NE(plot[0].get<std::string>().find("/plots/effective.png?"), std::string::npos) << plot[0];
  // Drawn for its figure's width (a scroll bar that appears once the picture is in may take 15 px).
  EXPECT_NEAR(plot[1].get<int>(), std::max(320, plot[2].get<int>()), 0.03 * plot[2].get<int>());
  EXPECT_TRUE(plot[3].get<bool>()) << "no contact plot for a model without gaps";
  save_artifact("dashboard-large-job.png", browser.screenshot());

  // A click opens the plot full size, drawn again for the window.
  browser.run("document.querySelector('#contour-plot').click(); return true;");
  ASSERT_TRUE(wait_until(browser,
                         "const v = document.querySelector('#full-view'); const i = v.querySelector('img');"
                         "return !v.hidden && i.complete && i.naturalWidth > 0;",
                         std::chrono::seconds(90)));
  EXPECT_GT(browser.run("const i = document.querySelector('#full-view img'); return i.naturalWidth * i.naturalHeight;")
                .get<double>(),
            1.2 * browser.run("const i = document.querySelector('#contour-plot'); return i.naturalWidth * i.naturalHeight;")
                      .get<double>());
  save_artifact("dashboard-full-view.png", browser.screenshot());
  fs::remove_all(dir);
}

}  // namespace
}  // namespace saasgaps::testing
