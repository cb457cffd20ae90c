/// JobStore, deleting finished jobs: one on request, or every one finished before a cutoff
/// (--retention), and giving the freed pages back to the file system.
#include "service/store/job_store.hpp"

#include "service/store/job_rows.hpp"
#include "service/store/job_store_detail.hpp"

namespace saasgaps::service {

using namespace detail;

void JobStore::remove(std::int64_t id) {
  require_writable();
  {
    auto db = pool_->lease();
    WriteTransaction tx(*db);
    const JobRecord job = require_job(*db, id);
    next_state(id, job.state, JobAction::remove);
    db->prepare("DELETE FROM jobs WHERE id = ?").bind(1, id).run();
    tx.commit();
  }
  reclaim_space();
}

int JobStore::remove_finished_before(const std::string& cutoff) {
  if (!writable()) return 0;
  int removed = 0;
  {
    auto db = pool_->lease();
    WriteTransaction tx(*db);
    db->prepare("DELETE FROM jobs WHERE state IN (" + sql_states_accepting(JobAction::remove) +
                ") AND finished_at IS NOT NULL AND finished_at < ?")
        .bind(1, cutoff)
        .run();
    removed = db->changes();
    tx.commit();
  }
  if (removed > 0) reclaim_space();
  return removed;
}

void JobStore::reclaim_space() {
  try {
    auto db = pool_->lease();
    // Frees every page on the freelist, then folds the WAL into the file so it shrinks now.
    db->execute("PRAGMA incremental_vacuum; PRAGMA wal_checkpoint(TRUNCATE);");
  } catch (const StoreError&) {
    // The delete is committed; the space comes back at the next delete or checkpoint.
  }
}

}  // namespace saasgaps::service
