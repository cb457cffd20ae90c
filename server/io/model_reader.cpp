#include "io/model_reader.hpp"

#include "io/model_stream.hpp"
#include "io/section_reader.hpp"

namespace saasgaps::io {

Model read_model(const nlohmann::json& document) { return SectionReader().read(document); }

nlohmann::json parse_document(std::string_view text) { return parse_tree(text); }

Model parse_model(std::string_view text, std::string* digest) {
  SectionReader reader;
  stream_model(text, reader, digest);
  return reader.finish();
}

}  // namespace saasgaps::io
