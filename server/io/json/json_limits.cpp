#include "io/json/json_limits.hpp"

#include <utility>

#include "io/json/json_pointer.hpp"
#include "io/json/tree_builder.hpp"

namespace saasgaps::io {

namespace {

using json = nlohmann::json;

/// The reference tokens of a pointer ("" has none), each with its leading "/".
std::vector<std::string_view> tokens(std::string_view pointer) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  while (start < pointer.size()) {
    const std::size_t end = pointer.find('/', start + 1);
    out.push_back(pointer.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
    start = end == std::string_view::npos ? pointer.size() : end;
  }
  return out;
}

std::string shown_token(std::string_view token) {
  constexpr std::size_t longest = 40, kept = 32;
  return token.size() <= longest ? std::string(token) : std::string(token.substr(0, kept)) + "...";
}

/// A SAX handler that checks syntax and nesting only.
class NestingCheck final : public json::json_sax_t {
 public:
  bool null() override { return scalar(); }
  bool boolean(bool) override { return scalar(); }
  bool number_integer(number_integer_t) override { return scalar(); }
  bool number_unsigned(number_unsigned_t) override { return scalar(); }
  bool number_float(number_float_t, const string_t&) override { return scalar(); }
  bool string(string_t&) override { return scalar(); }
  bool binary(binary_t&) override { return scalar(); }
  bool start_object(std::size_t) override { return open(true); }
  bool start_array(std::size_t) override { return open(false); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }
  bool key(string_t& name) override {
    path_.key(name);
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }

 private:
  bool scalar() {
    path_.next();
    return true;
  }
  bool open(bool is_object) {
    path_.open(is_object);
    return true;
  }
  bool close() {
    path_.close();
    return true;
  }

  JsonPath path_;
};

/// A SAX handler that builds the tree of a CBOR document within the nesting limit.
class LimitedTree final : public json::json_sax_t {
 public:
  LimitedTree() { tree_.begin(); }

  bool null() override { return scalar(nullptr); }
  bool boolean(bool v) override { return scalar(v); }
  bool number_integer(number_integer_t v) override { return scalar(v); }
  bool number_unsigned(number_unsigned_t v) override { return scalar(v); }
  bool number_float(number_float_t v, const string_t&) override { return scalar(v); }
  bool string(string_t& v) override { return scalar(std::move(v)); }
  bool binary(binary_t& v) override { return scalar(std::move(v)); }
  bool start_object(std::size_t) override { return open(json::object()); }
  bool start_array(std::size_t) override { return open(json::array()); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }
  bool key(string_t& name) override {
    path_.key(name);
    (void)tree_.key(name);  // a repeated key: the later value replaces the earlier, as in from_cbor
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) override {
    rethrow_parse_exception(e);
  }

  json take() { return tree_.take(); }

 private:
  template <class Value>
  bool scalar(Value&& v) {
    tree_.value(std::forward<Value>(v));
    path_.next();
    return true;
  }
  bool open(json container) {
    path_.open(container.is_object());  // throws before the decoder recurses any deeper
    tree_.start(std::move(container));
    return true;
  }
  bool close() {
    path_.close();
    tree_.end();
    return true;
  }

  JsonPath path_;
  TreeBuilder tree_;
};

}  // namespace

std::string shown_pointer(const std::string& pointer) {
  constexpr std::size_t longest = 160, head = 96, tail = 48;
  if (pointer.size() <= longest) return pointer;
  const std::vector<std::string_view> parts = tokens(pointer);
  std::string front, back;
  std::size_t first = 0;
  while (first < parts.size() && front.size() + shown_token(parts[first]).size() <= head) front += shown_token(parts[first++]);
  std::size_t last = parts.size();
  while (last > first && back.size() + shown_token(parts[last - 1]).size() <= tail) back = shown_token(parts[--last]) + back;
  // A token too long for either end is shown cut, so the pointer never shows nothing.
  if (first == 0 && last == parts.size()) front = shown_token(parts[first++]);
  if (first == last) return front + back;
  return front + "/..." + back;
}

void JsonPath::open(bool is_object) {
  if (frames_.size() >= max_json_depth) {
    throw NestingTooDeep({{shown_pointer(pointer()), "arrays and objects nest deeper than " +
                                                         std::to_string(max_json_depth) +
                                                         " levels here; SAASGAPS models and assemblies need 5"}});
  }
  frames_.push_back(Frame{is_object, {}, 0});
}

void JsonPath::close() {
  frames_.pop_back();
  next();
}

void JsonPath::start_at_member(std::string name) { frames_.assign(1, Frame{true, std::move(name), 0}); }

std::string JsonPath::pointer() const {
  std::string text;
  for (const Frame& f : frames_) text = f.is_object ? pointer_append(text, f.key) : pointer_append(text, f.index);
  return text;
}

void rethrow_parse_exception(const nlohmann::detail::exception& e) {
  if (const auto* p = dynamic_cast<const json::parse_error*>(&e)) throw *p;
  if (const auto* r = dynamic_cast<const json::out_of_range*>(&e)) throw *r;
  throw json::other_error::create(599, e.what(), nullptr);
}

bool accept_json(std::string_view text) {
  NestingCheck check;
  return json::sax_parse(text, &check);
}

json parse_cbor(std::span<const std::uint8_t> bytes) {
  LimitedTree tree;
  json::sax_parse(bytes.begin(), bytes.end(), &tree, json::input_format_t::cbor);
  return tree.take();
}

json parse_cbor(std::string_view bytes) {
  LimitedTree tree;
  json::sax_parse(bytes.begin(), bytes.end(), &tree, json::input_format_t::cbor);
  return tree.take();
}

}  // namespace saasgaps::io
