#pragma once
/// A result document as the plots read it, from either of two sources:
///   - a parsed tree (nlohmann::json): in-memory documents, the live history of a running job, and
///     the tests' reference path;
///   - typed arrays read from the text (io/result_arrays.hpp): stored results and files, where a
///     tree of a 10^6-unknown result would cost a gigabyte.
/// Both give the plots the same numbers: the small members as a tree (document()), the mesh
/// (mesh()) and the stored values of an element member (element_member()).

#include <optional>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/results/result_arrays.hpp"
#include "plot/result/result_mesh.hpp"

namespace saasgaps::plot {

class PlotResult {
 public:
  /// The tree path. The tree must outlive this object (it is not copied); implicit, so that a
  /// document can be drawn as it is.
  PlotResult(const nlohmann::json& result);  // NOLINT(google-explicit-constructor)
  /// The typed path: what read_result_arrays read (it must hold what the plot reads: see
  /// result_selection_for in plot_request.hpp).
  explicit PlotResult(io::ResultArrays arrays);

  /// The result's members other than its nodes and elements (all of them on the tree path).
  [[nodiscard]] const nlohmann::json& document() const { return tree_ ? *tree_ : arrays_.document; }
  /// The mesh, read once. A failed run or a malformed document: std::invalid_argument
  /// (ResultMesh::from_result).
  [[nodiscard]] const ResultMesh& mesh() const;
  /// The stored value of element member `key` per solid element, in mesh().solids order. An element
  /// without it: std::invalid_argument "element 7 has no 'sigma_r'". A key the arrays were not read
  /// with: std::logic_error (the caller's selection is wrong).
  [[nodiscard]] std::vector<double> element_member(std::string_view key) const;

 private:
  const nlohmann::json* tree_ = nullptr;
  mutable io::ResultArrays arrays_;  ///< mesh() releases the columns it has taken
  mutable std::optional<ResultMesh> mesh_;
};

}  // namespace saasgaps::plot
