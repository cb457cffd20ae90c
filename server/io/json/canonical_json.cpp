#include "io/json/canonical_json.hpp"

#include <charconv>
#include <system_error>

#include "io/json/fingerprint.hpp"
#include "io/json/json_text.hpp"
#include "solver/base/result_version.hpp"

namespace saasgaps::io {

using nlohmann::json;

namespace {

void append_number(double v, std::string& out) {
  char text[32];
  const auto [end, error] = std::to_chars(text, text + sizeof text, v);
  if (error != std::errc{}) throw std::logic_error("to_chars failed on a double");
  out.append(text, end);
}

void append(const json& value, std::string& out) {
  switch (value.type()) {
    case json::value_t::object: {
      out += '{';
      bool first = true;
      // nlohmann::json keeps an object's members in a std::map: sorted by the keys' bytes.
      for (auto it = value.begin(); it != value.end(); ++it) {
        if (!first) out += ',';
        first = false;
        out += json_text(json(it.key()));
        out += ':';
        append(it.value(), out);
      }
      out += '}';
      return;
    }
    case json::value_t::array: {
      out += '[';
      for (std::size_t i = 0; i < value.size(); ++i) {
        if (i > 0) out += ',';
        append(value[i], out);
      }
      out += ']';
      return;
    }
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float:
      append_number(value.get<double>(), out);
      return;
    default:
      out += json_text(value);  // strings, booleans, null
      return;
  }
}

}  // namespace

std::string canonical_json(const json& document) {
  std::string out;
  append(document, out);
  return out;
}

std::string cache_key(const std::string& canonical_text) {
  Fingerprint f;
  f.add(canonical_text);
  return "r" + std::to_string(result_version) + "-" + std::to_string(canonical_text.size()) + "-" + f.hex();
}

}  // namespace saasgaps::io
