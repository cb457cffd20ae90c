// The dashboard in a real browser: Debian's headless Chromium, driven through chromedriver's WebDriver
// protocol, against a real `saasgaps serve`. Submit a job, open its page, watch the iteration table
// grow from the event stream, see the plots appear, and save a screenshot as a test artefact.
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <thread>

#include "service/long_job_model.hpp"
#include "service/server_process.hpp"

extern char** environ;

namespace saasgaps::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

/// chromedriver and one headless Chromium session.
class Browser {
 public:
  explicit Browser(const fs::path& profile) : port_(free_port()) {
    const std::string port_option = "--port=" + std::to_string(port_);
    std::vector<char*> argv = {const_cast<char*>("/usr/bin/chromedriver"), const_cast<char*>(port_option.c_str()),
                               nullptr};
    if (posix_spawn(&driver_, argv[0], nullptr, nullptr, argv.data(), environ) != 0) {
      throw std::runtime_error("cannot start /usr/bin/chromedriver (Debian package chromium-driver)");
    }
    client_ = std::make_unique<httplib::Client>("127.0.0.1", port_);
    client_->set_read_timeout(std::chrono::seconds(60));
    for (int attempt = 0; attempt < 100 && !client_->Get("/status"); ++attempt) {
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    // The flags keep Chromium off the network (this machine has none) and out of first-run dialogs.
    const json capabilities = {
        {"capabilities",
         {{"alwaysMatch",
           {{"browserName", "chrome"},
            {"goog:chromeOptions",
             {{"binary", "/usr/bin/chromium"},
              {"args",
               {"--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage", "--no-first-run",
                "--disable-background-networking", "--disable-component-update", "--disable-sync",
                "--disable-quic", "--window-size=1400,1600", "--user-data-dir=" + profile.string()}}}}}}}}};
    const json session = command("POST", "/session", capabilities);
    session_ = session["sessionId"].get<std::string>();
  }

  ~Browser() {
    if (!session_.empty()) client_->Delete("/session/" + session_);
    ::kill(driver_, SIGTERM);
    int status = 0;
    waitpid(driver_, &status, 0);
  }

  void open(const std::string& url) { command("POST", "/session/" + session_ + "/url", {{"url", url}}); }

  /// Runs script in the page and returns its value.
  json run(const std::string& script) {
    return command("POST", "/session/" + session_ + "/execute/sync", {{"script", script}, {"args", json::array()}});
  }

  /// The page as PNG bytes.
  std::string screenshot() { return decode_base64(command("GET", "/session/" + session_ + "/screenshot", nullptr).get<std::string>()); }

 private:
  json command(const std::string& method, const std::string& path, const json& body) {
    const httplib::Result r = method == "GET" ? client_->Get(path) : client_->Post(path, body.dump(), "application/json");
    if (!r) throw std::runtime_error("WebDriver " + path + ": " + httplib::to_string(r.error()));
    const json answer = json::parse(r->body);
    if (r->status != 200) throw std::runtime_error("WebDriver " + path + " answered " + r->body);
    return answer["value"];
  }

  static std::string decode_base64(const std::string& text) {
    static const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    unsigned bits = 0;
    int count = 0;
    for (char c : text) {
      const auto at = alphabet.find(c);
      if (at == std::string::npos) continue;
      bits = (bits << 6) | static_cast<unsigned>(at);
      count += 6;
      if (count >= 8) {
        count -= 8;
        out += static_cast<char>((bits >> count) & 0xFF);
      }
    }
    return out;
  }

  int port_;
  pid_t driver_ = -1;
  std::unique_ptr<httplib::Client> client_;
  std::string session_;
};

TEST(Dashboard, FollowsARunningJobAndShowsItsPlots) {
  const fs::path dir = fs::temp_directory_path() / ("saasgaps-browser-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  ServerProcess server(dir / "jobs.db");
  httplib::Client client = server.client();
  const httplib::Result submitted =
      client.Post("/v1/jobs", tilted_block_document(200).dump(), "application/json");
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
        " (document.querySelector('#job-state') || {}).textContent || ''];");
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
  EXPECT_EQ(browser.run("return document.querySelectorAll('#iterations tbody tr').length;").get<int>(), iterations);

  // The artefact: a screenshot of the finished job page.
  const std::string png = browser.screenshot();
  ASSERT_GT(png.size(), 10000U);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  fs::create_directories(SAASGAPS_ARTIFACTS_DIR);
  std::ofstream(fs::path(SAASGAPS_ARTIFACTS_DIR) / "dashboard-job.png", std::ios::binary) << png;

  // The job list shows the job with its state.
  browser.open(base + "/#/");
  std::string listed;
  for (int attempt = 0; attempt < 50 && listed.empty(); ++attempt) {
    listed = browser.run("const cell = document.querySelector('#jobs tbody tr td:nth-child(3)');"
                         "return cell ? cell.textContent : '';")
                 .get<std::string>();
    if (listed.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  EXPECT_EQ(listed, "converged");
  std::ofstream(fs::path(SAASGAPS_ARTIFACTS_DIR) / "dashboard-list.png", std::ios::binary) << browser.screenshot();
  fs::remove_all(dir);
}

}  // namespace
}  // namespace saasgaps::testing
