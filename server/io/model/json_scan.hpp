#pragma once
/// A strict cursor over JSON text (RFC 8259) for the model reader's fast path (internal to io/).
/// Each step either consumes exactly the grammar it names and returns true, or returns false and
/// the caller gives up (the reader then reads the text with the reporting path, which words the
/// issue). It reads in place: no copy of the text, no index, no tape, so the only memory a read
/// touches is the Model's.
///
/// What it reads itself is a small subset of JSON, the shape of a model's large arrays: keys of
/// printable ASCII without escapes, numbers (the JSON grammar, converted as nlohmann's parser
/// converts them: an integer without a sign unsigned, with a minus signed, anything with a fraction
/// or an exponent a correctly rounded double), and the structure between them. Anything else (a
/// string value, an escape, an integer beyond 64 bits, a number beyond the range of a double, "-0")
/// is a false. skip_value finds where any value ends without judging it: the caller hands that
/// span to a real parser.

#include <array>
#include <cstddef>
#include <string_view>

#include "io/sections/section_reader.hpp"

namespace saasgaps::io {

class JsonScan {
 public:
  explicit JsonScan(std::string_view text) : p_(text.data()), end_(text.data() + text.size()) {}

  /// Skips JSON whitespace (space, tab, line feed, carriage return).
  void skip_ws() {
    while (p_ != end_ && (*p_ == ' ' || *p_ == '\n' || *p_ == '\r' || *p_ == '\t')) ++p_;
  }
  /// After whitespace, the character c.
  bool consume(char c) {
    skip_ws();
    if (p_ == end_ || *p_ != c) return false;
    ++p_;
    return true;
  }
  /// After whitespace, the next character is c (not consumed).
  bool next_is(char c) {
    skip_ws();
    return p_ != end_ && *p_ == c;
  }
  /// After whitespace, a key (a string of printable ASCII without escapes) and its ':'.
  bool key(std::string_view& k);
  /// After whitespace, a number.
  bool number(Number& n);
  /// After whitespace, a whole value of any kind, unjudged: its span. Strings are skipped with
  /// their escapes, containers by counting brackets (false when they open deeper than max_depth
  /// levels below this one or do not close before the text ends), scalars up to the next
  /// delimiter. Whether the span is JSON is for a parser to say.
  bool skip_value(std::string_view& span, std::size_t max_depth);
  /// Only whitespace is left.
  bool at_end() {
    skip_ws();
    return p_ == end_;
  }
  [[nodiscard]] const char* position() const { return p_; }

 private:
  bool skip_string();
  const char* p_;
  const char* end_;
};

/// The members of an object, each key one of `keys` (a bit each in `seen`) and none repeated;
/// `each(index)` reads the value after the key and returns false to refuse the object.
template <std::size_t N, class Each>
bool scan_members(JsonScan& scan, const std::array<std::string_view, N>& keys, unsigned& seen, Each each) {
  if (!scan.consume('{')) return false;
  seen = 0;
  if (scan.consume('}')) return true;
  do {
    std::string_view key;
    if (!scan.key(key)) return false;
    std::size_t k = 0;
    while (k < N && keys[k] != key) ++k;
    if (k == N || (seen & (1U << k)) != 0) return false;
    seen |= 1U << k;
    if (!each(k)) return false;
  } while (scan.consume(','));
  return scan.consume('}');
}

/// The items of an array: `each()` reads one item and returns false to refuse the array.
template <class Each>
bool scan_items(JsonScan& scan, Each each) {
  if (!scan.consume('[')) return false;
  if (scan.consume(']')) return true;
  do {
    if (!each()) return false;
  } while (scan.consume(','));
  return scan.consume(']');
}

}  // namespace saasgaps::io
