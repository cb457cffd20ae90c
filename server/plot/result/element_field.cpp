#include "plot/result/element_field.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "solver/base/voigt.hpp"

namespace saasgaps::plot {

namespace {

std::uint64_t side_key(int node, int material) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(node)) << 32) | static_cast<std::uint32_t>(material);
}

Vec4 as_vec4(const std::array<double, 4>& s) { return Vec4(s[0], s[1], s[2], s[3]); }

}  // namespace

RecoveredStress::RecoveredStress(const PlotResult& result) : mesh_(result.mesh()) {
  has_sides_.assign(mesh_.nodes.size(), false);
  for (const SolidElement& e : mesh_.solids) {
    for (const int n : e.nodes) available_ = available_ && std::isfinite(mesh_.nodes[n].stress[0]);
    if (e.centre >= 0) available_ = available_ && std::isfinite(mesh_.nodes[e.centre].stress[0]);
  }
  if (!available_) return;
  const nlohmann::json& sides = array_member(result.document(), "node_sides");
  if (sides.empty()) return;
  std::unordered_map<int, int> index;
  for (std::size_t n = 0; n < mesh_.nodes.size(); ++n) index.emplace(mesh_.nodes[n].id, static_cast<int>(n));
  for (std::size_t k = 0; k < sides.size(); ++k) {
    const nlohmann::json& side = sides[k];
    const std::string where = "/node_sides/" + std::to_string(k);
    try {
      const auto node = index.find(side.at("node").get<int>());
      if (node == index.end()) throw std::invalid_argument(where + "/node is not a node of the result");
      std::array<double, 4> s{};
      constexpr std::array<const char*, 4> keys{"sigma_r", "sigma_z", "tau_rz", "sigma_theta"};
      for (std::size_t c = 0; c < keys.size(); ++c) s[c] = side.at(keys[c]).get<double>();
      sides_[side_key(node->second, side.at("material").get<int>())] = s;
      has_sides_[static_cast<std::size_t>(node->second)] = true;
    } catch (const nlohmann::json::exception& e) {
      throw std::invalid_argument("malformed result document: " + where + ": " + e.what());
    }
  }
}

const std::array<double, 4>& RecoveredStress::at(int node, int material) const {
  if (has_sides_[static_cast<std::size_t>(node)]) {
    if (const auto found = sides_.find(side_key(node, material)); found != sides_.end()) return found->second;
  }
  return mesh_.nodes[static_cast<std::size_t>(node)].stress;
}

std::array<double, 4> RecoveredStress::interpolate(const SolidElement& e, const std::vector<int>& nodes,
                                                   const ShapeValues& N) const {
  std::array<double, 4> s{};
  for (std::size_t a = 0; a < nodes.size(); ++a) {
    const std::array<double, 4>& v = at(nodes[a], e.material);
    for (std::size_t c = 0; c < 4; ++c) s[c] += N.N[a] * v[c];
  }
  return s;
}

double stress_field_value(const FieldInfo& field, const std::array<double, 4>& s, const PlanePoint& at,
                          const PlanePoint& centre) {
  if (field.cylindrical != Cylindrical::none) {
    // At the centre itself the direction is undefined; atan2(0, 0) = 0 takes x as radial there.
    const double phi = std::atan2(at[1] - centre[1], at[0] - centre[0]);
    return rotate_in_plane(s[0], s[1], s[2], phi, field.cylindrical);
  }
  if (field.name == "sigma_r") return s[0];
  if (field.name == "sigma_z") return s[1];
  if (field.name == "tau_rz") return s[2];
  if (field.name == "sigma_theta") return s[3];
  if (field.name == "sigma_1") return principal_in_plane(as_vec4(s)).s1;
  if (field.name == "sigma_2") return principal_in_plane(as_vec4(s)).s2;
  if (field.name == "effective") return von_mises(as_vec4(s));
  throw std::invalid_argument("'" + std::string(field.name) + "' is not a stress field");
}

ElementField::ElementField(const PlotResult& result, const FieldInfo& field, const PlanePoint& centre)
    : mesh_(result.mesh()), field_(field), centre_(centre) {
  require_field_fits(field, mesh_);
  if (field.constant_per_element) {
    source_ = FieldSource::element;
    per_element_ = element_values(result, mesh_, field, centre);
    return;
  }
  if (field.location == FieldLocation::element && field.quantity == Quantity::stress) {
    recovered_.emplace(result);
    if (recovered_->available()) {
      source_ = FieldSource::recovered;
      return;
    }
    recovered_.reset();
  }
  source_ = field.location == FieldLocation::element ? FieldSource::averaged : FieldSource::nodal;
  nodal_ = nodal_values(result, mesh_, field, centre);  // a gap field: std::invalid_argument
}

double ElementField::value(std::size_t e, const std::vector<int>& nodes, const ShapeValues& N,
                           const PlanePoint& at) const {
  if (recovered_) return stress_field_value(field_, recovered_->interpolate(mesh_.solids[e], nodes, N), at, centre_);
  if (source_ == FieldSource::element) return per_element_[e];
  double v = 0.0;
  for (std::size_t a = 0; a < nodes.size(); ++a) v += N.N[a] * nodal_[static_cast<std::size_t>(nodes[a])];
  return v;
}

PlanePoint located_point(const ResultMesh& mesh, const Location& location) {
  const SolidElement& e = mesh.solids[location.element];
  const std::vector<int> nodes = family_nodes(e);
  ShapeValues N;
  element_family(e).shape(location.at.xi, location.at.eta, N);
  PlanePoint p{0.0, 0.0};
  for (std::size_t a = 0; a < nodes.size(); ++a) {
    p[0] += N.N[a] * mesh.nodes[static_cast<std::size_t>(nodes[a])].r;
    p[1] += N.N[a] * mesh.nodes[static_cast<std::size_t>(nodes[a])].z;
  }
  return p;
}

double ElementField::value(const Location& location) const {
  const SolidElement& e = mesh_.solids[location.element];
  ShapeValues N;
  element_family(e).shape(location.at.xi, location.at.eta, N);
  return value(location.element, family_nodes(e), N, located_point(mesh_, location));
}

}  // namespace saasgaps::plot
