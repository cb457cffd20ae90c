#pragma once
/// The fast path of a model document's text (internal to io/): one strict scan in place
/// (io/json_scan.hpp) that reads a valid model of the usual shape straight into a SectionReader,
/// with no copy of the text, no index of its structure and no tape. A model's bulk is its large
/// arrays (nodes, elements, constraints, /loads/temperatures/nodal: 99 % of the text at 10^6
/// unknowns); their items are read typed, and their rules checked on the numbers
/// (SectionReader::read_*_values). Every other top-level member is small: its span is parsed into
/// a tree by the nlohmann parser of parse_document (parse_tree, which refuses repeated keys and
/// numbers beyond a double) and judged by the rule code.
///
/// It only accepts. Anything else (an unknown or repeated root key, a key with an escape, an item
/// of another shape or that breaks a rule, text that is not JSON, a small member the tree parser
/// refuses) makes it give up, and the caller reads the text again with the reporting path
/// (io/simd_model_reader.hpp), which finds and words every issue. The spans it hands to the tree
/// parser are each a whole JSON value and the scan checks the structure around them, so what it
/// accepts is JSON.
///
/// The sections are read as the text gives them when the sections they depend on (dependencies())
/// have been read, which in the contract's order is at once; any other is skipped and read from
/// its span when the root ends, in the order of Section.

#include <string_view>

#include "io/sections/section_reader.hpp"

namespace saasgaps::io {

/// Reads a model from text into `reader`; true when the whole text was read (reader.finish() then
/// gives the Model, or the issues of rules judged across sections). False when it gave up:
/// `reader` is then half fed and must be dropped.
bool scan_model_text(std::string_view text, SectionReader& reader);

}  // namespace saasgaps::io
