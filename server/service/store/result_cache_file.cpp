#include "service/store/result_cache_file.hpp"

#include <chrono>
#include <filesystem>
#include <ratio>

#include "service/ops/utc_time.hpp"
#include "service/store/sqlite.hpp"

namespace saasgaps::service {

std::string ResultCacheFile::file_of(const std::string& setting) {
  std::error_code ec;
  if (std::filesystem::is_directory(setting, ec)) return (std::filesystem::path(setting) / "saasgaps-results.sqlite").string();
  return setting;
}

ResultCacheFile::ResultCacheFile(const std::string& setting) : db_(std::make_unique<Connection>(file_of(setting))) {
  db_->execute(
      "CREATE TABLE IF NOT EXISTS cached_results ("
      " id INTEGER PRIMARY KEY,"
      " cache_key TEXT NOT NULL UNIQUE,"
      " model TEXT NOT NULL,"
      " result TEXT NOT NULL,"
      " created TEXT NOT NULL)");
  // Files written before eviction existed have no `used`: added, and read as `created` until set.
  bool has_used = false;
  Statement columns = db_->prepare("PRAGMA table_info(cached_results)");
  while (columns.step()) has_used = has_used || columns.text(1) == "used";
  if (!has_used) db_->execute("ALTER TABLE cached_results ADD COLUMN used TEXT");
}

ResultCacheFile::~ResultCacheFile() = default;

std::optional<ResultCacheFile::Hit> ResultCacheFile::find(const std::string& key, const std::string& canonical_model) {
  const std::lock_guard lock(mutex_);
  Hit hit;
  {
    Statement q = db_->prepare("SELECT id, model, result FROM cached_results WHERE cache_key = ?");
    q.bind(1, key);
    if (!q.step() || q.text(1) != canonical_model) return std::nullopt;
    hit = Hit{q.integer(0), q.text(2)};
  }
  db_->prepare("UPDATE cached_results SET used = ? WHERE id = ?").bind(1, utc_now()).bind(2, hit.entry).run();
  return hit;
}

std::int64_t ResultCacheFile::store(const std::string& key, const std::string& canonical_model, const std::string& result) {
  const std::lock_guard lock(mutex_);
  Statement q = db_->prepare(
      "INSERT INTO cached_results (cache_key, model, result, created, used) VALUES (?, ?, ?, ?, ?4) "
      "ON CONFLICT(cache_key) DO UPDATE SET model = excluded.model, result = excluded.result, created = excluded.created, "
      "used = excluded.used RETURNING id");
  q.bind(1, key).bind(2, canonical_model).bind(3, result).bind(4, utc_now());
  if (!q.step()) throw StoreError("the result cache did not store the entry");
  return q.integer(0);
}

int ResultCacheFile::evict(const Retention& rules) {
  const std::lock_guard lock(mutex_);
  int removed = 0;
  if (rules.keep_days) {
    const auto age = std::chrono::duration_cast<std::chrono::system_clock::duration>(
        std::chrono::duration<double, std::ratio<86400>>(*rules.keep_days));
    db_->prepare("DELETE FROM cached_results WHERE COALESCE(used, created) < ?")
        .bind(1, utc_text(std::chrono::system_clock::now() - age))
        .run();
    removed += db_->changes();
  }
  if (rules.max_entries) {
    db_->prepare("DELETE FROM cached_results WHERE id NOT IN (SELECT id FROM cached_results "
                 "ORDER BY COALESCE(used, created) DESC, id DESC LIMIT ?)")
        .bind(1, static_cast<std::int64_t>(*rules.max_entries))
        .run();
    removed += db_->changes();
  }
  if (removed > 0) db_->execute("VACUUM");
  return removed;
}

std::size_t ResultCacheFile::size() {
  const std::lock_guard lock(mutex_);
  Statement q = db_->prepare("SELECT COUNT(*) FROM cached_results");
  return q.step() ? static_cast<std::size_t>(q.integer(0)) : 0;
}

}  // namespace saasgaps::service
