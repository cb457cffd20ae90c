// The commit pipeline (server/service/commit_pipeline.*): commits run in order on one thread, at
// most one in flight, and a commit's failure reaches the solver's thread exactly once. The model
// hand-off (server/service/model_handoff.*): bounded, each model handed out once.

#include "service/runs/commit_pipeline.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include "service/runs/model_handoff.hpp"

namespace saasgaps::service {
namespace {

using namespace std::chrono_literals;

TEST(CommitPipeline, RunsCommitsInOrderOneAtATimeOffTheCallersThread) {
  std::vector<int> done;
  std::atomic<int> running{0};
  std::atomic<int> most_running{0};
  const std::thread::id caller = std::this_thread::get_id();
  {
    CommitPipeline pipeline;
    for (int k = 1; k <= 20; ++k) {
      pipeline.post([&, k] {
        const int now = ++running;
        if (now > most_running) most_running = now;
        EXPECT_NE(std::this_thread::get_id(), caller);
        std::this_thread::sleep_for(1ms);
        done.push_back(k);  // safe: post waits for the commit before
        --running;
      });
    }
    pipeline.wait();
    EXPECT_EQ(done.size(), 20U);
  }
  for (int k = 1; k <= 20; ++k) EXPECT_EQ(done[static_cast<size_t>(k - 1)], k);
  EXPECT_EQ(most_running.load(), 1);
}

TEST(CommitPipeline, PostReturnsWhileTheCommitRuns) {
  CommitPipeline pipeline;
  std::atomic<bool> release{false};
  std::atomic<bool> finished{false};
  pipeline.post([&] {
    while (!release) std::this_thread::sleep_for(1ms);
    finished = true;
  });
  // The caller computes the next iteration meanwhile.
  EXPECT_FALSE(finished);
  release = true;
  pipeline.wait();
  EXPECT_TRUE(finished);
}

TEST(CommitPipeline, AFailureIsRethrownOnceByTheNextPostOrWait) {
  CommitPipeline pipeline;
  pipeline.post([] { throw std::runtime_error("disk full"); });
  while (!pipeline.failed()) std::this_thread::sleep_for(1ms);
  bool ran = false;
  EXPECT_THROW(pipeline.post([&] { ran = true; }), std::runtime_error);
  EXPECT_FALSE(ran) << "a commit after a failed one must not run";
  EXPECT_FALSE(pipeline.failed());
  EXPECT_NO_THROW(pipeline.wait());

  pipeline.post([] { throw std::logic_error("lease revoked"); });
  try {
    pipeline.wait();
    ADD_FAILURE() << "wait did not rethrow";
  } catch (const std::logic_error& e) {
    EXPECT_STREQ(e.what(), "lease revoked");
  }
  EXPECT_NO_THROW(pipeline.wait());
}

TEST(CommitPipeline, DestructionWaitsForTheCommitInFlight) {
  std::atomic<bool> finished{false};
  {
    CommitPipeline pipeline;
    pipeline.post([&] {
      std::this_thread::sleep_for(20ms);
      finished = true;
    });
  }
  EXPECT_TRUE(finished);
}

TEST(ModelHandoff, KeepsUpToItsCapacityAndHandsEachModelOutOnce) {
  ModelHandoff handoff(2);
  auto model = [](const char* title) {
    auto parsed = std::make_shared<ParsedModel>();
    parsed->model.title = title;
    return parsed;
  };
  handoff.put(1, model("one"));
  handoff.put(2, model("two"));
  handoff.put(3, model("three"));  // full: the older jobs run first, this one reads its document
  EXPECT_EQ(handoff.size(), 2U);
  EXPECT_EQ(handoff.take(3), nullptr);
  const auto two = handoff.take(2);
  ASSERT_NE(two, nullptr);
  EXPECT_EQ(two->model.title, "two");
  EXPECT_EQ(handoff.take(2), nullptr);
  handoff.put(4, model("four"));
  handoff.clear();
  EXPECT_EQ(handoff.size(), 0U);
  EXPECT_EQ(handoff.take(1), nullptr);
  EXPECT_EQ(handoff.take(4), nullptr);
}

}  // namespace
}  // namespace saasgaps::service
