#include "plot/result/plot_result.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace saasgaps::plot {

PlotResult::PlotResult(const nlohmann::json& result) : tree_(&result) {}

PlotResult::PlotResult(io::ResultArrays arrays) : arrays_(std::move(arrays)) {}

const ResultMesh& PlotResult::mesh() const {
  if (mesh_) return *mesh_;
  mesh_ = tree_ ? ResultMesh::from_result(*tree_) : ResultMesh::from_arrays(arrays_);
  if (!tree_) {
    // The mesh holds the nodes and the connectivity now: at 10^6 unknowns the columns were 40 MB
    // more at the drawing's peak. The element values and ids stay for element_member().
    arrays_.nodes.reset();
    if (arrays_.elements) {
      arrays_.elements->node_ids = {};
      arrays_.elements->first_node = {};
    }
  }
  return *mesh_;
}

std::vector<double> PlotResult::element_member(std::string_view key) const {
  if (tree_) {
    std::vector<double> values;
    for (const nlohmann::json& e : tree_->at("elements")) {
      const auto found = e.find(key);
      if (found == e.end()) {
        throw std::invalid_argument("element " + e.value("id", nlohmann::json()).dump() + " has no '" +
                                    std::string(key) + "'");
      }
      values.push_back(found->get<double>());
    }
    return values;
  }
  const auto k = std::find(arrays_.element_keys.begin(), arrays_.element_keys.end(), key);
  if (k == arrays_.element_keys.end() || !arrays_.elements) {
    throw std::logic_error("the result was read without the elements' '" + std::string(key) + "'");
  }
  const auto column = static_cast<std::size_t>(k - arrays_.element_keys.begin());
  const io::ResultElements& elements = *arrays_.elements;
  if (const std::optional<std::size_t> missing = elements.first_missing[column]) {
    throw std::invalid_argument("element " + std::to_string(elements.id[*missing]) + " has no '" + std::string(key) +
                                "'");
  }
  return elements.values[column];
}

}  // namespace saasgaps::plot
