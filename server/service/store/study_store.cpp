/// JobStore, studies (docs/studies.md): a study and its points' jobs created in one transaction,
/// read back with the jobs' states, and each point's outputs recorded once its job has finished.
#include "service/store/job_rows.hpp"
#include "service/store/job_store.hpp"
#include "service/store/job_store_detail.hpp"

namespace saasgaps::service {

using namespace detail;

std::int64_t JobStore::create_study(const std::string& document, const std::string& title,
                                    const std::vector<StudyPointInput>& points) {
  require_writable();
  try {
    auto db = pool_->lease();
    WriteTransaction tx(*db);
    db->prepare("INSERT INTO studies (title, created_at, document) VALUES (?, ?, ?)")
        .bind(1, title)
        .bind(2, utc_now())
        .bind(3, document)
        .run();
    const std::int64_t id = db->last_insert_id();
    for (std::size_t k = 0; k < points.size(); ++k) {
      const StudyPointInput& p = points[k];
      std::optional<std::int64_t> job = p.cached_job;
      if (p.status == "queued") {
        job = insert_job_row(*db, p.model, p.title, p.max_iterations, std::nullopt, {}, p.cache_key);
      }
      Statement q = db->prepare(
          "INSERT INTO study_points (study_id, point_index, job_id, cached, status, outputs, message)"
          " VALUES (?, ?, ?, ?, ?, ?, ?)");
      q.bind(1, id)
          .bind(2, static_cast<std::int64_t>(k))
          .bind(3, job)
          .bind(4, p.cached_job ? 1 : 0)
          .bind(5, p.status == "queued" ? std::string() : p.status)
          .bind(6, p.outputs)
          .bind(7, p.message)
          .run();
    }
    tx.commit();
    return id;
  } catch (const StoreError& e) {
    note_failure(e);
    throw;
  }
}

StudyRecord JobStore::study(std::int64_t id) {
  auto db = pool_->lease();
  Statement s = db->prepare("SELECT id, title, created_at, document FROM studies WHERE id = ?");
  s.bind(1, id);
  if (!s.step()) throw JobNotFound(id);
  StudyRecord out{s.integer(0), s.text(1), s.text(2), s.text(3), {}};
  Statement q = db->prepare(
      "SELECT p.point_index, p.job_id, p.cached, p.status, p.outputs, p.message, j.state, j.error"
      " FROM study_points p LEFT JOIN jobs j ON j.id = p.job_id WHERE p.study_id = ? ORDER BY p.point_index");
  q.bind(1, id);
  while (q.step()) {
    StudyPointRow row;
    row.index = static_cast<std::size_t>(q.integer(0));
    if (!q.is_null(1)) row.job = q.integer(1);
    row.cached = q.integer(2) != 0;
    row.status = q.text(3);
    row.outputs = q.text(4);
    row.message = q.text(5);
    if (!q.is_null(6)) row.job_state = parse_job_state(q.text(6));
    row.job_error = q.optional_text(7);
    out.points.push_back(std::move(row));
  }
  return out;
}

std::vector<StudyRecord> JobStore::studies() {
  auto db = pool_->lease();
  Statement s = db->prepare("SELECT id FROM studies ORDER BY id DESC");
  std::vector<std::int64_t> ids;
  while (s.step()) ids.push_back(s.integer(0));
  std::vector<StudyRecord> out;
  for (const std::int64_t id : ids) {
    try {
      StudyRecord r = study(id);
      r.document.clear();
      out.push_back(std::move(r));
    } catch (const JobNotFound&) {
      // deleted meanwhile
    }
  }
  return out;
}

void JobStore::set_study_point(std::int64_t study, std::size_t index, const std::string& status,
                               const std::string& outputs, const std::string& message) {
  require_writable();
  try {
    auto db = pool_->lease();
    WriteTransaction tx(*db);
    db->prepare("UPDATE study_points SET status = ?, outputs = ?, message = ? WHERE study_id = ? AND point_index = ?")
        .bind(1, status)
        .bind(2, outputs)
        .bind(3, message)
        .bind(4, study)
        .bind(5, static_cast<std::int64_t>(index))
        .run();
    tx.commit();
  } catch (const StoreError& e) {
    note_failure(e);
    throw;
  }
}

}  // namespace saasgaps::service
