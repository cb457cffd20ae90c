// A database written by an earlier version of the server: schema version 1, 4 KiB pages, an
// interrupted job whose restart state is the plain CBOR of that version. Opened by this version it
// migrates, the job resumes from that state and ends with the uninterrupted run's numbers; the
// state it stores from then on is the compressed encoding, and every stored row gets its commit
// time. A new database gets the larger page size.
#include <gtest/gtest.h>
#include <sqlite3.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "io/restart/state_codec.hpp"
#include "io/restart/stored_state.hpp"
#include "io/results/history_json.hpp"
#include "io/results/result_writer.hpp"
#include "service/runs/job_runner.hpp"
#include "service/store/event_hub.hpp"
#include "service/store/job_store.hpp"
#include "solver/analysis/analysis.hpp"
#include "support/examples.hpp"
#include "support/temp_directory.hpp"

namespace saasgaps {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr const char* example = "ring-shrink-fit-plane-strain.json";

/// The schema of version 1 as that version created it (a frozen fixture, not the migration list).
constexpr const char* schema_version_1 = R"sql(
PRAGMA page_size=4096;
PRAGMA journal_mode=WAL;
CREATE TABLE jobs (id INTEGER PRIMARY KEY AUTOINCREMENT, state TEXT NOT NULL, title TEXT NOT NULL,
  created_at TEXT NOT NULL, started_at TEXT, finished_at TEXT, updated_at TEXT NOT NULL,
  iteration INTEGER NOT NULL DEFAULT 0, max_iterations INTEGER NOT NULL, attempts INTEGER NOT NULL DEFAULT 0,
  interruptions INTEGER NOT NULL DEFAULT 0, cancel_requested INTEGER NOT NULL DEFAULT 0,
  settings TEXT NOT NULL DEFAULT '{}', lease_owner TEXT, heartbeat_at TEXT, idempotency_key TEXT UNIQUE,
  request_digest TEXT, error TEXT, message TEXT);
CREATE INDEX jobs_by_state ON jobs(state, id);
CREATE TABLE models (job_id INTEGER PRIMARY KEY REFERENCES jobs(id) ON DELETE CASCADE, document TEXT NOT NULL);
CREATE TABLE iterations (job_id INTEGER NOT NULL REFERENCES jobs(id) ON DELETE CASCADE, iteration INTEGER NOT NULL,
  row TEXT NOT NULL, PRIMARY KEY (job_id, iteration)) WITHOUT ROWID;
CREATE TABLE states (job_id INTEGER NOT NULL REFERENCES jobs(id) ON DELETE CASCADE, iteration INTEGER NOT NULL,
  state BLOB NOT NULL, created_at TEXT NOT NULL, PRIMARY KEY (job_id, iteration));
CREATE TABLE results (job_id INTEGER PRIMARY KEY REFERENCES jobs(id) ON DELETE CASCADE, document TEXT NOT NULL);
CREATE TABLE events (id INTEGER PRIMARY KEY AUTOINCREMENT, job_id INTEGER NOT NULL REFERENCES jobs(id) ON DELETE CASCADE,
  kind TEXT NOT NULL, data TEXT NOT NULL, created_at TEXT NOT NULL);
CREATE INDEX events_by_job ON events(job_id, id);
PRAGMA user_version=1;
)sql";

/// Keeps the restart states of a run and stops it after `stop_after` iterations.
class Recorder : public IterationObserver {
 public:
  explicit Recorder(int stop_after) : stop_after_(stop_after) {}
  void on_iteration(const IterationRecord&, const RestartState& state) override { states.push_back(state); }
  bool stop_requested() override { return static_cast<int>(states.size()) >= stop_after_; }
  std::vector<RestartState> states;

 private:
  int stop_after_;
};

void exec(sqlite3* db, const std::string& sql) {
  char* error = nullptr;
  ASSERT_EQ(sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &error), SQLITE_OK) << (error ? error : "");
}

int page_size(const fs::path& path) {
  service::Connection c(path.string());
  service::Statement q = c.prepare("PRAGMA page_size");
  q.step();
  return static_cast<int>(q.integer(0));
}

json without_wall_times(json result) {
  for (json& row : result["history"]) {
    row.erase("seconds");
    row.erase("attempt");
  }
  return result;
}

class OldDatabase : public ::testing::Test {
 protected:
  testing::TempDirectory temp_{"old-db"};
  fs::path directory_ = temp_.path();
};

TEST_F(OldDatabase, MigratesAndItsInterruptedJobResumesFromTheOldState) {
  const json document = testing::example_document(example);
  const Model model = testing::example_model(example);
  const std::string digest = io::model_digest(document);
  Recorder first_run(2);
  solve(model, &first_run);
  const RestartState& saved = first_run.states.back();

  const fs::path path = directory_ / "old.db";
  {
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
    exec(db, schema_version_1);
    exec(db, "INSERT INTO jobs (state, title, created_at, updated_at, iteration, max_iterations, attempts) "
             "VALUES ('interrupted', 'old', 'then', 'then', 2, 40, 1)");
    sqlite3_stmt* q = nullptr;
    ASSERT_EQ(sqlite3_prepare_v2(db, "INSERT INTO models VALUES (1, ?)", -1, &q, nullptr), SQLITE_OK);
    const std::string text = document.dump();
    sqlite3_bind_text(q, 1, text.c_str(), static_cast<int>(text.size()), SQLITE_TRANSIENT);
    ASSERT_EQ(sqlite3_step(q), SQLITE_DONE);
    sqlite3_finalize(q);
    for (const IterationRecord& row : saved.history) {
      ASSERT_EQ(sqlite3_prepare_v2(db, "INSERT INTO iterations VALUES (1, ?, ?)", -1, &q, nullptr), SQLITE_OK);
      const std::string row_text = io::history_row_json(row).dump();
      sqlite3_bind_int(q, 1, row.iteration);
      sqlite3_bind_text(q, 2, row_text.c_str(), static_cast<int>(row_text.size()), SQLITE_TRANSIENT);
      ASSERT_EQ(sqlite3_step(q), SQLITE_DONE);
      sqlite3_finalize(q);
    }
    // The state as version 1 stored it: plain CBOR.
    const std::vector<std::uint8_t> old_state = io::state_to_cbor(saved, digest);
    ASSERT_EQ(sqlite3_prepare_v2(db, "INSERT INTO states VALUES (1, 2, ?, 'then')", -1, &q, nullptr), SQLITE_OK);
    sqlite3_bind_blob(q, 1, old_state.data(), static_cast<int>(old_state.size()), SQLITE_TRANSIENT);
    ASSERT_EQ(sqlite3_step(q), SQLITE_DONE);
    sqlite3_finalize(q);
    sqlite3_close(db);
  }

  service::JobStore store(path.string(), 3);
  {
    service::EventHub hub;
    service::JobRunner runner(store, hub, 1);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (!service::is_finished(store.get(1).state)) {
      ASSERT_LT(std::chrono::steady_clock::now(), deadline) << "the job did not finish";
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  }
  const service::JobRecord job = store.get(1);
  ASSERT_EQ(job.state, service::JobState::converged) << job.error.value_or("");
  EXPECT_EQ(job.attempts, 2);
  const Solution uninterrupted = solve(model);
  EXPECT_EQ(without_wall_times(json::parse(*store.result(1))),
            without_wall_times(json::parse(io::result_text(model, uninterrupted))));

  // Rows of the resumed run carry their commit time; the old rows stay as they were.
  const std::vector<std::string> rows = store.iterations(1, 0);
  ASSERT_EQ(rows.size(), uninterrupted.history.size());
  EXPECT_FALSE(json::parse(rows[1]).contains("commit_seconds"));
  for (std::size_t k = 2; k < rows.size(); ++k) {
    const json row = json::parse(rows[k]);
    ASSERT_TRUE(row.contains("commit_seconds")) << "row " << k + 1;
    EXPECT_GT(row["commit_seconds"].get<double>(), 0.0);
  }
  // Migrated to the thermal rows' table: a model without thermal has none.
  EXPECT_TRUE(store.thermal_rows(1, 0).empty());
  // Migrated to the result cache: the old job was submitted without a cache key, so it answers none.
  EXPECT_EQ(store.cache_entries(), 0);
  // The latest state is stored in the new encoding, and decodes to the final iteration.
  service::Connection c(path.string());
  service::Statement q = c.prepare("SELECT state FROM states WHERE job_id = 1 ORDER BY iteration DESC LIMIT 1");
  ASSERT_TRUE(q.step());
  const std::vector<std::uint8_t> latest = q.blob(0);
  ASSERT_GE(latest.size(), 4U);
  EXPECT_EQ(std::string(latest.begin(), latest.begin() + 4), "SGZ1");
  EXPECT_EQ(io::decode_stored_state(latest, digest).iteration, uninterrupted.iterations);
  EXPECT_EQ(page_size(path), 4096);
}

TEST_F(OldDatabase, ANewDatabaseGetsLargePages) {
  const fs::path path = directory_ / "new.db";
  service::JobStore store(path.string(), 3);
  EXPECT_EQ(page_size(path), service::Connection::page_size);
}

}  // namespace
}  // namespace saasgaps
