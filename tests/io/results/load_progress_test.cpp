// The progress line of a job (io/results/load_progress.hpp): the load path read from a model's
// text, the fraction of it done, the time left, and the line watch and the dashboard show.
#include <gtest/gtest.h>

#include <chrono>

#include "io/results/load_progress.hpp"

namespace saasgaps::io {
namespace {

using nlohmann::json;

TEST(JobProgress, TheLoadPathIsReadFromTheModelsSteps) {
  const LoadPlan plan = load_plan(R"({"nodes": [{"id": 1, "r": 0, "z": 0}],
      "steps": [{"name": "press", "constraints": [{"set": "a", "z": 0}]},
                {"name": "push", "increments": 10, "loads": {"pressures": [{"set": "b", "normal": 1}]}}]})");
  ASSERT_EQ(plan.steps.size(), 2U);
  EXPECT_EQ(plan.steps[0], (std::pair<std::string, int>{"press", 1}));
  EXPECT_EQ(plan.steps[1], (std::pair<std::string, int>{"push", 10}));
  EXPECT_TRUE(load_plan(R"({"nodes": []})").steps.empty());
  EXPECT_TRUE(load_plan("not json").steps.empty());
}

TEST(JobProgress, FractionAndTimeLeftFollowTheIncrementsFinished) {
  const LoadPlan plan{{{"press", 1}, {"push", 10}}};
  // Step 2, increment 4 under way: 1 + 3 of 11 increments finished, after 8 s.
  const json p = job_progress(plan, json{{"iteration", 9}, {"step", 2}, {"increment", 4}}, true, false, 30, 8.0);
  EXPECT_EQ(p["step"], 2);
  EXPECT_EQ(p["steps"], 2);
  EXPECT_EQ(p["step_name"], "push");
  EXPECT_EQ(p["increment"], 4);
  EXPECT_EQ(p["increments"], 10);
  EXPECT_DOUBLE_EQ(p["fraction"].get<double>(), 4.0 / 11.0);
  EXPECT_DOUBLE_EQ(p["seconds_left"].get<double>(), 8.0 * (7.0 / 11.0) / (4.0 / 11.0));  // 14 s
  EXPECT_EQ(p["text"], "step 2/2 \"push\", increment 4/10, iteration 9: 36 % of the load path done, about 14 s left");
  EXPECT_EQ(p["load_path"].size(), 2U);
  // Before the first row: nothing done, no estimate; once converged: all of it.
  const json first = job_progress(plan, nullptr, true, false, 30, 0.5);
  EXPECT_EQ(first["fraction"], 0.0);
  EXPECT_TRUE(first["seconds_left"].is_null());
  const json done = job_progress(plan, json{{"iteration", 30}, {"step", 2}, {"increment", 10}}, false, true, 30, 20.0);
  EXPECT_EQ(done["fraction"], 1.0);
  EXPECT_TRUE(done["seconds_left"].is_null());
  // A model without steps is one increment: its line says the iteration and its limit.
  const json plain = job_progress(LoadPlan{}, json{{"iteration", 3}}, true, false, 40, 2.0);
  EXPECT_EQ(plain["text"], "iteration 3 (at most 40): 0 % of the load path done");
  EXPECT_TRUE(plain["load_path"].is_null());
  EXPECT_TRUE(plain["step_name"].is_null());
}

TEST(JobProgress, SecondsSinceReadsTheServicesTimes) {
  const auto now = std::chrono::system_clock::from_time_t(1796000000) + std::chrono::milliseconds(250);
  EXPECT_DOUBLE_EQ(seconds_since("2026-11-30T00:53:15.000Z", now), 5.25);
  EXPECT_EQ(seconds_since("yesterday", now), 0.0);
}

}  // namespace
}  // namespace saasgaps::io
