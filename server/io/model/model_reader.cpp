#include "io/model/model_reader.hpp"

#include <optional>
#include <utility>

#include "io/json/json_limits.hpp"
#include "io/model/document_kind.hpp"
#include "io/model/model_stream.hpp"
#include "io/model/scan_model_reader.hpp"
#include "io/model/simd_model_reader.hpp"
#include "io/sections/section_reader.hpp"
#include "solver/base/errors.hpp"

namespace saasgaps::io {

Model read_model(const nlohmann::json& document) {
  try {
    return SectionReader().read(document);
  } catch (const ModelError& e) {
    rethrow_naming_document(e);
  }
}

nlohmann::json parse_document(std::string_view text) { return parse_tree(text); }

namespace {

/// The model of the fast path (io/scan_model_reader.hpp), when it reads the text and finds no issue.
std::optional<Model> scanned_model(std::string_view text) {
  SectionReader reader;
  if (!scan_model_text(text, reader)) return std::nullopt;
  try {
    return reader.finish();
  } catch (const ModelError&) {
    return std::nullopt;  // the reporting path finds the issues again and words them in full
  }
}

}  // namespace

std::string model_text_digest(std::string_view text) {
  std::string digest;
  if (digest_model_text(text, digest)) return digest;
  // Text simdjson refuses (an integer beyond 64 bits, ...): the nlohmann pass, which reads it.
  SectionReader reader;
  stream_model(text, reader, &digest);
  return digest;
}

Model parse_model(std::string_view text, std::string* digest) {
  if (std::optional<Model> model = scanned_model(text)) {
    if (digest != nullptr) *digest = model_text_digest(text);
    return std::move(*model);
  }
  try {
    SectionReader reader;
    if (read_model_text(text, reader, digest)) return reader.finish();
    // Text simdjson refuses: the nlohmann pass says why, at the byte or pointer where it is.
    SectionReader diagnosis;
    stream_model(text, diagnosis, digest);
    return diagnosis.finish();
  } catch (const NotJsonText&) {
    throw;  // no document to name
  } catch (const NestingTooDeep&) {
    throw;  // nor here: the pass stopped at the limit
  } catch (const ModelError& e) {
    rethrow_naming_document(e);
  }
}

}  // namespace saasgaps::io
