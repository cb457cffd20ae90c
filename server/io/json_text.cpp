#include "io/json_text.hpp"

namespace saasgaps::io {

std::string json_text(const nlohmann::json& value, int indent) {
  return value.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

bool is_utf8(std::string_view text) {
  std::size_t i = 0;
  while (i < text.size()) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x80) {
      ++i;
      continue;
    }
    std::size_t length = 0;
    std::uint32_t code = 0, least = 0;
    if ((c & 0xE0) == 0xC0) { length = 2; code = c & 0x1F; least = 0x80; }
    else if ((c & 0xF0) == 0xE0) { length = 3; code = c & 0x0F; least = 0x800; }
    else if ((c & 0xF8) == 0xF0) { length = 4; code = c & 0x07; least = 0x10000; }
    else return false;
    if (i + length > text.size()) return false;
    for (std::size_t k = 1; k < length; ++k) {
      const auto next = static_cast<unsigned char>(text[i + k]);
      if ((next & 0xC0) != 0x80) return false;
      code = (code << 6) | (next & 0x3F);
    }
    if (code < least || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return false;
    i += length;
  }
  return true;
}

}  // namespace saasgaps::io
