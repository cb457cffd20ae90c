#include "solver/model/restraint_check.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace saasgaps {

namespace {

/// Union-find over node indices, with path halving.
class Bodies {
 public:
  explicit Bodies(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  int find(int a) {
    while (parent_[a] != a) {
      parent_[a] = parent_[parent_[a]];
      a = parent_[a];
    }
    return a;
  }
  void join(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<int> parent_;
};

template <class E>
void join_corners(Bodies& bodies, std::vector<char>& used, const E& element) {
  for (int k = 0; k < element.node_count; ++k) {
    used[element.nodes[k]] = 1;
    bodies.join(element.nodes[0], element.nodes[k]);
  }
}

/// The rigid motions of one body left free by its prescribed components.
/// Which components of each node are prescribed (a node may appear in several constraints).
struct Prescribed {
  std::vector<char> r, z;
};

std::vector<const char*> free_motions(const Model& model, const std::vector<int>& nodes, const Prescribed& fixed) {
  if (model.analysis == AnalysisType::axisymmetric) {
    for (int n : nodes) {
      if (fixed.z[n]) return {};
    }
    return {"translation z"};
  }
  // Rows of the constraint map in (a, b, theta), coordinates centred and scaled by the body's size
  // so the rank test does not depend on units or where the body sits.
  double rc = 0.0, zc = 0.0;
  for (int n : nodes) {
    rc += model.nodes[n].r;
    zc += model.nodes[n].z;
  }
  rc /= static_cast<double>(nodes.size());
  zc /= static_cast<double>(nodes.size());
  double size = 0.0;
  for (int n : nodes) size = std::max({size, std::abs(model.nodes[n].r - rc), std::abs(model.nodes[n].z - zc)});
  if (size == 0.0) size = 1.0;
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();  // sum of row^T row
  for (int n : nodes) {
    const double r = (model.nodes[n].r - rc) / size, z = (model.nodes[n].z - zc) / size;
    if (fixed.r[n]) {
      const Eigen::Vector3d row(1.0, 0.0, -z);
      normal += row * row.transpose();
    }
    if (fixed.z[n]) {
      const Eigen::Vector3d row(0.0, 1.0, r);
      normal += row * row.transpose();
    }
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(normal);
  const double largest = std::max(eigen.eigenvalues()(2), 1.0);
  std::vector<const char*> motions;
  for (int k = 0; k < 3; ++k) {
    if (eigen.eigenvalues()(k) > 1e-9 * largest) continue;
    // Name the free motion by its dominant component (a, b or theta).
    Eigen::Index dominant = 0;
    eigen.eigenvectors().col(k).cwiseAbs().maxCoeff(&dominant);
    const char* name = dominant == 0 ? "translation r" : dominant == 1 ? "translation z" : "rotation";
    if (std::find(motions.begin(), motions.end(), name) == motions.end()) motions.push_back(name);
  }
  return motions;
}

}  // namespace

std::vector<RestraintIssue> check_restraint(const Model& model) {
  const std::size_t n = model.nodes.size();
  Bodies bodies(n);
  std::vector<char> used(n, 0);
  for (const Element& e : model.elements) join_corners(bodies, used, e);
  if (model.gaps) {
    for (const GapElement& g : model.gaps->elements) join_corners(bodies, used, g);
  }
  if (model.contact) {
    // A contact pair joins its two surfaces' bodies, like a closed gap: a body pressed onto another
    // is held by it. (Surfaces are sides of solid elements, so their nodes are already used.)
    for (const SurfacePair& pair : model.contact->pairs) {
      const auto& a = model.contact->surfaces[static_cast<std::size_t>(pair.surfaces[0])].edges;
      const auto& b = model.contact->surfaces[static_cast<std::size_t>(pair.surfaces[1])].edges;
      if (!a.empty() && !b.empty()) bodies.join(a.front()[0], b.front()[0]);
    }
  }
  Prescribed fixed{std::vector<char>(n, 0), std::vector<char>(n, 0)};
  for (const Constraint& c : model.constraints) {
    if (c.u_r) fixed.r[c.node] = 1;
    if (c.u_z) fixed.z[c.node] = 1;
  }

  std::vector<RestraintIssue> issues;
  std::vector<std::vector<int>> members(n);
  for (std::size_t k = 0; k < n; ++k) {
    const int node = static_cast<int>(k);
    if (!used[k]) {
      // A node no element uses has no stiffness: only prescribing both components removes it.
      if (!fixed.r[k] || !fixed.z[k]) {
        issues.push_back({RestraintIssue::Kind::orphan_node, {node}, {}});
      }
      continue;
    }
    members[bodies.find(node)].push_back(node);
  }
  for (std::size_t root = 0; root < n; ++root) {
    if (members[root].empty()) continue;
    std::vector<const char*> motions = free_motions(model, members[root], fixed);
    if (!motions.empty()) {
      issues.push_back({RestraintIssue::Kind::unrestrained_body, std::move(members[root]), std::move(motions)});
    }
  }
  std::sort(issues.begin(), issues.end(),
            [](const RestraintIssue& a, const RestraintIssue& b) { return a.nodes.front() < b.nodes.front(); });
  return issues;
}

}  // namespace saasgaps
