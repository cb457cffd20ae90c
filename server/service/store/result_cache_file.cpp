#include "service/store/result_cache_file.hpp"

#include <filesystem>

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
}

ResultCacheFile::~ResultCacheFile() = default;

std::optional<ResultCacheFile::Hit> ResultCacheFile::find(const std::string& key, const std::string& canonical_model) {
  const std::lock_guard lock(mutex_);
  Statement q = db_->prepare("SELECT id, model, result FROM cached_results WHERE cache_key = ?");
  q.bind(1, key);
  if (!q.step() || q.text(1) != canonical_model) return std::nullopt;
  return Hit{q.integer(0), q.text(2)};
}

std::int64_t ResultCacheFile::store(const std::string& key, const std::string& canonical_model, const std::string& result) {
  const std::lock_guard lock(mutex_);
  Statement q = db_->prepare(
      "INSERT INTO cached_results (cache_key, model, result, created) VALUES (?, ?, ?, ?) "
      "ON CONFLICT(cache_key) DO UPDATE SET model = excluded.model, result = excluded.result, created = excluded.created "
      "RETURNING id");
  q.bind(1, key).bind(2, canonical_model).bind(3, result).bind(4, utc_now());
  if (!q.step()) throw StoreError("the result cache did not store the entry");
  return q.integer(0);
}

}  // namespace saasgaps::service
