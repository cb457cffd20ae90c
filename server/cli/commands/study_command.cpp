#include "cli/commands/study_command.hpp"

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "cli/common/file_io.hpp"
#include "io/import/assembly_reader.hpp"
#include "io/json/canonical_json.hpp"
#include "io/json/json_text.hpp"
#include "io/json/value_quote.hpp"
#include "io/model/model_reader.hpp"
#include "io/results/result_writer.hpp"
#include "io/study/study_outputs.hpp"
#include "io/study/study_result.hpp"
#include "service/store/result_cache_file.hpp"
#include "solver/base/errors.hpp"
#include "solver/thermal/thermal_analysis.hpp"

namespace saasgaps::cli {

using nlohmann::json;

namespace {

class StudyRun {
 public:
  StudyRun(const io::Study& study, std::filesystem::path base, service::ResultCacheFile* cache, bool quiet)
      : study_(study), base_(std::move(base)), cache_(cache), quiet_(quiet), points_(study.point_count()) {
    for (std::size_t i = 0; i < points_.size(); ++i) points_[i].index = i;
  }

  /// Every point's model read by the model reader before anything is solved: a point it refuses
  /// fails alone, with the parameter that made it invalid (model studies; an assembly's points are
  /// judged by their import).
  void validate() {
    if (study_.assembly) return;
    for (io::PointOutcome& p : points_) {
      std::string why = io::point_issues(study_, p.index);
      if (why.empty()) continue;
      p.status = "failed";
      p.message = std::move(why);
      report(p);
    }
  }

  void run(int workers) {
    std::atomic<std::size_t> next{0};
    const auto work = [&] {
      for (std::size_t i = next++; i < points_.size(); i = next++) {
        if (points_[i].status == "failed") continue;
        run_point(points_[i]);
        report(points_[i]);
      }
    };
    std::vector<std::thread> pool;
    const int n = std::max(1, std::min<int>(workers, static_cast<int>(points_.size())));
    for (int k = 1; k < n; ++k) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
  }

  [[nodiscard]] const std::vector<io::PointOutcome>& points() const { return points_; }
  [[nodiscard]] std::size_t solved() const { return solved_; }

 private:
  void run_point(io::PointOutcome& p) {
    std::string result;
    try {
      const json model_document = study_.assembly ? io::import_assembly(study_.point_document(p.index), base_)
                                                  : study_.point_document(p.index);
      const std::string canonical = io::canonical_json(model_document);
      const std::string key = io::cache_key(canonical);
      std::optional<service::ResultCacheFile::Hit> hit;
      if (cache_ != nullptr) hit = cache_->find(key, canonical);
      if (hit) {
        p.cached = true;
        p.job = hit->entry;
        result = std::move(hit->result);
      } else {
        const Model model = io::read_model(model_document);
        const Solution solution = solve_with_heat(model);
        ++solved_;
        result = io::result_text(model, solution);
        if (cache_ != nullptr && solution.status == RunStatus::converged) p.job = cache_->store(key, canonical, result);
      }
    } catch (const ModelError& e) {
      p.status = "failed";
      p.message = io::point_issues(study_, p.index, e);
      return;
    } catch (const std::exception& e) {
      p.status = "failed";
      p.message = e.what();
      return;
    }
    io::take_result(json::parse(result), study_, p);
  }

  void report(const io::PointOutcome& p) {
    if (quiet_) return;
    const std::lock_guard lock(print_);
    std::cerr << "point " << p.index << " of " << points_.size() << ": " << p.status << (p.cached ? " (cached)" : "");
    for (const io::StudyOutput& o : study_.outputs) {
      const auto it = p.outputs.find(o.name);
      if (it != p.outputs.end() && it->is_number()) std::cerr << " " << o.name << "=" << io::format_number(it->get<double>());
    }
    if (p.status == "failed") std::cerr << ": " << p.message;
    std::cerr << '\n';
  }

  const io::Study& study_;
  std::filesystem::path base_;
  service::ResultCacheFile* cache_;
  bool quiet_;
  std::vector<io::PointOutcome> points_;
  std::atomic<std::size_t> solved_{0};
  std::mutex print_;
};

}  // namespace

std::string csv_path_beside(const std::string& result_path) {
  const std::string suffix = ".json";
  if (result_path.size() > suffix.size() && result_path.ends_with(suffix)) {
    return result_path.substr(0, result_path.size() - suffix.size()) + ".csv";
  }
  return result_path + ".csv";
}

int run_study(const StudyOptions& options) {
  const std::string csv = options.csv_path.empty() ? csv_path_beside(options.result_path) : options.csv_path;
  require_writable(options.result_path, "-o");
  require_writable(csv, "--csv");
  const io::Study study = io::read_study(io::parse_document(read_file(options.study_path)), options.max_points);

  std::unique_ptr<service::ResultCacheFile> cache;
  const char* setting = std::getenv("SAASGAPS_CACHE");
  if (!options.no_cache && setting != nullptr && *setting != '\0') cache = std::make_unique<service::ResultCacheFile>(setting);

  StudyRun run(study, std::filesystem::absolute(options.study_path).parent_path(), cache.get(), options.quiet);
  run.validate();
  run.run(options.workers);

  if (cache && (options.cache_keep_days > 0.0 || options.cache_max_entries > 0)) {
    service::ResultCacheFile::Retention rules;
    if (options.cache_keep_days > 0.0) rules.keep_days = options.cache_keep_days;
    if (options.cache_max_entries > 0) rules.max_entries = options.cache_max_entries;
    if (const int evicted = cache->evict(rules); evicted > 0) {
      std::cerr << "the cache's retention removed " << evicted << (evicted == 1 ? " entry" : " entries") << ", "
                << cache->size() << " left\n";
    }
  }
  const json result = io::study_result_json(study, run.points(), run.solved());
  write_file_atomically(options.result_path, io::json_text(result, 1) + "\n");
  write_file_atomically(csv, io::study_csv(study, run.points()));
  std::cerr << result["message"].get<std::string>() << " (" << run.solved() << " solved, "
            << result["cached"].get<std::size_t>() << " from the cache)\n";
  return result["status"] == "converged" ? 0 : 3;
}

}  // namespace saasgaps::cli
