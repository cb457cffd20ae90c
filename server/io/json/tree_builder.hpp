#pragma once
/// A JSON tree built from SAX events (internal to io/): the model reader builds each item of a
/// model with it, parse_json_subset the members it keeps, read_result_arrays the small members of a
/// result (io/result_arrays.hpp).

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace saasgaps::io {

/// Builds a tree from SAX events, like nlohmann's own DOM parser, but reports a repeated key
/// (the later value replaces the earlier one, as nlohmann's parser does).
class TreeBuilder {
  using json = nlohmann::json;

 public:
  void begin() {
    root_ = json();
    stack_.clear();
    active_ = true;
  }
  [[nodiscard]] bool active() const { return active_; }

  template <class Value>
  void value(Value&& v) {
    place(json(std::forward<Value>(v)));
  }
  void start(json container) { stack_.push_back(place(std::move(container))); }
  /// False when the object already has this key.
  bool key(const std::string& name) {
    auto& members = stack_.back()->get_ref<json::object_t&>();
    const auto [it, fresh] = members.try_emplace(name);
    slot_ = &it->second;
    return fresh;
  }
  void end() { stack_.pop_back(); }
  /// True once the value that begin() started is complete.
  [[nodiscard]] bool complete() const { return active_ && stack_.empty(); }
  json take() {
    active_ = false;
    return std::move(root_);
  }

 private:
  json* place(json&& v) {
    if (stack_.empty()) {
      root_ = std::move(v);
      return &root_;
    }
    json& top = *stack_.back();
    if (top.is_array()) {
      top.get_ref<json::array_t&>().push_back(std::move(v));
      return &top.get_ref<json::array_t&>().back();
    }
    *slot_ = std::move(v);
    return slot_;
  }

  json root_;
  std::vector<json*> stack_;  // open containers; a parent only grows once its child has ended
  json* slot_ = nullptr;      // the member named by the last key
  bool active_ = false;
};

}  // namespace saasgaps::io
