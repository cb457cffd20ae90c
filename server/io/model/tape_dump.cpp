#include "io/model/tape_dump.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdio>

#include <nlohmann/json.hpp>

namespace saasgaps::io {

namespace dom = simdjson::dom;

void append_number(std::string& out, const Number& n) {
  std::array<char, 64> buffer{};
  char* end = buffer.data();
  switch (n.kind) {
    case Number::Kind::signed_integer: end = std::to_chars(buffer.begin(), buffer.end(), n.integer).ptr; break;
    case Number::Kind::unsigned_integer: end = std::to_chars(buffer.begin(), buffer.end(), n.unsigned_).ptr; break;
    // Text holds finite numbers only, which dump() writes with nlohmann's to_chars.
    case Number::Kind::floating: end = nlohmann::detail::to_chars(buffer.begin(), buffer.end(), n.floating); break;
  }
  out.append(buffer.data(), end);
}

void TapeDump::flush() {
  if (!buffer_.empty()) sink_(buffer_);
  buffer_.clear();
}

void TapeDump::value(dom::element value) {
  this->value(value, 0);
  flush();
}

void TapeDump::string(std::string_view text) {
  buffer_ += '"';
  // Most strings (every key of a model) need no escape: copy them whole.
  if (std::none_of(text.begin(), text.end(), [](char c) {
        return c == '"' || c == '\\' || static_cast<unsigned char>(c) <= 0x1F;
      })) {
    buffer_ += text;
    buffer_ += '"';
    return;
  }
  for (const char c : text) {
    switch (c) {
      case '"': buffer_ += "\\\""; break;
      case '\\': buffer_ += "\\\\"; break;
      case '\b': buffer_ += "\\b"; break;
      case '\t': buffer_ += "\\t"; break;
      case '\n': buffer_ += "\\n"; break;
      case '\f': buffer_ += "\\f"; break;
      case '\r': buffer_ += "\\r"; break;
      default:
        if (static_cast<unsigned char>(c) <= 0x1F) {
          std::array<char, 8> escaped{};
          std::snprintf(escaped.data(), escaped.size(), "\\u%04x", static_cast<unsigned>(c));
          buffer_ += escaped.data();
        } else {
          buffer_ += c;
        }
    }
  }
  buffer_ += '"';
}

void TapeDump::object(dom::object members, std::size_t depth) {
  auto& sorted = members_[depth];
  sorted.clear();
  for (const dom::key_value_pair member : members) sorted.emplace_back(member.key, member.value);
  // Stable: of a repeated key the members stay in text order, and the last one is the value. Text
  // printed with sorted keys (and every node {id, r, z}) is in order already.
  const auto by_key = [](const auto& a, const auto& b) { return a.first < b.first; };
  if (!std::is_sorted(sorted.begin(), sorted.end(), by_key)) std::stable_sort(sorted.begin(), sorted.end(), by_key);
  buffer_ += '{';
  bool first = true;
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    if (i + 1 < sorted.size() && sorted[i + 1].first == sorted[i].first) continue;
    if (!first) buffer_ += ',';
    first = false;
    string(sorted[i].first);
    buffer_ += ':';
    value(sorted[i].second, depth + 1);
  }
  buffer_ += '}';
}

void TapeDump::value(dom::element value, std::size_t depth) {
  if (buffer_.size() >= capacity) flush();
  switch (value.type()) {
    case dom::element_type::OBJECT: object(dom::object(value), depth); break;
    case dom::element_type::ARRAY: {
      buffer_ += '[';
      bool first = true;
      for (const dom::element item : dom::array(value)) {
        if (!first) buffer_ += ',';
        first = false;
        this->value(item, depth + 1);
      }
      buffer_ += ']';
      break;
    }
    case dom::element_type::INT64:
      append_number(buffer_, Number{Number::Kind::signed_integer, value.get_int64().value_unsafe()});
      break;
    case dom::element_type::UINT64: {
      Number n{Number::Kind::unsigned_integer};
      n.unsigned_ = value.get_uint64().value_unsafe();
      append_number(buffer_, n);
      break;
    }
    case dom::element_type::DOUBLE: {
      Number n;
      n.floating = value.get_double().value_unsafe();
      append_number(buffer_, n);
      break;
    }
    case dom::element_type::STRING: string(value.get_string().value_unsafe()); break;
    case dom::element_type::BOOL: buffer_ += value.get_bool().value_unsafe() ? "true" : "false"; break;
    case dom::element_type::NULL_VALUE: buffer_ += "null"; break;
  }
}

}  // namespace saasgaps::io
