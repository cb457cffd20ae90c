#include "io/json/json_writer.hpp"

#include <cassert>
#include <charconv>
#include <cmath>
#include <cstring>
#include <ios>

namespace saasgaps::io {

namespace {

/// nlohmann's layout of a decimal exponent: "+05", "-12", "+123".
char* append_exponent(char* p, int e) {
  *p++ = e < 0 ? '-' : '+';
  e = std::abs(e);
  if (e >= 100) {
    *p++ = static_cast<char>('0' + e / 100);
    e %= 100;
    *p++ = static_cast<char>('0' + e / 10);
    *p++ = static_cast<char>('0' + e % 10);
  } else {
    *p++ = static_cast<char>('0' + e / 10);
    *p++ = static_cast<char>('0' + e % 10);
  }
  return p;
}

/// A finite double into out (at least 32 chars); returns the end. The digits are std::to_chars'
/// shortest round trip; the layout is nlohmann's format_buffer with exponent limits -4 and 15
/// (printf %g-like, always with a '.' or an exponent so the number reads back as a double).
char* format_finite(double v, char* out) {
  char* p = out;
  if (std::signbit(v)) {
    *p++ = '-';
    v = -v;
  }
  if (v == 0.0) {
    std::memcpy(p, "0.0", 3);
    return p + 3;
  }
  char sci[40];
  const auto [end, ec] = std::to_chars(sci, sci + sizeof sci, v, std::chars_format::scientific);
  assert(ec == std::errc());
  // sci is "d[.ddd]e[+-]XX": the significant digits, then the exponent of the first one.
  char digits[24];
  int k = 0;
  const char* s = sci;
  digits[k++] = *s++;
  if (*s == '.') {
    for (++s; *s != 'e'; ++s) digits[k++] = *s;
  }
  ++s;  // 'e'
  const bool negative_exponent = *s == '-';
  ++s;  // sign
  int exponent = 0;
  std::from_chars(s, end, exponent);
  if (negative_exponent) exponent = -exponent;
  const int n = exponent + 1;  // position of the decimal point relative to the first digit
  constexpr int min_exp = -4;
  constexpr int max_exp = 15;
  if (k <= n && n <= max_exp) {  // digits[000].0
    std::memcpy(p, digits, static_cast<std::size_t>(k));
    p += k;
    std::memset(p, '0', static_cast<std::size_t>(n - k));
    p += n - k;
    *p++ = '.';
    *p++ = '0';
    return p;
  }
  if (0 < n && n <= max_exp) {  // dig.its
    std::memcpy(p, digits, static_cast<std::size_t>(n));
    p += n;
    *p++ = '.';
    std::memcpy(p, digits + n, static_cast<std::size_t>(k - n));
    return p + (k - n);
  }
  if (min_exp < n && n <= 0) {  // 0.[000]digits
    *p++ = '0';
    *p++ = '.';
    std::memset(p, '0', static_cast<std::size_t>(-n));
    p += -n;
    std::memcpy(p, digits, static_cast<std::size_t>(k));
    return p + k;
  }
  *p++ = digits[0];  // d[.igits]e+XX
  if (k > 1) {
    *p++ = '.';
    std::memcpy(p, digits + 1, static_cast<std::size_t>(k - 1));
    p += k - 1;
  }
  *p++ = 'e';
  return append_exponent(p, n - 1);
}

/// Length of the valid UTF-8 sequence at text[i], or 0 when it is not one (overlong forms,
/// surrogates and code points above U+10FFFF are invalid, as in RFC 3629).
std::size_t utf8_sequence(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t j) { return static_cast<unsigned char>(text[j]); };
  const unsigned char c = byte(i);
  std::size_t length = 0;
  unsigned char low = 0x80;
  unsigned char high = 0xBF;  // allowed range of the second byte
  if (c >= 0xC2 && c <= 0xDF) {
    length = 2;
  } else if (c >= 0xE0 && c <= 0xEF) {
    length = 3;
    if (c == 0xE0) low = 0xA0;
    if (c == 0xED) high = 0x9F;
  } else if (c >= 0xF0 && c <= 0xF4) {
    length = 4;
    if (c == 0xF0) low = 0x90;
    if (c == 0xF4) high = 0x8F;
  } else {
    return 0;
  }
  if (i + length > text.size()) return 0;
  if (byte(i + 1) < low || byte(i + 1) > high) return 0;
  for (std::size_t j = 2; j < length; ++j) {
    if ((byte(i + j) & 0xC0) != 0x80) return 0;
  }
  return length;
}

}  // namespace

std::string format_double(double v) {
  if (!std::isfinite(v)) return "null";
  char text[40];
  return std::string(text, format_finite(v, text));
}

JsonWriter::JsonWriter(Sink sink, bool pretty) : sink_(std::move(sink)), pretty_(pretty) {
  buffer_.reserve(buffer_limit + 256);
}

JsonWriter::JsonWriter(Sink sink, bool pretty, std::vector<Level> levels) : JsonWriter(std::move(sink), pretty) {
  levels_ = std::move(levels);
}

JsonWriter JsonWriter::continuation(Sink sink, std::size_t before) const {
  assert(!levels_.empty() && !levels_.back().is_object && !after_key_ && "continuation() inside an array only");
  std::vector<Level> levels = levels_;
  levels.back().items = before;
  return JsonWriter(std::move(sink), pretty_, std::move(levels));
}

JsonWriter& JsonWriter::items(std::string_view text, std::size_t count) {
  assert(!levels_.empty() && !levels_.back().is_object && !after_key_);
  // A piece is usually larger than the buffer: it goes to the sink directly, in the sink's sizes.
  flush();
  for (std::size_t at = 0; at < text.size(); at += buffer_limit) {
    const std::string_view part = text.substr(at, buffer_limit);
    sink_(part);
    flushed_ += part.size();
  }
  levels_.back().items += count;
  return *this;
}

void JsonWriter::flush() {
  if (buffer_.empty()) return;
  sink_(buffer_);
  flushed_ += buffer_.size();
  buffer_.clear();
}

void JsonWriter::newline_and_indent() {
  put('\n');
  for (std::size_t i = 0; i < levels_.size(); ++i) put("  ");
}

void JsonWriter::separate() {
  if (after_key_) {  // the value of a member: its key has placed it
    after_key_ = false;
    return;
  }
  if (levels_.empty()) return;
  Level& level = levels_.back();
  assert(!level.is_object && "a value inside an object needs a key");
  if (level.items++ > 0) put(',');
  if (pretty_) newline_and_indent();
}

void JsonWriter::open(char bracket) {
  separate();
  put(bracket);
  levels_.push_back(Level{bracket == '{', 0});
}

void JsonWriter::close(char bracket) {
  assert(!levels_.empty() && levels_.back().is_object == (bracket == '}') && !after_key_);
  const bool empty = levels_.back().items == 0;
  levels_.pop_back();
  if (pretty_ && !empty) newline_and_indent();
  put(bracket);
}

JsonWriter& JsonWriter::begin_object() {
  open('{');
  return *this;
}
JsonWriter& JsonWriter::end_object() {
  close('}');
  return *this;
}
JsonWriter& JsonWriter::begin_array() {
  open('[');
  return *this;
}
JsonWriter& JsonWriter::end_array() {
  close(']');
  return *this;
}

JsonWriter& JsonWriter::key(std::string_view name) {
  assert(!levels_.empty() && levels_.back().is_object && !after_key_);
  Level& level = levels_.back();
  if (level.items++ > 0) put(',');
  if (pretty_) newline_and_indent();
  put_string(name);
  put(pretty_ ? std::string_view(": ") : std::string_view(":"));
  after_key_ = true;
  return *this;
}

JsonWriter& JsonWriter::value(double v) {
  separate();
  if (!std::isfinite(v)) {
    put("null");
    return *this;
  }
  char text[40];
  put(std::string_view(text, static_cast<std::size_t>(format_finite(v, text) - text)));
  return *this;
}

template <class Integer>
JsonWriter& JsonWriter::integer(Integer v) {
  separate();
  char text[24];
  const auto [end, ec] = std::to_chars(text, text + sizeof text, v);
  put(std::string_view(text, static_cast<std::size_t>(end - text)));
  return *this;
}

JsonWriter& JsonWriter::value(std::int64_t v) { return integer(v); }
JsonWriter& JsonWriter::value(std::uint64_t v) { return integer(v); }

JsonWriter& JsonWriter::value(bool v) {
  separate();
  put(v ? std::string_view("true") : std::string_view("false"));
  return *this;
}

JsonWriter& JsonWriter::value(std::string_view text) {
  separate();
  put_string(text);
  return *this;
}

JsonWriter& JsonWriter::null() {
  separate();
  put("null");
  return *this;
}

JsonWriter& JsonWriter::value(const std::vector<double>& values) {
  begin_array();
  for (const double v : values) value(v);
  return end_array();
}

void JsonWriter::put_string(std::string_view text) {
  static constexpr char hex[] = "0123456789abcdef";
  put('"');
  std::size_t run = 0;  // start of the bytes that go out unchanged
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c != '"' && c != '\\' && c < 0x80) {
      ++i;
      continue;
    }
    if (c >= 0x80) {
      if (const std::size_t length = utf8_sequence(text, i)) {
        i += length;
        continue;
      }
    }
    put(text.substr(run, i - run));
    switch (c) {
      case '"': put("\\\""); break;
      case '\\': put("\\\\"); break;
      case '\b': put("\\b"); break;
      case '\f': put("\\f"); break;
      case '\n': put("\\n"); break;
      case '\r': put("\\r"); break;
      case '\t': put("\\t"); break;
      default:
        if (c < 0x20) {
          const char escaped[6] = {'\\', 'u', '0', '0', hex[c >> 4], hex[c & 0xF]};
          put(std::string_view(escaped, 6));
        } else {
          put("\xEF\xBF\xBD");  // U+FFFD for a byte that starts no valid UTF-8 sequence
        }
    }
    run = ++i;
  }
  put(text.substr(run));
  put('"');
}

JsonWriter::Sink string_sink(std::string& out) {
  return [&out](std::string_view text) { out.append(text); };
}

JsonWriter::Sink stream_sink(std::ostream& out) {
  return [&out](std::string_view text) {
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    if (!out) throw std::ios_base::failure("writing the document failed");
  };
}

}  // namespace saasgaps::io
