#pragma once
/// The fast pass over a model document's text (internal to io/): simdjson's DOM parser validates
/// the whole text and lays it out in a tape at about a gigabyte per second (runtime dispatch to the
/// processor's SIMD kernels), then one walk over the tape feeds a SectionReader.
///
/// - The sections are read in dependency order (Section order) whatever their order in the text:
///   the tape gives random access to the root's members, so no section is kept and parsed again.
/// - Each item of nodes, elements and constraints of the usual shape (exactly its keys, each once,
///   numbers where numbers belong) goes to SectionReader::read_*_values with no tree at all; any
///   other item, and every other section (small), becomes a nlohmann tree judged by the rules of
///   read_model, so every issue reads exactly as there.
/// - simdjson keeps every member of an object, repeated keys included: the walk reports each
///   repeated key at its pointer (a tree keeps the later value, as nlohmann's parser does).
/// - The digest is that of model_digest (io/state_codec.hpp), hashed from the dump of each section
///   written from the tape (io/tape_dump.hpp), never held whole.
///
/// simdjson reports only an error code, no position, and it refuses an integer beyond 64 bits that
/// nlohmann reads as a double. So text that simdjson refuses is not judged here: the caller reads
/// it again with the nlohmann pass (model_stream.hpp), which words the issue with its byte position
/// (or reads the big integer); the nesting limit is simdjson's max_depth, and the nlohmann pass
/// gives the NestingTooDeep with its pointer.

#include <string>
#include <string_view>

#include "io/sections/section_reader.hpp"

namespace saasgaps::io {

/// Reads a model from text into `reader` (then reader.finish() gives the Model or every issue),
/// and with `digest` sets it to the model_digest of the document. Returns false, having called
/// nothing on `reader`, when the text is not within this pass: text simdjson refuses (not JSON, a
/// number beyond a double or an integer beyond 64 bits, nesting deeper than max_json_depth, a byte
/// order mark) or a document that is not an object.
bool read_model_text(std::string_view text, SectionReader& reader, std::string* digest);

/// Sets `digest` to the model_digest of the document, from the tape alone (no rule is judged).
/// False, `digest` untouched, when the text is not within this pass (as read_model_text).
bool digest_model_text(std::string_view text, std::string& digest);

}  // namespace saasgaps::io
