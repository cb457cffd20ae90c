#include "web/browser_session.hpp"

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <stdexcept>
#include <thread>

#include "service/server_process.hpp"

extern char** environ;

namespace saasgaps::testing {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::string decode_base64(const std::string& text) {
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

}  // namespace

Browser::Browser(const fs::path& profile) : port_(free_port()) {
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

Browser::~Browser() {
  if (!session_.empty()) client_->Delete("/session/" + session_);
  ::kill(driver_, SIGTERM);
  int status = 0;
  waitpid(driver_, &status, 0);
}

void Browser::open(const std::string& url) { command("POST", "/session/" + session_ + "/url", {{"url", url}}); }

json Browser::run(const std::string& script) {
  return command("POST", "/session/" + session_ + "/execute/sync", {{"script", script}, {"args", json::array()}});
}

void Browser::choose_files(const std::string& selector, const std::vector<fs::path>& files) {
  const json element = command("POST", "/session/" + session_ + "/element", {{"using", "css selector"}, {"value", selector}});
  // The W3C element reference's key.
  const auto reference = element.find("element-6066-11e4-a52e-4f735466cecf");
  if (reference == element.end()) throw std::runtime_error("WebDriver: no element " + selector + ": " + element.dump());
  const std::string id = reference->get<std::string>();
  std::string paths;
  for (const fs::path& file : files) paths += (paths.empty() ? "" : "\n") + fs::absolute(file).string();
  command("POST", "/session/" + session_ + "/element/" + id + "/value", {{"text", paths}});
}

std::string Browser::screenshot() {
  return decode_base64(command("GET", "/session/" + session_ + "/screenshot", nullptr).get<std::string>());
}

json Browser::command(const std::string& method, const std::string& path, const json& body) {
  const httplib::Result r = method == "GET" ? client_->Get(path) : client_->Post(path, body.dump(), "application/json");
  if (!r) throw std::runtime_error("WebDriver " + path + ": " + httplib::to_string(r.error()));
  const json answer = json::parse(r->body);
  if (r->status != 200) throw std::runtime_error("WebDriver " + path + " answered " + r->body);
  return answer["value"];
}

bool wait_until(Browser& browser, const std::string& script, std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < deadline) {
    if (browser.run(script).get<bool>()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return false;
}

void save_artifact(const std::string& name, const std::string& png) {
  fs::create_directories(SAASGAPS_ARTIFACTS_DIR);
  std::ofstream(fs::path(SAASGAPS_ARTIFACTS_DIR) / name, std::ios::binary) << png;
}

}  // namespace saasgaps::testing
