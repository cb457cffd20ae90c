#include "io/mesher/geo_constants.hpp"

#include <algorithm>
#include <cctype>

namespace saasgaps::io {

namespace {

bool starts_name(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0 || c == '_'; }
bool in_name(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

/// Walks the text with comments and strings skipped.
class GeoScanner {
 public:
  explicit GeoScanner(std::string_view text) : text_(text) {}

  [[nodiscard]] bool done() {
    skip_blank();
    return at_ >= text_.size();
  }
  [[nodiscard]] char peek() {
    skip_blank();
    return at_ < text_.size() ? text_[at_] : '\0';
  }
  /// The next token: a name, a string (returned with its quotes), or one character.
  std::string_view next() {
    skip_blank();
    const std::size_t start = at_;
    if (at_ >= text_.size()) return {};
    if (starts_name(text_[at_])) {
      while (at_ < text_.size() && in_name(text_[at_])) ++at_;
    } else if (text_[at_] == '"') {
      for (++at_; at_ < text_.size() && text_[at_] != '"'; ++at_) {
        if (text_[at_] == '\\') ++at_;
      }
      at_ = std::min(at_ + 1, text_.size());
    } else {
      ++at_;
    }
    return text_.substr(start, at_ - start);
  }

 private:
  /// Spaces and comments.
  void skip_blank() {
    while (at_ < text_.size()) {
      if (std::isspace(static_cast<unsigned char>(text_[at_])) != 0) {
        ++at_;
      } else if (text_.substr(at_, 2) == "//") {
        const std::size_t end = text_.find('\n', at_);
        at_ = end == std::string_view::npos ? text_.size() : end + 1;
      } else if (text_.substr(at_, 2) == "/*") {
        const std::size_t end = text_.find("*/", at_ + 2);
        at_ = end == std::string_view::npos ? text_.size() : end + 2;
      } else {
        return;
      }
    }
  }

  std::string_view text_;
  std::size_t at_ = 0;
};

}  // namespace

bool geo_identifier(std::string_view name) {
  return !name.empty() && starts_name(name.front()) && std::all_of(name.begin(), name.end(), in_name);
}

std::vector<std::string> geo_constants(std::string_view text) {
  std::vector<std::string> names;
  GeoScanner scan(text);
  while (!scan.done()) {
    if (scan.next() != "DefineConstant" || scan.peek() != '[') continue;
    (void)scan.next();
    // Inside the bracket: at its own level (depth 1), a name right after '[' or ',' and followed
    // by '=' is declared.
    int depth = 1;
    bool item_start = true;
    while (depth > 0 && !scan.done()) {
      const std::string_view token = scan.next();
      const char c = token.size() == 1 ? token.front() : '\0';
      if (c == '[' || c == '{' || c == '(') {
        ++depth;
        item_start = false;
      } else if (c == ']' || c == '}' || c == ')') {
        --depth;
        item_start = false;
      } else if (depth == 1 && c == ',') {
        item_start = true;
      } else if (depth == 1 && item_start && geo_identifier(token)) {
        item_start = false;
        if (scan.peek() == '=' && std::find(names.begin(), names.end(), token) == names.end()) {
          names.emplace_back(token);
        }
      } else {
        item_start = false;
      }
    }
  }
  return names;
}

}  // namespace saasgaps::io
