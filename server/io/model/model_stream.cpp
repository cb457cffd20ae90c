#include "io/model/model_stream.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cstddef>
#include <iterator>
#include <utility>

#include "io/json/json_limits.hpp"
#include "io/json/tree_builder.hpp"
#include "io/json/value_quote.hpp"
#include "io/model/model_digest.hpp"
#include "io/model/model_reader.hpp"

namespace saasgaps::io {

namespace {

/// A character iterator that mirrors its position into a shared cursor, so the SAX handler knows
/// how far the parser has read. At start_object / start_array the parser has consumed exactly the
/// opening bracket, at end_object / end_array exactly the closing one (its lexer reads one
/// character past a number or literal only, never past a bracket).
struct TrackedIterator {
  using iterator_category = std::input_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  const char* at = nullptr;
  const char** cursor = nullptr;

  reference operator*() const { return *at; }
  TrackedIterator& operator++() {
    *cursor = ++at;
    return *this;
  }
  TrackedIterator operator++(int) {
    TrackedIterator before = *this;
    ++*this;
    return before;
  }
  bool operator==(const TrackedIterator& other) const { return at == other.at; }
};

/// nlohmann's what() starts with "[json.exception.parse_error.101] "; the user needs the rest.
std::string without_exception_tag(const char* what) {
  std::string text = what;
  if (const auto end = text.find("] "); text.starts_with("[json.exception.") && end != std::string::npos) {
    text.erase(0, end + 2);
  }
  return text;
}

/// The SAX handler. Depth = open containers (path_.depth()): 1 inside the root object, so its
/// members' values start at depth 1; items of a streamed array at depth 2.
class ModelStream final : public json::json_sax_t {
 public:
  enum class Mode {
    model,  ///< judge sections as they come (stream_model)
    tree,   ///< build the whole document (parse_tree)
  };

  ModelStream(Mode mode, SectionReader* reader, bool digest) : mode_(mode), reader_(reader), digest_(digest) {}

  /// Parses text (the whole document, or the kept span of `section`).
  bool run(std::string_view text, std::optional<Section> section = std::nullopt) {
    base_ = text.data();
    cursor_ = base_;
    if (section) {
      // A kept span is the value of one member of the root: pretend the root is open at its key.
      path_.start_at_member(std::string(section_key(*section)));
      root_is_object_ = true;
      section_ = *section;
      target_ = streams_items(*section) ? Target::items : Target::whole;
    }
    TrackedIterator first{text.data(), &cursor_};
    TrackedIterator last{text.data() + text.size(), &cursor_};
    return json::sax_parse(first, last, this);
  }

  // ---- SAX events
  bool null() override { return scalar(nullptr); }
  bool boolean(bool v) override { return scalar(v); }
  bool number_integer(json::number_integer_t v) override { return scalar(v); }
  bool number_unsigned(json::number_unsigned_t v) override { return scalar(v); }
  bool number_float(json::number_float_t v, const json::string_t&) override { return scalar(v); }
  bool string(json::string_t& v) override { return scalar(std::move(v)); }
  bool binary(json::binary_t&) override { return scalar(nullptr); }  // JSON text has none
  bool start_object(std::size_t) override { return open(true); }
  bool start_array(std::size_t) override { return open(false); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }

  bool key(json::string_t& name) override {
    path_.key(name);
    if (builder_.active()) {
      if (!builder_.key(name)) repeated_here();
      return true;
    }
    if (path_.depth() == 1 && mode_ == Mode::model) root_member(name);
    return true;
  }

  bool parse_error(std::size_t byte, const std::string&, const nlohmann::detail::exception& e) override {
    // A number beyond the range of a double (out_of_range.406, e.g. 1e400) stops the parser inside
    // the value the handler is at; anything else is text that is not JSON.
    not_json_ = e.id != 406;
    if (e.id == 406) {
      error_ = InputIssue{pointer(), without_exception_tag(e.what()) +
                                         "; numbers must be finite and within the range of a double"};
    } else {
      error_ = InputIssue{"", "the document is not valid JSON: " + without_exception_tag(e.what()) + " (byte " +
                                  std::to_string(byte) + ")"};
    }
    return false;
  }

  // ---- results
  [[nodiscard]] const std::optional<InputIssue>& error() const { return error_; }
  /// Throws the parse error: NotJsonText for a syntax error, ModelError for a number out of range.
  [[noreturn]] void throw_error() const {
    if (not_json_) throw NotJsonText({*error_});
    throw ModelError({*error_});
  }
  std::vector<InputIssue>& repeated_keys() { return repeated_; }
  json take_tree() { return std::move(tree_); }

  /// After the pass over the whole text: the kept spans (in dependency order), the absent sections,
  /// the root's required keys, and the digest.
  void finish(std::string_view text, std::string* digest) {
    if (!root_is_object_) {
      // Not an object: the tree reader says so (and nothing else applies).
      for (InputIssue& issue : repeated_) reader_->repeated_key(std::move(issue.pointer), std::move(issue.detail));
      (void)reader_->read(tree_);  // throws ModelError: the document is not an object
      return;
    }
    for (std::size_t k = 0; k < section_count; ++k) {
      const auto s = static_cast<Section>(k);
      if (done_[k]) continue;
      if (kept_scalar_[k]) {
        if (digest_) dumps_[k] = kept_trees_[k].dump();
        reader_->read_section(s, &kept_trees_[k]);
      } else if (kept_[k].second > kept_[k].first) {
        // Every section it depends on is done by now (they come earlier in Section order).
        ModelStream again(Mode::model, reader_, digest_);
        const bool parsed = again.run(text.substr(kept_[k].first, kept_[k].second - kept_[k].first), s);
        assert(parsed && "a span that parsed once parses again");
        (void)parsed;
        for (InputIssue& issue : again.repeated_) repeated_.push_back(std::move(issue));
        dumps_[k] = std::move(again.dumps_[k]);
      } else {
        reader_->read_section(s, nullptr);
      }
      done_[k] = true;
    }
    reader_->check_required_root_keys(present_);
    for (InputIssue& issue : repeated_) reader_->repeated_key(std::move(issue.pointer), std::move(issue.detail));
    if (digest != nullptr) {
      *digest = model_fingerprint(present_, [&](Section s, Fingerprint& f) { f.add(dumps_[static_cast<std::size_t>(s)]); });
    }
  }

 private:
  /// What happens to the value of the root member being read.
  enum class Target {
    none,   ///< nothing yet / an unknown or repeated key: built and dropped
    whole,  ///< built whole, then read_section
    items,  ///< a streamed array: each item built and read_item
    keep,   ///< skipped, its span kept for later
  };

  [[nodiscard]] std::string pointer() const { return path_.pointer(); }

  void repeated_here() {
    repeated_.push_back(InputIssue{pointer(), repeated_key_detail(path_.top().key)});
  }

  /// A key of the root object: which section, and whether it can be read now.
  void root_member(const std::string& name) {
    target_ = Target::none;
    const auto s = section_of(name);
    if (!s) {
      reader_->unknown_root_key(name);
      return;
    }
    const auto k = static_cast<std::size_t>(*s);
    if (present_[k]) {
      repeated_here();
      return;
    }
    present_[k] = true;
    section_ = *s;
    bool ready = true;
    for (const Section d : dependencies(*s)) ready = ready && done_[static_cast<std::size_t>(d)];
    target_ = !ready ? Target::keep : streams_items(*s) ? Target::items : Target::whole;
  }

  /// A value starts at depth 1 (a root member's value) with this first event.
  void begin_member_value(bool container, bool is_object) {
    if (target_ == Target::keep && container) {
      keep_from_ = static_cast<std::size_t>(cursor_ - base_) - 1;
      return;
    }
    if (target_ == Target::items && container && !is_object) {
      reader_->begin_items(section_);
      if (digest_) dumps_[static_cast<std::size_t>(section_)] = "[";
      streaming_ = true;
      return;
    }
    // Anything else is built whole: a section read at once, a scalar of a kept section (read
    // later from the tree), a streamed section that is no array, an unknown key's value.
    if (target_ == Target::items) target_ = Target::whole;
    builder_.begin();
  }

  template <class Value>
  bool scalar(Value&& v) {
    if (builder_.active()) {
      builder_.value(std::forward<Value>(v));
      if (builder_.complete()) built();
    } else if (path_.depth() == 0) {  // the whole document is a scalar
      builder_.begin();
      builder_.value(std::forward<Value>(v));
      built();
    } else if (streaming_ && path_.depth() == 2) {  // a scalar item of a streamed array
      builder_.begin();
      builder_.value(std::forward<Value>(v));
      built();
    } else if (path_.depth() == 1 && mode_ == Mode::model) {
      begin_member_value(false, false);
      builder_.value(std::forward<Value>(v));
      built();
    }
    path_.next();
    return true;
  }

  bool open(bool is_object) {
    // Throws NestingTooDeep one level past the limit, before anything is built.
    const std::size_t depth = path_.depth();
    path_.open(is_object);
    if (builder_.active()) {
      builder_.start(is_object ? json::object() : json::array());
    } else if (depth == 0) {
      if (is_object && mode_ == Mode::model) {
        root_is_object_ = true;
      } else {  // the document itself is built
        builder_.begin();
        builder_.start(is_object ? json::object() : json::array());
      }
    } else if (streaming_ && depth == 2) {
      builder_.begin();
      builder_.start(is_object ? json::object() : json::array());
    } else if (depth == 1 && !streaming_) {
      begin_member_value(true, is_object);
      if (builder_.active()) builder_.start(is_object ? json::object() : json::array());
    }
    return true;
  }

  bool close() {
    path_.close();
    if (builder_.active()) {
      builder_.end();
      if (builder_.complete()) built();
    } else if (streaming_ && path_.depth() == 1) {  // the streamed array ends
      streaming_ = false;
      const auto k = static_cast<std::size_t>(section_);
      if (digest_) dumps_[k] += "]";
      reader_->end_items(section_, items_);
      items_ = 0;
      done_[k] = true;
    } else if (target_ == Target::keep && path_.depth() == 1) {
      kept_[static_cast<std::size_t>(section_)] = {keep_from_, static_cast<std::size_t>(cursor_ - base_)};
      target_ = Target::none;
    }
    return true;
  }

  /// A value that the builder started is complete: deliver it.
  void built() {
    json value = builder_.take();
    if (path_.depth() == 0 || mode_ == Mode::tree) {
      tree_ = std::move(value);
      return;
    }
    const auto k = static_cast<std::size_t>(section_);
    if (streaming_) {
      if (digest_) {
        if (items_ > 0) dumps_[k] += ',';
        dumps_[k] += value.dump();
      }
      reader_->read_item(section_, value, items_++);
      return;
    }
    if (target_ == Target::whole) {
      if (digest_) dumps_[k] = value.dump();
      reader_->read_section(section_, &value);
      done_[k] = true;
    } else if (target_ == Target::keep) {  // a scalar: kept as a tree, tiny
      kept_trees_[k] = std::move(value);
      kept_scalar_[k] = true;
    }
    target_ = Target::none;
  }

 private:
  Mode mode_;
  SectionReader* reader_;
  bool digest_;
  const char* base_ = nullptr;
  const char* cursor_ = nullptr;

  JsonPath path_;
  TreeBuilder builder_;
  json tree_;
  std::optional<InputIssue> error_;
  bool not_json_ = false;
  std::vector<InputIssue> repeated_;

  bool root_is_object_ = false;
  Target target_ = Target::none;
  Section section_ = Section::schema_version;  ///< of the root member being read
  bool streaming_ = false;
  std::size_t items_ = 0;
  std::size_t keep_from_ = 0;
  std::array<bool, section_count> present_{};
  std::array<bool, section_count> done_{};
  std::array<std::pair<std::size_t, std::size_t>, section_count> kept_{};
  std::array<json, section_count> kept_trees_{};
  std::array<bool, section_count> kept_scalar_{};
  std::array<std::string, section_count> dumps_{};
};

}  // namespace

std::string repeated_key_detail(std::string_view key) {
  return "key " + quote_string(key) +
         " appears more than once in this object; a JSON reader keeps only one of the values, so give each key once";
}

std::string model_fingerprint(const std::array<bool, section_count>& present,
                              const std::function<void(Section, Fingerprint&)>& add) {
  std::array<std::size_t, section_count> order{};
  for (std::size_t k = 0; k < section_count; ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [](std::size_t a, std::size_t b) {
    return section_key(static_cast<Section>(a)) < section_key(static_cast<Section>(b));
  });
  Fingerprint f;
  f.add("{");
  bool first = true;
  for (const std::size_t k : order) {
    const auto s = static_cast<Section>(k);
    if (!present[k] || s == Section::title || s == Section::description || s == Section::output) continue;
    f.add(first ? "\"" : ",\"");
    first = false;
    f.add(section_key(s));
    f.add("\":");
    add(s, f);
  }
  f.add("}");
  return f.hex();
}

void stream_model(std::string_view text, SectionReader& reader, std::string* digest) {
  ModelStream stream(ModelStream::Mode::model, &reader, digest != nullptr);
  if (!stream.run(text)) stream.throw_error();
  stream.finish(text, digest);
}

json parse_tree(std::string_view text) {
  ModelStream stream(ModelStream::Mode::tree, nullptr, false);
  if (!stream.run(text)) stream.throw_error();
  if (!stream.repeated_keys().empty()) throw ModelError(std::move(stream.repeated_keys()));
  return stream.take_tree();
}

}  // namespace saasgaps::io
