#include "solver/fe/material_points.hpp"

#include "solver/fe/element_family.hpp"

namespace saasgaps {

MaterialPoints::MaterialPoints(const Model& model) : size_(model.elements.size()) {
  bool one_each = true;
  for (const Element& el : model.elements) {
    if (family(el.type).point_count(el.integration) != 1) {
      one_each = false;
      break;
    }
  }
  if (one_each) return;
  first_.reserve(model.elements.size() + 1);
  std::uint32_t next = 0;
  for (const Element& el : model.elements) {
    first_.push_back(next);
    next += static_cast<std::uint32_t>(family(el.type).point_count(el.integration));
  }
  first_.push_back(next);
  size_ = next;
}

std::size_t material_point_count(const Model& model) { return MaterialPoints(model).size(); }

}  // namespace saasgaps
