// The dashboard's studies (docs/studies.md), in headless Chromium against a real `saasgaps serve`:
// the list under the jobs links each study; a study's page has a row per point and, for each output,
// a plot against each parameter, a dot per point and a line per combination of the other
// parameters. Screenshots land in build/tests/artifacts/.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "service/job_client.hpp"
#include "service/server_process.hpp"
#include "support/lame_cylinder_document.hpp"
#include "web/browser_session.hpp"

namespace saasgaps::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

TEST(DashboardStudies, TheListLinksAStudyWhosePageDrawsEachOutputAgainstEachParameter) {
  const TempDirectory temp("browser");
  const fs::path& dir = temp.path();
  {
    ServerProcess server(dir / "jobs.db");
    httplib::Client client = server.client();
    const json doc = lame_cylinder::study_document({1000.0, 2500.0, 4000.0}, {10.0e6, 30.0e6});
    const httplib::Result posted = client.Post("/v1/studies", doc.dump(), "application/json");
    ASSERT_TRUE(posted);
    ASSERT_EQ(posted->status, 202) << posted->body;
    const std::int64_t id = json::parse(posted->body)["id"];
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    json study;
    do {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      study = get_json(client, "/v1/studies/" + std::to_string(id));
    } while (study["status"] == "running" && std::chrono::steady_clock::now() < deadline);
    ASSERT_EQ(study["status"], "converged") << study.dump();

    const std::string base = "http://127.0.0.1:" + std::to_string(server.port());
    Browser browser(dir / "chromium-profile");
    browser.open(base + "/#/");
    ASSERT_TRUE(wait_until(browser, "return document.body.dataset.ready === 'list';", std::chrono::seconds(30)));
    const json listed = browser.run(
        "const s = document.querySelector('#studies-section');"
        "return [s.hidden, [...s.querySelectorAll('tbody tr')].map(tr => [...tr.children].map(td => td.textContent))];");
    EXPECT_FALSE(listed[0].get<bool>());
    ASSERT_EQ(listed[1].size(), 1U) << listed;
    EXPECT_EQ(listed[1][0][0], std::to_string(id));
    EXPECT_EQ(listed[1][0][2], "6");  // points
    EXPECT_EQ(listed[1][0][4], "6");  // converged

    browser.run("document.querySelector('#studies tbody a').click(); return true;");
    ASSERT_TRUE(wait_until(browser, "return document.body.dataset.ready === 'study';", std::chrono::seconds(30)));
    EXPECT_EQ(browser.run("return document.querySelectorAll('#study-points tbody tr').length;"), 6);
    // One plot per output (fz, u_max) and parameter: against E a line per p, two dots each;
    // against p a line per E, three dots each.
    const json plots = browser.run(
        "return [...document.querySelectorAll('#study-plots svg')].map(svg => [svg.dataset.output, "
        "svg.dataset.parameter, svg.querySelectorAll('polyline').length, svg.querySelectorAll('circle').length]);");
    ASSERT_EQ(plots.size(), 4U) << plots;
    // (Names in the order the study result's objects keep them: by bytes.)
    EXPECT_EQ(plots[0], json({"fz", "E", 3, 6}));
    EXPECT_EQ(plots[1], json({"fz", "p", 2, 6}));
    EXPECT_EQ(plots[2], json({"u_max", "E", 3, 6}));
    EXPECT_EQ(plots[3], json({"u_max", "p", 2, 6}));
    // The dots carry the points' outputs: at E = 1e7 u_max rises with p, in proportion.
    const json dots = browser.run(
        "return [...document.querySelectorAll('#study-plots svg[data-output=\"u_max\"][data-parameter=\"p\"] polyline')][0]"
        ".getAttribute('data-series');");
    EXPECT_EQ(dots, "E = 10000000");
    const json heights = browser.run(
        "return [...document.querySelectorAll('#study-plots svg[data-output=\"u_max\"][data-parameter=\"p\"] circle')]"
        ".map(c => [Number(c.dataset.point), Number(c.getAttribute('cy'))]);");
    ASSERT_EQ(heights.size(), 6U);
    // Points 0, 2, 4 are E = 1e7 at p = 1000, 2500, 4000: higher on the page as u_max grows.
    EXPECT_GT(heights[0][1].get<double>(), heights[1][1].get<double>()) << heights;
    EXPECT_GT(heights[1][1].get<double>(), heights[2][1].get<double>()) << heights;
    save_artifact("dashboard-study.png", browser.screenshot());
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace saasgaps::testing
