#include "service/store/result_cache.hpp"

#include "io/json/canonical_json.hpp"
#include "io/model/model_reader.hpp"

namespace saasgaps::service {

ModelKey model_key(const nlohmann::json& document) {
  ModelKey out;
  out.canonical = io::canonical_json(document);
  out.key = io::cache_key(out.canonical);
  return out;
}

std::optional<ModelKey> model_key(std::string_view text) {
  if (text.size() > cache_max_model_bytes) return std::nullopt;
  return model_key(io::parse_document(text));
}

std::optional<std::int64_t> find_cached(JobStore& store, const ModelKey& key) {
  const std::optional<std::int64_t> job = store.cached_job(key.key);
  if (!job) return std::nullopt;
  try {
    const std::string stored_model = store.model(*job);
    const std::optional<ModelKey> stored = model_key(std::string_view(stored_model));
    if (stored && stored->canonical == key.canonical) return job;
  } catch (const JobNotFound&) {
    // Deleted between the two reads: a miss.
  }
  return std::nullopt;
}

}  // namespace saasgaps::service
