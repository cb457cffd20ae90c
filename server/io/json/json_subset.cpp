#include "io/json/json_subset.hpp"

#include <cstddef>
#include <string>
#include <utility>

#include "io/json/json_limits.hpp"
#include "io/json/tree_builder.hpp"

namespace saasgaps::io {

namespace {

using json = nlohmann::json;

/// Feeds a TreeBuilder the SAX events of the members the filter keeps; a rejected member's value
/// (and everything inside it) is skipped.
class SubsetBuilder final : public json::json_sax_t {
 public:
  explicit SubsetBuilder(const MemberFilter& keep) : keep_(keep) { tree_.begin(); }

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
    if (skipped_ > 0) return true;
    // The object holding this key is the innermost open container: its depth is depth_.
    if (depth_ == 1) section_ = name;
    if (keep_ && !keep_(depth_, depth_ == 1 ? std::string_view() : std::string_view(section_), name)) {
      skip_next_ = true;
      return true;
    }
    (void)tree_.key(name);  // a repeated key: the later value replaces the earlier, as in nlohmann's parser
    return true;
  }

  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) override {
    rethrow_parse_exception(e);  // what nlohmann::json::parse would have thrown
  }

  json take() { return tree_.take(); }

 private:
  template <class Value>
  bool scalar(Value&& v) {
    path_.next();
    if (skipped_ > 0) return true;
    if (skip_next_) {
      skip_next_ = false;
      return true;
    }
    tree_.value(std::forward<Value>(v));
    return true;
  }

  bool open(json container) {
    path_.open(container.is_object());  // skipped or not: the limit is the document's
    if (skipped_ > 0 || skip_next_) {
      skip_next_ = false;
      ++skipped_;
      return true;
    }
    tree_.start(std::move(container));
    ++depth_;
    return true;
  }

  bool close() {
    path_.close();
    if (skipped_ > 0) {
      --skipped_;
      return true;
    }
    tree_.end();
    --depth_;
    return true;
  }

  const MemberFilter& keep_;
  JsonPath path_;
  TreeBuilder tree_;
  int depth_ = 0;             // containers open in the tree
  std::string section_;       // the root member being read
  bool skip_next_ = false;    // the next value belongs to a rejected member
  int skipped_ = 0;           // depth inside a rejected container
};

}  // namespace

nlohmann::json parse_json_subset(std::string_view text, const MemberFilter& keep) {
  SubsetBuilder builder(keep);
  json::sax_parse(text, &builder);
  return builder.take();
}

}  // namespace saasgaps::io
