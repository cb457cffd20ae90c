#pragma once
/// The item of a result list (nodes, elements, gaps, watched rows) with the given id.

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace saasgaps::testing {

/// Throws std::out_of_range when no item has that id (a test then fails naming it).
template <typename T>
const T& by_id(const std::vector<T>& items, int id) {
  const auto it = std::find_if(items.begin(), items.end(), [id](const T& x) { return x.id == id; });
  if (it == items.end()) throw std::out_of_range("no item with id " + std::to_string(id));
  return *it;
}

}  // namespace saasgaps::testing
