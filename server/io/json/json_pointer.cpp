#include "io/json/json_pointer.hpp"

namespace saasgaps::io {

std::string escape_token(std::string_view key) {
  std::string token;
  token.reserve(key.size());
  for (const char c : key) {
    if (c == '~') {
      token += "~0";
    } else if (c == '/') {
      token += "~1";
    } else {
      token += c;
    }
  }
  return token;
}

std::string pointer_append(const std::string& base, std::string_view key) {
  return base + '/' + escape_token(key);
}

std::string pointer_append(const std::string& base, std::size_t index) {
  return base + '/' + std::to_string(index);
}

}  // namespace saasgaps::io
