// The job resource's error estimate (ResultRoutes::error_estimate) against a real job store, in
// the race the kill -9 rounds met: GET /v1/jobs/{id} reads the job finished, a resume and a claim
// make it run again before the result is read. The job resource still answers, without an estimate.
#include "service/http/result_routes.hpp"
#include "support/temp_directory.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

namespace saasgaps::service {
namespace {

namespace fs = std::filesystem;

class ErrorEstimateOfAJob : public ::testing::Test {
 protected:
  void SetUp() override { store_ = std::make_unique<JobStore>((dir_ / "jobs.db").string(), 2); }
  /// A job whose first run stopped not converged with this result document.
  std::int64_t finished_job(const std::string& result) {
    const std::int64_t id = store_->submit("{}", "job", 10, std::nullopt, "").job.id;
    const std::optional<ClaimedJob> run = store_->claim("test");
    EXPECT_TRUE(run.has_value());
    store_->finish(id, JobState::not_converged, result, "ended", std::nullopt, std::nullopt, &run->lease, "d");
    return id;
  }

  static constexpr const char* result_with_estimate =
      R"({"status":"not_converged","error_estimate":{"relative":0.125,"error":2.5,"energy_norm":20.0}})";
  testing::TempDirectory temp_{"result-routes"};
  fs::path dir_ = temp_.path();
  std::unique_ptr<JobStore> store_;
};

TEST_F(ErrorEstimateOfAJob, AFinishedJobShowsItsResultsEstimate) {
  const std::int64_t id = finished_job(result_with_estimate);
  ResultRoutes routes(*store_);
  const nlohmann::json estimate = routes.error_estimate(store_->get(id));
  ASSERT_TRUE(estimate.is_object()) << estimate.dump();
  EXPECT_EQ(estimate["relative"], 0.125);
}

TEST_F(ErrorEstimateOfAJob, AJobResumedAndClaimedSinceItWasReadHasNone) {
  const std::int64_t id = finished_job(result_with_estimate);
  const JobRecord read_before = store_->get(id);  // not_converged, finished_at set
  store_->resume(id, {});
  const JobRecord queued = store_->get(id);
  ASSERT_TRUE(store_->claim("test").has_value());  // running again
  ResultRoutes routes(*store_);
  // The stored result may not be read while the job runs (JobConflict): no estimate, no exception.
  EXPECT_EQ(routes.error_estimate(read_before), nullptr);
  // Queued again, the estimate of the run before no longer holds.
  EXPECT_EQ(routes.error_estimate(queued), nullptr);
  EXPECT_EQ(routes.error_estimate(store_->get(id)), nullptr);
}

}  // namespace
}  // namespace saasgaps::service
