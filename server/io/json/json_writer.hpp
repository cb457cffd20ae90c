#pragma once
/// A streaming JSON writer: values go out as they are given, through a 64 KiB buffer, to a sink;
/// nothing of the document is kept. Used for result documents, which at 10^6 unknowns are hundreds
/// of megabytes as text and several times that as a tree.
///
/// The text is laid out as nlohmann::json::dump() lays out the same values, so documents written
/// either way read back the same:
/// - doubles as the shortest decimal that reads back to the same double (std::to_chars; nlohmann's
///   Grisu2 sometimes prints a longer one of the same double), laid out like nlohmann's dump (1.0
///   keeps its ".0"; fixed notation for decimal exponents -4 < n <= 15, else 1e-05, 1.5e+16),
///   non-finite doubles as null (JSON has no inf or nan);
/// - strings with '"', '\\' and control characters escaped; invalid UTF-8 replaced by U+FFFD;
/// - compact (no whitespace) by default; pretty: nlohmann's dump(2) layout, two spaces per level,
///   "key": value, empty arrays and objects as [] and {}.
///
/// Calls must nest correctly (key() before every value inside an object, never inside an array);
/// the writer asserts it. Sink failures (a full disk) surface as the sink's exceptions.

#include <cstdint>
#include <functional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace saasgaps::io {

class JsonWriter {
 public:
  /// Receives the text in pieces of up to the buffer size, in order.
  using Sink = std::function<void(std::string_view)>;

  explicit JsonWriter(Sink sink, bool pretty = false);
  JsonWriter(const JsonWriter&) = delete;
  JsonWriter& operator=(const JsonWriter&) = delete;

  JsonWriter& begin_object();
  JsonWriter& end_object();
  JsonWriter& begin_array();
  JsonWriter& end_array();
  /// The next member's name; the value follows with one of the value calls or begin_*.
  JsonWriter& key(std::string_view name);

  JsonWriter& value(double v);
  JsonWriter& value(int v) { return value(static_cast<std::int64_t>(v)); }
  JsonWriter& value(std::int64_t v);
  JsonWriter& value(std::uint64_t v);
  JsonWriter& value(bool v);
  JsonWriter& value(std::string_view text);
  JsonWriter& value(const char* text) { return value(std::string_view(text)); }
  JsonWriter& value(const std::string& text) { return value(std::string_view(text)); }
  JsonWriter& null();

  /// key(name).value(v)
  template <class T>
  JsonWriter& field(std::string_view name, const T& v) {
    key(name);
    return value(v);
  }
  /// An array of doubles.
  JsonWriter& value(const std::vector<double>& values);

  /// A writer that continues this one's text from inside the array it is writing, as if `before`
  /// items had been written into that array already: the same calls give the same text (the comma
  /// before an item, pretty indentation) as they would give here. For writing an array's items in
  /// pieces on other threads (io/parallel_items.hpp); put the pieces back with items().
  [[nodiscard]] JsonWriter continuation(Sink sink, std::size_t before) const;
  /// Appends the text a continuation() wrote for `count` items of the array being written, as is,
  /// through the sink in pieces of at most the buffer size.
  JsonWriter& items(std::string_view text, std::size_t count);

  /// Writes out what is buffered. Call once the document is complete (the destructor does not,
  /// so that a sink's failure is never swallowed).
  void flush();

  /// Bytes handed to the sink or buffered so far.
  [[nodiscard]] std::uint64_t bytes() const { return flushed_ + buffer_.size(); }

 private:
  /// Comma and (pretty) line break before a value or key at the current level.
  void separate();
  void open(char bracket);
  void close(char bracket);
  void put(std::string_view text) {
    buffer_.append(text);
    if (buffer_.size() >= buffer_limit) flush();
  }
  void put(char c) {
    buffer_.push_back(c);
    if (buffer_.size() >= buffer_limit) flush();
  }
  void put_string(std::string_view text);
  template <class Integer>
  JsonWriter& integer(Integer v);
  void newline_and_indent();

  static constexpr std::size_t buffer_limit = 1 << 16;

  struct Level {
    bool is_object = false;
    std::size_t items = 0;  ///< values (arrays) or members (objects) written
  };

  /// continuation()'s writer: at the given levels.
  JsonWriter(Sink sink, bool pretty, std::vector<Level> levels);

  Sink sink_;
  bool pretty_ = false;
  bool after_key_ = false;  ///< a key was written; its value comes next
  std::string buffer_;
  std::vector<Level> levels_;
  std::uint64_t flushed_ = 0;
};

/// A sink that appends to a string (for the service's database, and tests).
JsonWriter::Sink string_sink(std::string& out);
/// A sink that writes to a stream and throws std::ios_base::failure when the stream fails (a full
/// disk), so a writer stops at once.
JsonWriter::Sink stream_sink(std::ostream& out);

/// The JSON text of a double as JsonWriter writes it (and nlohmann's dump): "1.0", "0.001",
/// "1e-05", "null" for inf and nan.
std::string format_double(double v);

}  // namespace saasgaps::io
