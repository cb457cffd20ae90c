#include "solver/state/recovered_field.hpp"

namespace saasgaps {

int RecoveredField::side(std::size_t node, int m) const {
  if (!has(node)) return -1;
  for (std::uint32_t s = first[node]; s < first[node + 1]; ++s) {
    if (material[s] == m) return static_cast<int>(s);
  }
  return -1;
}

Vec4 RecoveredField::at(std::size_t node, int m) const {
  const int s = side(node, m);
  return s >= 0 ? value[static_cast<std::size_t>(s)] : mean(node);
}

Vec4 RecoveredField::mean(std::size_t node) const {
  Vec4 sum = Vec4::Zero();
  if (!has(node)) return sum;
  for (std::uint32_t s = first[node]; s < first[node + 1]; ++s) sum += value[s];
  return sum / side_count(node);
}

}  // namespace saasgaps
