#pragma once
/// The SAX pass over a model document's text (internal to io/): one pass of nlohmann's SAX parser
/// feeds a SectionReader without a tree of the whole document.
///
/// - Each item of nodes, elements and constraints is built as a small tree of its own, judged and
///   dropped; every other top-level member (small: analysis, materials, gaps, loads, ...) is built
///   whole and judged when it ends.
/// - A member that comes before a member it depends on (dependencies() in section_reader.hpp; e.g.
///   elements before nodes, as in documents printed with sorted keys) is skipped and its byte span
///   kept; once the pass is over, the kept spans are parsed again, in dependency order. Documents
///   in the contract's order are read in one pass.
/// - The pass tracks the JSON Pointer of the value being parsed, so a repeated key and a number
///   beyond the range of a double are reported where they are. (nlohmann's own tree keeps only the
///   last of repeated keys and forgets where a parse error was.)
/// - The pass stops with NestingTooDeep at the first container nested deeper than max_json_depth
///   (io/json_limits.hpp), before anything of it is built.

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/model/model_digest.hpp"
#include "io/sections/section_reader.hpp"
#include "solver/base/errors.hpp"

namespace saasgaps::io {

/// Reads a model from text into `reader` (then reader.finish() gives the Model or every issue).
/// Throws ModelError with the one issue when the text is not JSON. When `digest` is given, also
/// computes model_digest of the document (io/state_codec.hpp) from the members as they are read.
void stream_model(std::string_view text, SectionReader& reader, std::string* digest);

/// The detail of an issue at a key that an object repeats.
std::string repeated_key_detail(std::string_view key);

/// model_digest (io/state_codec.hpp) of a document with these sections: the fingerprint of the
/// root's compact dump without title, description and output, keys sorted; `add(s, f)` adds the
/// compact dump of section s's value (as nlohmann's dump() prints it) to f.
std::string model_fingerprint(const std::array<bool, section_count>& present,
                              const std::function<void(Section, Fingerprint&)>& add);

/// The whole document as a tree, with repeated keys and out-of-range numbers reported at their
/// pointers (ModelError), as parse_document promises.
nlohmann::json parse_tree(std::string_view text);

}  // namespace saasgaps::io
