#pragma once
/// Where each solid element's material points sit in the arrays kept per point (material state,
/// stresses at the points): element e owns points first(e) .. first(e) + count(e) - 1, in its
/// family's order (element_family.hpp). The report's elements keep one each, so a model of only
/// them numbers its points as its elements, and keeps every array it always had.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "solver/model/model.hpp"

namespace saasgaps {

class MaterialPoints {
 public:
  explicit MaterialPoints(const Model& model);

  [[nodiscard]] std::size_t first(std::size_t element) const { return first_.empty() ? element : first_[element]; }
  [[nodiscard]] int count(std::size_t element) const {
    return first_.empty() ? 1 : static_cast<int>(first_[element + 1] - first_[element]);
  }
  /// Points in the model.
  [[nodiscard]] std::size_t size() const { return size_; }
  /// True when every element has one point (then point e is element e's).
  [[nodiscard]] bool one_per_element() const { return first_.empty(); }

 private:
  std::vector<std::uint32_t> first_;  // element_count + 1 offsets; empty: one point per element
  std::size_t size_ = 0;
};

/// The number of material points of a model: its element count when every element has one.
std::size_t material_point_count(const Model& model);

}  // namespace saasgaps
