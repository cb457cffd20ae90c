#pragma once
/// `saasgaps study STUDY.json -o STUDY-RESULT.json` (docs/studies.md): every point of a study solved
/// here, on a pool of --workers threads, each point's outputs reduced from its result; the study
/// result and a CSV of parameters and outputs beside it (STUDY-RESULT.csv). With `SAASGAPS_CACHE`
/// set, a point whose model was solved before is answered from the cache file
/// (service/store/result_cache_file.hpp) without solving; --no-cache solves every point afresh.
/// The study document is judged whole before anything runs (exit 2 with every error at its
/// pointer), then every point's model is read by the model reader: a point it refuses fails alone.
/// Exit code: 0 when every point converged, 3 when some did not, 2 for a bad study.

#include <cstddef>
#include <string>

#include "io/study/study_document.hpp"

namespace saasgaps::cli {

struct StudyOptions {
  std::string study_path;
  std::string result_path;  ///< required; the CSV goes beside it (.json replaced by .csv)
  std::string csv_path;     ///< empty: beside the result
  int workers = 1;          ///< points solved at once
  std::size_t max_points = io::default_max_study_points;
  bool no_cache = false;  ///< ignore SAASGAPS_CACHE: solve every point, store nothing
  /// The cache's retention, applied after the study (ResultCacheFile::evict): 0 keeps everything.
  double cache_keep_days = 0.0;       ///< --cache-keep-days, SAASGAPS_CACHE_KEEP_DAYS
  std::size_t cache_max_entries = 0;  ///< --cache-max-entries, SAASGAPS_CACHE_MAX_ENTRIES
  bool quiet = false;     ///< no line per finished point on stderr
};

int run_study(const StudyOptions& options);

/// STUDY-RESULT.json -> STUDY-RESULT.csv (any other name gets ".csv" appended).
std::string csv_path_beside(const std::string& result_path);

}  // namespace saasgaps::cli
