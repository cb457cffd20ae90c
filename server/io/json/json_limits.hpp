#pragma once
/// The resource limits on every JSON and CBOR document SAASGAPS reads (models, assemblies, request
/// bodies, results and restart states read back, the worker protocol), in one place; listed with
/// their defaults in docs/operations.md, section "Limits".
///
/// Why a nesting limit: nlohmann's JSON text parser is iterative, but its CBOR decoder is a
/// recursive descent, and most of what handles a tree recurses once per level (dump, copies,
/// comparison, the readers that judge and quote a value). A document of 10^5 nested arrays (200 KB)
/// overflowed the stack: the server died with SIGSEGV and `saasgaps import` with exit 139. So every
/// reader refuses a container opened deeper than max_json_depth while it parses, before any tree of
/// it exists (and before the CBOR decoder recurses into it).
///
/// Nothing else needs a limit here: the length of a string or a key and the count of members or
/// items are bounded by the size of the input (--max-body for the service, the file for the CLI),
/// and the readers' work and memory are linear in that size.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "solver/base/errors.hpp"

namespace saasgaps::io {

/// The deepest nesting of arrays and objects any document may have: the root container is level 1.
/// The example models and assemblies (schemas/examples) nest 5 levels (e.g. /materials/0/table/0 and
/// its values); 64 leaves room for any extension and is far from the stack's reach (a tree consumer
/// spends a few hundred bytes of stack per level).
inline constexpr std::size_t max_json_depth = 64;

/// A document nests deeper than max_json_depth: one issue, at the (abbreviated, see
/// shown_pointer) pointer of the value that would open level max_json_depth + 1. A ModelError, so
/// the service answers 422 and the CLI exits 2, as for any other refused value.
class NestingTooDeep : public ModelError {
 public:
  using ModelError::ModelError;
};

/// A pointer as an error message shows it: unchanged up to 160 bytes; longer ones keep their first
/// and last reference tokens around "/..." (a token itself longer than 40 bytes is cut to 32 and
/// "..."), so that a message about a value 64 levels deep (or under a key of a megabyte) stays
/// readable.
std::string shown_pointer(const std::string& pointer);

/// Where a SAX pass is: the open containers, each with its current member key or item index, and
/// the nesting limit. Readers call open/key/close/next as the parser reports events.
class JsonPath {
 public:
  struct Frame {
    bool is_object = false;
    std::string key;        ///< objects: the current member
    std::size_t index = 0;  ///< arrays: the current item
  };

  /// A container opens at the current place. Throws NestingTooDeep (opening nothing) when it would
  /// be level max_json_depth + 1.
  void open(bool is_object);
  /// The innermost container closes; the value it was is complete (next() is called for it).
  void close();
  /// The innermost object's next member is `name`.
  void key(std::string_view name) { frames_.back().key.assign(name); }
  /// A value in the innermost container is complete: an array moves on to its next item.
  void next() {
    if (!frames_.empty() && !frames_.back().is_object) ++frames_.back().index;
  }
  /// Starts inside the root object at member `name` (a reader that parses one member's text alone).
  void start_at_member(std::string name);

  [[nodiscard]] std::size_t depth() const { return frames_.size(); }
  [[nodiscard]] Frame& top() { return frames_.back(); }
  /// The JSON Pointer of the current place (RFC 6901), in full.
  [[nodiscard]] std::string pointer() const;

 private:
  std::vector<Frame> frames_;
};

/// For SAX handlers in io/ whose parse_error should throw what nlohmann's own parse functions throw
/// (json::parse_error, json::out_of_range for a number beyond a double).
[[noreturn]] void rethrow_parse_exception(const nlohmann::detail::exception& e);

/// Whether `text` is JSON (syntax only, like nlohmann::json::accept) without building a tree.
/// Throws NestingTooDeep when it nests deeper than max_json_depth.
bool accept_json(std::string_view text);

/// Decodes CBOR (RFC 8949, as nlohmann::json::from_cbor with strict checking and tags refused)
/// within max_json_depth. Throws nlohmann::json::parse_error for bytes that are not such CBOR and
/// NestingTooDeep.
nlohmann::json parse_cbor(std::span<const std::uint8_t> bytes);
/// The same for bytes held in a string (an HTTP body).
nlohmann::json parse_cbor(std::string_view bytes);

}  // namespace saasgaps::io
