#include "io/json/json_text.hpp"

namespace saasgaps::io {

std::string json_text(const nlohmann::json& value, int indent) {
  return value.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace saasgaps::io
