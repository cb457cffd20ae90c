#include "io/model/json_scan.hpp"

#include <array>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <limits>
#include <system_error>

namespace saasgaps::io {

namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

/// What ends a scalar: whitespace or the structure after a value.
bool is_delimiter(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == ',' || c == ']' || c == '}';
}

/// Clinger's fast path: a decimal whose digits make an integer m <= 2^53 and whose power of ten e
/// is within +-22 is m * 10^e or m / 10^-e with both operands exact, so one correctly rounded
/// operation gives the correctly rounded value (the double strtod gives). Most numbers of a model
/// are such (1.0, 400.0, 1.003125); false for the others, which from_chars reads.
bool exact_decimal(const char* digits, const char* digits_end, const char* fraction, const char* fraction_end,
                   const char* exponent, const char* end, bool negative, double& value) {
  static constexpr std::array<double, 23> powers{1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                                 1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                                 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  if ((digits_end - digits) + (fraction_end - fraction) > 19) return false;
  std::uint64_t m = 0;
  for (const char* d = digits; d != digits_end; ++d) m = m * 10 + static_cast<std::uint64_t>(*d - '0');
  for (const char* d = fraction; d != fraction_end; ++d) m = m * 10 + static_cast<std::uint64_t>(*d - '0');
  if (m > (std::uint64_t{1} << 53)) return false;
  long e = -(fraction_end - fraction);
  if (exponent != end) {
    const bool minus = *exponent == '-';
    const char* d = exponent + ((*exponent == '-' || *exponent == '+') ? 1 : 0);
    if (end - d > 3) return false;  // beyond the fast path's range whatever the digits
    long x = 0;
    for (; d != end; ++d) x = x * 10 + (*d - '0');
    e += minus ? -x : x;
  }
  if (e < -22 || e > 22) return false;
  const double magnitude = e < 0 ? static_cast<double>(m) / powers[static_cast<std::size_t>(-e)]
                                 : static_cast<double>(m) * powers[static_cast<std::size_t>(e)];
  value = negative ? -magnitude : magnitude;
  return true;
}

}  // namespace

bool JsonScan::key(std::string_view& k) {
  if (!consume('"')) return false;
  const char* begin = p_;
  while (p_ != end_ && *p_ != '"') {
    // Printable ASCII only: no escape, no control character, nothing that needs UTF-8 checks.
    if (*p_ == '\\' || static_cast<unsigned char>(*p_) < 0x20 || static_cast<unsigned char>(*p_) > 0x7E) return false;
    ++p_;
  }
  if (p_ == end_) return false;
  k = std::string_view(begin, static_cast<std::size_t>(p_ - begin));
  ++p_;
  return consume(':');
}

bool JsonScan::number(Number& n) {
  skip_ws();
  const char* begin = p_;
  const char* p = p_;
  const bool negative = p != end_ && *p == '-';
  if (negative) ++p;
  if (p == end_ || !is_digit(*p)) return false;
  const char* digits = p;
  if (*p == '0') {
    ++p;
  } else {
    while (p != end_ && is_digit(*p)) ++p;
  }
  const char* digits_end = p;
  bool integral = true;
  const char* fraction = p;  // its digits, when there is a fraction
  const char* fraction_end = p;
  if (p != end_ && *p == '.') {
    ++p;
    if (p == end_ || !is_digit(*p)) return false;
    fraction = p;
    while (p != end_ && is_digit(*p)) ++p;
    fraction_end = p;
    integral = false;
  }
  const char* exponent = p;  // its sign and digits, when there is an exponent
  if (p != end_ && (*p == 'e' || *p == 'E')) {
    ++p;
    exponent = p;
    if (p != end_ && (*p == '+' || *p == '-')) ++p;
    if (p == end_ || !is_digit(*p)) return false;
    while (p != end_ && is_digit(*p)) ++p;
    integral = false;
  }
  if (integral) {
    // Integers beyond 64 bits are left to the reporting path (nlohmann reads them as doubles).
    if (digits_end - digits > 20) return false;
    std::uint64_t value = 0;
    for (const char* d = digits; d != digits_end; ++d) {
      if (__builtin_mul_overflow(value, 10U, &value) ||
          __builtin_add_overflow(value, static_cast<std::uint64_t>(*d - '0'), &value)) {
        return false;
      }
    }
    if (negative) {
      // "-0" is an integer to nlohmann and a double to simdjson: the reporting path decides.
      if (value == 0 || value > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) return false;
      n.kind = Number::Kind::signed_integer;
      n.integer = -static_cast<std::int64_t>(value);
    } else {
      n.kind = Number::Kind::unsigned_integer;
      n.unsigned_ = value;
    }
  } else {
    double value = 0.0;
    if (!exact_decimal(digits, digits_end, fraction, fraction_end, exponent, p, negative, value)) {
      // The span is JSON's number grammar, which from_chars reads (correctly rounded, as strtod).
      const auto [end, error] = std::from_chars(begin, p, value);
      if (error != std::errc() || end != p) return false;  // out of a double's range: reported elsewhere
    }
    n.kind = Number::Kind::floating;
    n.floating = value;
  }
  p_ = p;
  return true;
}

bool JsonScan::skip_string() {
  ++p_;  // the opening quote
  while (true) {
    const auto* quote = static_cast<const char*>(std::memchr(p_, '"', static_cast<std::size_t>(end_ - p_)));
    if (quote == nullptr) return false;
    // A quote preceded by an odd number of backslashes is escaped.
    std::size_t backslashes = 0;
    for (const char* b = quote; b != p_ && *(b - 1) == '\\'; --b) ++backslashes;
    p_ = quote + 1;
    if (backslashes % 2 == 0) return true;
  }
}

bool JsonScan::skip_value(std::string_view& span, std::size_t max_depth) {
  skip_ws();
  const char* begin = p_;
  if (p_ == end_) return false;
  if (*p_ == '"') {
    if (!skip_string()) return false;
  } else if (*p_ == '[' || *p_ == '{') {
    std::size_t depth = 0;
    do {
      const char c = *p_;
      if (c == '"') {
        if (!skip_string()) return false;
        continue;
      }
      if (c == '[' || c == '{') {
        if (++depth > max_depth) return false;
      } else if (c == ']' || c == '}') {
        --depth;
      }
      ++p_;
    } while (depth > 0 && p_ != end_);
    if (depth > 0) return false;
  } else {
    while (p_ != end_ && !is_delimiter(*p_)) ++p_;
  }
  span = std::string_view(begin, static_cast<std::size_t>(p_ - begin));
  return true;
}

}  // namespace saasgaps::io
