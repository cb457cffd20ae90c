#pragma once
/// nlohmann's compact dump of a value held in simdjson's DOM tape (internal to io/), written
/// without a tree: what json::dump() prints for the tree nlohmann's parser would build from the
/// same text. The model reader's digest (model_digest, io/state_codec.hpp) hashes it, so it must
/// match dump() byte for byte:
/// - object members in key order (std::map's: bytes compared as unsigned), and of a repeated key
///   only the last value (nlohmann's parser keeps the later one);
/// - integers as written (a minus zero is the integer 0), other numbers by nlohmann's own to_chars
///   (shortest round trip, 1.0 keeps ".0", exponents as "1e+20");
/// - strings with '"', '\\' and the control characters escaped as dump() escapes them
///   (\b \t \n \f \r, others \u00xx), every other byte as it is (the tape holds valid UTF-8).

#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <simdjson.h>

#include "io/json/json_limits.hpp"
#include "io/sections/section_reader.hpp"

namespace saasgaps::io {

/// A number as nlohmann's dump() writes it.
void append_number(std::string& out, const Number& n);

/// Writes dumps into `sink` (called with pieces of at most about 64 KiB), so that a dump of a
/// large section is never held whole.
class TapeDump {
 public:
  using Sink = std::function<void(std::string_view)>;
  explicit TapeDump(Sink sink) : sink_(std::move(sink)) {
    buffer_.reserve(capacity + 4096);
    members_.resize(max_json_depth + 1);  // never reallocated, so a level's list stays in place
  }

  /// The dump of `value` (nesting bounded by the parser's max_depth).
  void value(simdjson::dom::element value);
  /// Hands what is buffered to the sink.
  void flush();

 private:
  static constexpr std::size_t capacity = 64 * 1024;
  void string(std::string_view text);
  void object(simdjson::dom::object members, std::size_t depth);
  void value(simdjson::dom::element value, std::size_t depth);

  Sink sink_;
  std::string buffer_;
  /// Per depth, the members of the object being written (reused: a model has an object per item).
  std::vector<std::vector<std::pair<std::string_view, simdjson::dom::element>>> members_;
};

}  // namespace saasgaps::io
