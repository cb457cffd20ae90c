#include "solver/base/plural.hpp"

namespace saasgaps {

std::string plural(long long count, const std::string& noun) {
  return std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
}

}  // namespace saasgaps
