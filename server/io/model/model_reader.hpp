#pragma once
/// Reads the model document (the JSON contract of docs/model.md, formally
/// schemas/model.schema.json) into the solver's Model, with every user id resolved to an index.
///
/// The reader is the one place where input is judged. It checks every rule of the contract, keeps
/// going after a failure, and throws saasgaps::ModelError carrying every issue it found, each
/// located by the JSON Pointer of the offending value (of the enclosing object for a missing key)
/// and described by a sentence that quotes the value. It never throws anything else for any input.
///
/// Decisions beyond the contract's text (also documented in the schema's descriptions):
/// - ids are JSON integers (1.0 is rejected even though JSON Schema calls it an integer) in
///   1..2147483647; nodes, materials and elements are non-empty arrays.
/// - gaps.shear_ratio (gap shear modulus / current tensile modulus, default 1e-6) and
///   gaps.convergence_test ("report" | "strict", default "report") are SAASGAPS additions.
/// - loads.temperatures.default defaults to analysis.reference_temperature, so a model without a
///   temperature load has no thermal strain.
/// - body_force.omega must be 0 unless the analysis is axisymmetric; analysis.thickness may only
///   appear in plane analyses.
/// - a constraint must prescribe r and/or z, and no component of a node is prescribed twice;
///   constraints must not be empty (an unrestrained model is a rigid body mechanism).
/// - a node may receive several nodal forces (they add); a node may have one nodal temperature.
/// - watch lists may not repeat an id.
/// - a repeated key in one JSON object is an error (parse_model only: a parsed nlohmann::json has
///   already kept just one of the values).
///
/// From text (parse_model), the model is read without a tree of the whole document (a scan in
/// place, io/scan_model_reader.hpp, and for text with issues the reporting path,
/// io/simd_model_reader.hpp); read_model judges a tree held in memory. Both apply the same rules
/// (io/section_reader.hpp) and report the same issues in the same order.
/// - a node that no element uses is not an error here (the solver reports the model singular).

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "solver/base/errors.hpp"
#include "solver/model/model.hpp"

namespace saasgaps::io {

/// Text that is not JSON at all (a syntax error): a ModelError with one issue at pointer "", told
/// apart from a JSON document that is not a valid model (the service answers 400 rather than 422).
class NotJsonText : public ModelError {
 public:
  using ModelError::ModelError;
};

/// Checks `document` against every rule and returns the Model. Throws ModelError with all issues.
Model read_model(const nlohmann::json& document);

/// Parses JSON text into a document, for callers that need the tree itself. Throws ModelError when the text is not JSON (one issue at ""), when a number is beyond the
/// range of a double (at the number's pointer) and when an object repeats a key (at that key);
/// NestingTooDeep (a ModelError) when it nests deeper than max_json_depth (io/json_limits.hpp).
nlohmann::json parse_document(std::string_view text);

/// Reads JSON text straight into a Model, with the checks of read_model. Text that is not JSON gives
/// NotJsonText, one issue at pointer "" with the parser's message and byte position; a number too large for a
/// double is reported at its own pointer; repeated keys are reported (at the repeated key's
/// pointer) before the issues of read_model; a document nesting deeper than max_json_depth gives
/// NestingTooDeep alone, at the place of the limit. With `digest`, also sets it to the model_digest
/// (io/state_codec.hpp) of the document, for restart states.
/// The model is read first by a strict scan in place (io/scan_model_reader.hpp), which accepts a
/// valid model of the usual shape and gives up on anything else; the text is then read again by
/// the reporting path (io/simd_model_reader.hpp), which finds and words every issue. The digest is
/// not part of reading: it is model_text_digest(text), computed only when `digest` is given.
Model parse_model(std::string_view text, std::string* digest = nullptr);

/// model_digest (io/state_codec.hpp) of a model document's text: the fingerprint that ties restart
/// states to it, the same bit for bit as that of the tree nlohmann's parser builds from the text.
/// No rule is judged (parse_model judges them); ModelError when the text is not JSON.
std::string model_text_digest(std::string_view text);

}  // namespace saasgaps::io
