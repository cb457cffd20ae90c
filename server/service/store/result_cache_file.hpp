#pragma once
/// The command line's result cache (`SAASGAPS_CACHE`, docs/studies.md): an SQLite file of results
/// keyed by the canonical form of their model (io/json/canonical_json.hpp) and the solver's
/// result_version. The service keeps its cache in its own database instead (result_cache.hpp).
///
/// `SAASGAPS_CACHE` is the path of an SQLite file, created if missing, or of an existing
/// directory, in which the file is `saasgaps-results.sqlite`. Each entry holds the canonical model
/// text itself: a lookup compares it with the asked one, so two models that share a fingerprint
/// are a miss, never a false hit. Only converged results are stored. Each entry records when it was
/// last used (stored, or answered a lookup); evict() removes entries by the retention rules
/// (`saasgaps study --cache-keep-days` / `--cache-max-entries`, or SAASGAPS_CACHE_KEEP_DAYS /
/// SAASGAPS_CACHE_MAX_ENTRIES): by age, as the service's --keep-finished removes old jobs and their
/// cache entries with them, and by count, the least recently used first.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

namespace saasgaps::service {

class Connection;

class ResultCacheFile {
 public:
  /// The file of a `SAASGAPS_CACHE` value (a directory: its saasgaps-results.sqlite).
  static std::string file_of(const std::string& setting);

  explicit ResultCacheFile(const std::string& setting);
  ~ResultCacheFile();

  struct Hit {
    std::int64_t entry = 0;  ///< the entry's id: the provenance a study point reports as `job`
    std::string result;      ///< the result document's text
  };
  /// The result stored under `key` for exactly this canonical model text.
  std::optional<Hit> find(const std::string& key, const std::string& canonical_model);
  /// Stores a converged result; returns its entry id (an entry already there for the key is replaced).
  std::int64_t store(const std::string& key, const std::string& canonical_model, const std::string& result);

  /// The retention rules; each absent one keeps everything.
  struct Retention {
    std::optional<double> keep_days;         ///< entries last used longer ago than this are removed
    std::optional<std::size_t> max_entries;  ///< beyond this many, the least recently used are removed
  };
  /// Removes the entries the rules say and gives their pages back to the file system; returns how
  /// many were removed.
  int evict(const Retention& rules);
  /// Entries stored now.
  [[nodiscard]] std::size_t size();

 private:
  std::mutex mutex_;
  std::unique_ptr<Connection> db_;
};

}  // namespace saasgaps::service
