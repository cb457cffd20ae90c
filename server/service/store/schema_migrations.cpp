#include "service/store/schema_migrations.hpp"

namespace saasgaps::service {
namespace detail {

extern const std::vector<const char*> migrations = {
    // 1: the first schema.
    R"sql(
    CREATE TABLE jobs (
      id INTEGER PRIMARY KEY AUTOINCREMENT,
      state TEXT NOT NULL,
      title TEXT NOT NULL,
      created_at TEXT NOT NULL,
      started_at TEXT,
      finished_at TEXT,
      updated_at TEXT NOT NULL,
      iteration INTEGER NOT NULL DEFAULT 0,
      max_iterations INTEGER NOT NULL,
      attempts INTEGER NOT NULL DEFAULT 0,
      interruptions INTEGER NOT NULL DEFAULT 0,
      cancel_requested INTEGER NOT NULL DEFAULT 0,
      settings TEXT NOT NULL DEFAULT '{}',
      lease_owner TEXT,
      heartbeat_at TEXT,
      idempotency_key TEXT UNIQUE,
      request_digest TEXT,
      error TEXT,
      message TEXT
    );
    CREATE INDEX jobs_by_state ON jobs(state, id);
    CREATE TABLE models (
      job_id INTEGER PRIMARY KEY REFERENCES jobs(id) ON DELETE CASCADE,
      document TEXT NOT NULL
    );
    CREATE TABLE iterations (
      job_id INTEGER NOT NULL REFERENCES jobs(id) ON DELETE CASCADE,
      iteration INTEGER NOT NULL,
      row TEXT NOT NULL,
      PRIMARY KEY (job_id, iteration)
    ) WITHOUT ROWID;
    CREATE TABLE states (
      job_id INTEGER NOT NULL REFERENCES jobs(id) ON DELETE CASCADE,
      iteration INTEGER NOT NULL,
      state BLOB NOT NULL,
      created_at TEXT NOT NULL,
      PRIMARY KEY (job_id, iteration)
    );
    CREATE TABLE results (
      job_id INTEGER PRIMARY KEY REFERENCES jobs(id) ON DELETE CASCADE,
      document TEXT NOT NULL
    );
    CREATE TABLE events (
      id INTEGER PRIMARY KEY AUTOINCREMENT,
      job_id INTEGER NOT NULL REFERENCES jobs(id) ON DELETE CASCADE,
      kind TEXT NOT NULL,
      data TEXT NOT NULL,
      created_at TEXT NOT NULL
    );
    CREATE INDEX events_by_job ON events(job_id, id);
    )sql",
    // 2: leases of runs (remote workers) and the Slurm job running each.
    R"sql(
    ALTER TABLE jobs ADD COLUMN lease_secret TEXT;
    ALTER TABLE jobs ADD COLUMN slurm_job_id TEXT;
    ALTER TABLE jobs ADD COLUMN slurm_state TEXT;
    )sql",
    // 3: the single-use ticket of a run handed to Slurm, and what a finish keeps of its spent lease.
    R"sql(
    ALTER TABLE jobs ADD COLUMN lease_ticket TEXT;
    ALTER TABLE jobs ADD COLUMN finish_digest TEXT;
    )sql",
    // 4: the thermal history rows of runs with `thermal` (a table of their own: their key is the
    // row's index in the run, not an iteration, and a database of older jobs simply has none).
    R"sql(
    CREATE TABLE thermal_rows (
      job_id INTEGER NOT NULL REFERENCES jobs(id) ON DELETE CASCADE,
      row_index INTEGER NOT NULL,
      row TEXT NOT NULL,
      PRIMARY KEY (job_id, row_index)
    ) WITHOUT ROWID;
    )sql",
    // 5: the result cache (docs/studies.md): a job's cache key (the canonical form of its model and
    // the solver's result_version), and the converged job that answers each key. An entry goes with
    // its job (ON DELETE CASCADE: a delete or the retention never leaves an entry without its result).
    R"sql(
    ALTER TABLE jobs ADD COLUMN cache_key TEXT;
    CREATE TABLE result_cache (
      cache_key TEXT PRIMARY KEY,
      job_id INTEGER NOT NULL REFERENCES jobs(id) ON DELETE CASCADE,
      created_at TEXT NOT NULL
    );
    CREATE INDEX result_cache_by_job ON result_cache(job_id);
    )sql",
    // 6: studies (docs/studies.md): the study document, and each point's job (the job that solves
    // it, or the cached job that answered it), its final status and outputs once reduced.
    R"sql(
    CREATE TABLE studies (
      id INTEGER PRIMARY KEY AUTOINCREMENT,
      title TEXT NOT NULL,
      created_at TEXT NOT NULL,
      document TEXT NOT NULL
    );
    CREATE TABLE study_points (
      study_id INTEGER NOT NULL REFERENCES studies(id) ON DELETE CASCADE,
      point_index INTEGER NOT NULL,
      job_id INTEGER REFERENCES jobs(id) ON DELETE SET NULL,
      cached INTEGER NOT NULL DEFAULT 0,
      status TEXT NOT NULL DEFAULT '',
      outputs TEXT NOT NULL DEFAULT '{}',
      message TEXT NOT NULL DEFAULT '',
      PRIMARY KEY (study_id, point_index)
    ) WITHOUT ROWID;
    CREATE INDEX study_points_by_job ON study_points(job_id);
    )sql",
    // 7: adaptive jobs (docs/http-api.md, POST /v1/imports?submit=true with `adapt`): the uploaded
    // assembly and its files, which every cycle re-imports, and each cycle's `adaptation` row with
    // the sizes it asked for the next mesh (null for the last cycle), so that a run resumes after
    // the last stored cycle.
    R"sql(
    CREATE TABLE adapt_inputs (
      job_id INTEGER PRIMARY KEY REFERENCES jobs(id) ON DELETE CASCADE,
      assembly TEXT NOT NULL
    );
    CREATE TABLE adapt_files (
      job_id INTEGER NOT NULL REFERENCES jobs(id) ON DELETE CASCADE,
      name TEXT NOT NULL,
      content BLOB NOT NULL,
      PRIMARY KEY (job_id, name)
    ) WITHOUT ROWID;
    CREATE TABLE adapt_cycles (
      job_id INTEGER NOT NULL REFERENCES jobs(id) ON DELETE CASCADE,
      cycle INTEGER NOT NULL,
      row TEXT NOT NULL,
      next_sizes TEXT,
      PRIMARY KEY (job_id, cycle)
    );
    )sql",
};

}  // namespace detail
}  // namespace saasgaps::service
