#include "solver/contact/contact_pair.hpp"

namespace saasgaps {

double gap_function(const ContactPair& pair, std::span<const double> displacement) {
  double g = pair.g0;
  for (std::size_t k = 0; k < pair.node.size(); ++k) {
    const Vec2 c = pair.coefficient(k);
    for (int dir = 0; dir < 2; ++dir) g += c[dir] * displacement[2 * pair.node[k] + dir];
  }
  return g;
}

}  // namespace saasgaps
