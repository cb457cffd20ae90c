#include "io/model_reader.hpp"

#include "errors.hpp"
#include "io/document_kind.hpp"
#include "io/json_limits.hpp"
#include "io/model_stream.hpp"
#include "io/section_reader.hpp"
#include "io/simd_model_reader.hpp"

namespace saasgaps::io {

Model read_model(const nlohmann::json& document) {
  try {
    return SectionReader().read(document);
  } catch (const ModelError& e) {
    rethrow_naming_document(e);
  }
}

nlohmann::json parse_document(std::string_view text) { return parse_tree(text); }

Model parse_model(std::string_view text, std::string* digest) {
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
