#pragma once
/// The browser tests' harness: Debian's headless Chromium driven through chromedriver's WebDriver
/// protocol (packages chromium and chromium-driver), plus the helpers every dashboard test uses.
/// Screenshots land in build/tests/artifacts/.

#include <httplib.h>
#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/temp_directory.hpp"

namespace saasgaps::testing {

/// chromedriver and one headless Chromium session (a 1400 x 1600 window, off the network).
class Browser {
 public:
  explicit Browser(const std::filesystem::path& profile);
  ~Browser();
  Browser(const Browser&) = delete;
  Browser& operator=(const Browser&) = delete;

  void open(const std::string& url);
  /// Runs script in the page and returns its value.
  nlohmann::json run(const std::string& script);
  /// Chooses files in the page's <input type="file"> found by a CSS selector, as a user picking
  /// them would (WebDriver's Element Send Keys: several paths for an input with `multiple`).
  void choose_files(const std::string& selector, const std::vector<std::filesystem::path>& files);
  /// The page as PNG bytes.
  std::string screenshot();

 private:
  nlohmann::json command(const std::string& method, const std::string& path, const nlohmann::json& body);

  int port_;
  pid_t driver_ = -1;
  std::unique_ptr<httplib::Client> client_;
  std::string session_;
};

/// Polls script (returning true when done) every 50 ms up to the timeout.
bool wait_until(Browser& browser, const std::string& script, std::chrono::milliseconds timeout);

/// Writes the PNG to build/tests/artifacts/name.
void save_artifact(const std::string& name, const std::string& png);

}  // namespace saasgaps::testing
