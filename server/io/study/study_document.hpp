#pragma once
/// The study document (docs/studies.md): one model (or assembly) document run over a set of
/// parameter values, each parameter a JSON Pointer into it, and the outputs reduced from each
/// point's result.
///
///   {"schema_version": 1, "title": "...", "model": {...} | "assembly": {...},
///    "parameters": [{"name": "p", "pointer": "/loads/pressures/0/normal", "values": [1, 2, 3]}],
///    "sampling": "grid" | "zip",                        (default "grid")
///    "outputs": [{"name": "u_max", "of": "nodes.u_r", "reduce": "max", "nodes": [ids]},
///                {"name": "push", "of": "set_reactions.fz", "reduce": "sum", "set": "pushed"}]}
///
/// read_study judges the whole document before anything runs and throws ModelError (document
/// "study") with every issue at its JSON Pointer: an unknown key, a pointer that does not resolve
/// in the model, a value whose JSON type differs from the value it replaces, an empty `values`,
/// `zip` over `values` of unequal lengths, more points than the limit, an unknown output field or
/// reducer, names repeated. A value of the right type that the model reader refuses (E = -1) is not
/// the study's error: that point fails alone (point_issues).

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "solver/base/errors.hpp"

namespace saasgaps::io {

/// Points a study may have unless the caller says otherwise (`saasgaps study --max-points`).
inline constexpr std::size_t default_max_study_points = 10000;

struct StudyParameter {
  std::string name;
  std::string pointer;  ///< into the model (or assembly) document
  std::vector<nlohmann::json> values;
};

enum class Reducer { max, min, sum, mean };

struct StudyOutput {
  std::string name;
  std::string of;  ///< "nodes.u_r", "contact.pressure", "reaction_sum.fz", ... (study_outputs.hpp)
  Reducer reduce = Reducer::max;
  /// At most one of these: the ids, the contact pair [A, B] or the node set (of set_reactions)
  /// the reduction runs over.
  std::optional<std::vector<int>> elements, nodes;
  std::optional<std::vector<std::string>> pair;
  std::optional<std::string> set;
};

enum class Sampling { grid, zip };

struct Study {
  std::string title;
  bool assembly = false;  ///< the base is an assembly document (imported per point) rather than a model
  nlohmann::json base;    ///< the model or assembly document
  std::vector<StudyParameter> parameters;
  Sampling sampling = Sampling::grid;
  std::vector<StudyOutput> outputs;

  /// Points: the product of the values' lengths (grid) or their common length (zip).
  [[nodiscard]] std::size_t point_count() const;
  /// The value index of each parameter at point `index`: grid points run the last parameter
  /// fastest (index = ((i0 n1 + i1) n2 + i2) ...), zip points take the index-th of every one.
  [[nodiscard]] std::vector<std::size_t> value_indices(std::size_t index) const;
  /// {name: value} of point `index`.
  [[nodiscard]] nlohmann::json point_parameters(std::size_t index) const;
  /// The base document with point `index`'s values put at their pointers.
  [[nodiscard]] nlohmann::json point_document(std::size_t index) const;
};

/// Reads and checks a study document (parsed). ModelError("study") with every issue otherwise.
Study read_study(const nlohmann::json& document, std::size_t max_points = default_max_study_points);

/// Why point `index`'s model is refused by the model reader, one line naming, for an issue at or
/// under a parameter's pointer, the parameter and its value's pointer in the study:
/// "parameter \"E\" = -1 (/parameters/1/values/0): /materials/0/table/0/E: E = -1 is out of
/// range: ..."; empty when the model reads. Model studies only (an assembly's point is judged by
/// its import, when it runs).
std::string point_issues(const Study& study, std::size_t index);

/// The same line for an error already thrown for point `index`'s document: the model reader's, or
/// an assembly point's import (whose pointers are into the assembly, where the parameters point).
std::string point_issues(const Study& study, std::size_t index, const ModelError& error);

}  // namespace saasgaps::io
