#pragma once
/// What the service fault, kill and fuzz tests share: a fresh directory per test, the example
/// models, submitting a job, checking a problem answer, and `saasgaps solve` as the reference.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "service/server_process.hpp"
#include "support/temp_directory.hpp"

namespace saasgaps::testing {

class ServiceFixture : public ::testing::Test {
 protected:
  [[nodiscard]] std::filesystem::path database() const { return dir_ / "jobs.db"; }

  static std::string example_text(const std::string& name) {
    std::ifstream in(std::string(SAASGAPS_EXAMPLES_DIR) + "/" + name);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }

  /// POST a model as a new job (?cache=off: these tests submit the same models again and mean new
  /// jobs; the result cache has tests of its own); returns the job id (asserting 202).
  static std::int64_t submit(httplib::Client& client, const std::string& body, const httplib::Headers& headers = {}) {
    const httplib::Result r = client.Post("/v1/jobs?cache=off", headers, body, "application/json");
    EXPECT_TRUE(r) << httplib::to_string(r.error());
    if (!r) return 0;
    EXPECT_EQ(r->status, 202) << r->body;
    if (r->status != 202) return 0;
    const std::int64_t id = nlohmann::json::parse(r->body)["id"].get<std::int64_t>();
    EXPECT_EQ(r->get_header_value("Location"), "/v1/jobs/" + std::to_string(id));
    return id;
  }

  static nlohmann::json problem(const httplib::Result& r, int status) {
    EXPECT_TRUE(r);
    if (!r) return nullptr;
    EXPECT_EQ(r->status, status) << r->body;
    EXPECT_EQ(r->get_header_value("Content-Type"), "application/problem+json") << r->body;
    return nlohmann::json::parse(r->body, nullptr, false);
  }

  /// `saasgaps solve` of the same document: the reference every service result must equal.
  [[nodiscard]] nlohmann::json solve_locally(const std::string& body, const std::string& name = "reference") const {
    const auto model = dir_ / (name + "-model.json"), result = dir_ / (name + "-result.json");
    std::ofstream(model) << body;
    const CommandResult run = run_command({SAASGAPS_BINARY, "solve", model.string(), "-q", "-o", result.string()});
    EXPECT_LE(run.exit_code, 3) << run.output;
    std::ifstream in(result);
    return nlohmann::json::parse(in);
  }

  TempDirectory temp_{"service"};
  std::filesystem::path dir_ = temp_.path();
};

}  // namespace saasgaps::testing
