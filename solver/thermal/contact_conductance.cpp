#include "solver/thermal/contact_conductance.hpp"

#include <algorithm>
#include <cassert>

namespace saasgaps {

double closed_conductance(const InterfaceConductance& c, double p) {
  const auto& rows = c.closed;
  if (p <= rows.front().p) return rows.front().h;
  if (p >= rows.back().p) return rows.back().h;
  const auto upper = std::upper_bound(rows.begin(), rows.end(), p, [](double v, const ConductanceRow& r) { return v < r.p; });
  const ConductanceRow& b = *upper;
  const ConductanceRow& a = *(upper - 1);
  return a.h + (p - a.p) / (b.p - a.p) * (b.h - a.h);
}

ContactConductance::ContactConductance(const Model& model) : model_(model) {
  if (!model.contact) return;
  const auto& pairs = model.contact->pairs;
  if (std::none_of(pairs.begin(), pairs.end(), [](const SurfacePair& p) { return p.conductance.has_value(); })) return;
  surfaces_ = surface_contact(model);
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    if (!pairs[k].conductance) continue;
    for (std::size_t r = 0; r < surfaces_.rows[k].size(); ++r) rows_.push_back({k, r});
  }
}

std::span<const int> ContactConductance::nodes(std::size_t r) const {
  const MortarRows& rows = surfaces_.rows[rows_[r].pair];
  const std::size_t row = rows_[r].row;
  return {rows.node.data() + rows.start[row], rows.start[row + 1] - rows.start[row]};
}

ContactConductance::Point ContactConductance::point(std::size_t r, std::span<const ContactPairResult> results) const {
  const Row& at = rows_[r];
  const MortarRows& rows = surfaces_.rows[at.pair];
  const double D = rows.weight[at.row];
  Point p{rows.g0[at.row] / D, 0.0, false};
  bool in_contact = false;
  if (!results.empty()) {
    assert(results[at.pair].points.size() == rows.size());
    const ContactPointResult& result = results[at.pair].points[at.row];
    p.gap = result.gap;
    p.pressure = result.pressure;
    in_contact = result.state != ContactPointState::open;
  }
  const SurfaceMeasure measure{model_.analysis, model_.thickness};
  const Node& node = model_.nodes[static_cast<std::size_t>(rows.slave_node[at.row])];
  const double length = D / measure.weight(node.r);  // the node's share of side A's length
  p.touching = in_contact || p.gap <= touching_gap_fraction * length;
  return p;
}

std::vector<double> ContactConductance::conductances(std::span<const ContactPairResult> results) const {
  std::vector<double> H;
  H.reserve(rows_.size());
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    const InterfaceConductance& c = *model_.contact->pairs[rows_[r].pair].conductance;
    const Point p = point(r, results);
    H.push_back(p.touching ? closed_conductance(c, p.pressure) : c.gas_conductivity / p.gap);
  }
  return H;
}

std::vector<bool> ContactConductance::touching(std::span<const ContactPairResult> results) const {
  std::vector<bool> t;
  t.reserve(rows_.size());
  for (std::size_t r = 0; r < rows_.size(); ++r) t.push_back(point(r, results).touching);
  return t;
}

Eigen::MatrixXd ContactConductance::block(std::size_t r, double H) const {
  const MortarRows& rows = surfaces_.rows[rows_[r].pair];
  const std::size_t row = rows_[r].row;
  const auto first = static_cast<Eigen::Index>(rows.start[row]);
  const auto n = static_cast<Eigen::Index>(rows.start[row + 1] - rows.start[row]);
  const Eigen::Map<const Eigen::VectorXd> c(rows.mortar.data() + first, n);
  return (H / rows.weight[row]) * c * c.transpose();
}

}  // namespace saasgaps
