#include "service/runs/model_handoff.hpp"

#include <utility>

namespace saasgaps::service {

void ModelHandoff::put(std::int64_t job, std::shared_ptr<const ParsedModel> model) {
  std::lock_guard lock(mutex_);
  if (models_.size() < capacity_) models_.emplace(job, std::move(model));
}

std::shared_ptr<const ParsedModel> ModelHandoff::take(std::int64_t job) {
  std::lock_guard lock(mutex_);
  auto it = models_.find(job);
  if (it == models_.end()) return nullptr;
  std::shared_ptr<const ParsedModel> model = std::move(it->second);
  models_.erase(it);
  return model;
}

void ModelHandoff::clear() {
  std::map<std::int64_t, std::shared_ptr<const ParsedModel>> dropped;
  {
    std::lock_guard lock(mutex_);
    dropped.swap(models_);
  }
  // The models are freed here, outside the lock.
}

std::size_t ModelHandoff::size() const {
  std::lock_guard lock(mutex_);
  return models_.size();
}

}  // namespace saasgaps::service
