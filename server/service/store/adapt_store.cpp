/// JobStore, adaptive jobs: the uploaded assembly and its files, and each cycle's row with the
/// sizes it asked for (schema migration 7).
#include "service/store/job_store.hpp"

#include "service/store/job_rows.hpp"
#include "service/store/job_store_detail.hpp"

namespace saasgaps::service {

using namespace detail;

JobStore::Submitted JobStore::submit_adaptive(const std::string& model, const std::string& title, int max_iterations,
                                              const AdaptiveInput& input,
                                              const std::optional<std::string>& idempotency_key,
                                              const std::string& request_digest) {
  require_writable();
  try {
    auto db = pool_->lease();
    WriteTransaction tx(*db);
    if (std::optional<JobRecord> earlier = replayed_job(*db, idempotency_key, request_digest)) return {*earlier, true};
    const std::int64_t id = insert_job_row(*db, model, title, max_iterations, idempotency_key, request_digest, {});
    db->prepare("INSERT INTO adapt_inputs (job_id, assembly) VALUES (?, ?)").bind(1, id).bind(2, input.assembly).run();
    for (const auto& [name, content] : input.files) {
      db->prepare("INSERT INTO adapt_files (job_id, name, content) VALUES (?, ?, ?)")
          .bind(1, id)
          .bind(2, name)
          .bind_blob(3, std::vector<std::uint8_t>(content.begin(), content.end()))
          .run();
    }
    JobRecord job = require_job(*db, id);
    tx.commit();
    return {job, false};
  } catch (const StoreError& e) {
    note_failure(e);
    throw;
  }
}

std::optional<AdaptiveInput> JobStore::adaptive_input(std::int64_t id) {
  auto db = pool_->lease();
  Statement q = db->prepare("SELECT assembly FROM adapt_inputs WHERE job_id = ?");
  q.bind(1, id);
  if (!q.step()) return std::nullopt;
  AdaptiveInput input;
  input.assembly = q.text(0);
  Statement f = db->prepare("SELECT name, content FROM adapt_files WHERE job_id = ? ORDER BY name");
  f.bind(1, id);
  while (f.step()) {
    const std::vector<std::uint8_t> bytes = f.blob(1);
    input.files.emplace_back(f.text(0), std::string(bytes.begin(), bytes.end()));
  }
  return input;
}

void JobStore::record_adapt_cycle(std::int64_t id, int cycle, const std::string& row,
                                  const std::optional<std::string>& next_sizes) {
  run_write(id, [&](Connection& db, const JobRecord&) {
    db.prepare("DELETE FROM adapt_cycles WHERE job_id = ? AND cycle >= ?").bind(1, id).bind(2, cycle).run();
    db.prepare("INSERT INTO adapt_cycles (job_id, cycle, row, next_sizes) VALUES (?, ?, ?, ?)")
        .bind(1, id)
        .bind(2, cycle)
        .bind(3, row)
        .bind(4, next_sizes)
        .run();
    db.prepare("UPDATE jobs SET heartbeat_at = ?1, updated_at = ?1 WHERE id = ?2").bind(1, utc_now()).bind(2, id).run();
    add_event(db, id, "adapt_cycle", row);
    return true;
  });
}

std::vector<StoredAdaptCycle> JobStore::adapt_cycles(std::int64_t id, bool with_sizes) {
  auto db = pool_->lease();
  require_job(*db, id);
  Statement q = db->prepare(with_sizes ? "SELECT cycle, row, next_sizes FROM adapt_cycles WHERE job_id = ? ORDER BY cycle"
                                       : "SELECT cycle, row, NULL FROM adapt_cycles WHERE job_id = ? ORDER BY cycle");
  q.bind(1, id);
  std::vector<StoredAdaptCycle> out;
  while (q.step()) {
    StoredAdaptCycle c;
    c.cycle = static_cast<int>(q.integer(0));
    c.row = q.text(1);
    if (!q.is_null(2)) c.next_sizes = q.text(2);
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace saasgaps::service
