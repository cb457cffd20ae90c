#include "io/json/value_quote.hpp"

#include <cmath>

namespace saasgaps::io {

using nlohmann::json;

namespace {
constexpr std::size_t quote_limit = 80;
constexpr int quote_depth = 2;
}  // namespace

std::string format_number(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0.0 ? "inf" : "-inf";
  return json(v).dump();
}

std::string quote_string(std::string_view text) {
  const bool cut = text.size() > quote_limit;
  const json literal = std::string(cut ? text.substr(0, quote_limit) : text);
  return literal.dump(-1, ' ', false, json::error_handler_t::replace) + (cut ? "..." : "");
}

namespace {

void append_quote(const json& value, int depth, std::string& out) {
  if (value.is_number_float()) {
    out += format_number(value.get<double>());
  } else if (value.is_string()) {
    out += quote_string(value.get_ref<const std::string&>());
  } else if (value.is_structured()) {
    const bool is_object = value.is_object();
    out += is_object ? '{' : '[';
    if (!value.empty() && depth == 0) out += "...";
    if (depth > 0) {
      bool first = true;
      for (auto it = value.begin(); it != value.end(); ++it) {
        if (!first) out += ", ";
        first = false;
        if (out.size() > quote_limit) {
          out += "...";
          break;
        }
        if (is_object) out += quote_string(it.key()) + ": ";
        append_quote(*it, depth - 1, out);
      }
    }
    out += is_object ? '}' : ']';
  } else {
    // null, booleans and integers: their JSON text is short and exact.
    out += value.dump();
  }
}

}  // namespace

std::string quote(const json& value) {
  std::string out;
  append_quote(value, quote_depth, out);
  return out;
}

std::string describe(const json& value) {
  switch (value.type()) {
    case json::value_t::null: return "null";
    case json::value_t::boolean: return "the boolean " + quote(value);
    case json::value_t::string: return "the string " + quote(value);
    case json::value_t::array: return "the array " + quote(value);
    case json::value_t::object: return "the object " + quote(value);
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float: return "the number " + quote(value);
    default: return "a value that is not plain JSON";
  }
}

std::string join(std::span<const std::string_view> names) {
  std::string text;
  for (const std::string_view name : names) {
    if (!text.empty()) text += ", ";
    text += name;
  }
  return text;
}

}  // namespace saasgaps::io
