#pragma once
/// The service's result cache (docs/studies.md): a model document solved before is answered from the
/// job that solved it. The key is io::cache_key of the document's canonical form
/// (io/json/canonical_json.hpp), which carries the solver's result_version; the entries live in the
/// job store's `result_cache` table (JobStore::cached_job). A candidate found by key is answered
/// only when the canonical form of that job's stored model equals the asked one: a false hit is
/// worse than a miss.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "service/store/job_store.hpp"

namespace saasgaps::service {

/// Models larger than this (bytes of text) are neither looked up nor stored: their canonical form
/// costs a parse tree of the whole document (about ten times its size) on an HTTP thread.
inline constexpr std::size_t cache_max_model_bytes = std::size_t{16} << 20;

struct ModelKey {
  std::string canonical;
  std::string key;
};

/// The key of a parsed model document.
ModelKey model_key(const nlohmann::json& document);
/// The key of a model's text, or nothing when it is beyond cache_max_model_bytes. The text must be
/// JSON (the model reader has read it).
std::optional<ModelKey> model_key(std::string_view text);

/// The converged job whose stored model has exactly this canonical form, if the cache holds one.
std::optional<std::int64_t> find_cached(JobStore& store, const ModelKey& key);

}  // namespace saasgaps::service
