#include "solver/gaps/contact_pairs.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>

#include "solver/assembly/element_data.hpp"
#include "solver/fe/edge_loads.hpp"
#include "solver/fe/element_kernel.hpp"
#include "solver/gaps/gap_faces.hpp"

namespace saasgaps {

namespace {

/// A node faces another when their offset across M is within this fraction of the face length.
constexpr double max_facing_offset = 0.5;
/// Separations below this fraction of the face length count as zero.
constexpr double zero_separation = 1.0e-9;

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

/// The consistent nodal loads of a unit pressure on edge p-q: the face area each end stands for.
std::array<double, 2> face_areas(const Model& model, const Vec2& p, const Vec2& q) {
  const auto loads = edge_traction_loads(p, q, Vec2(1.0, 0.0), model.analysis, model.thickness);
  return {loads[0].x(), loads[1].x()};
}

/// One pair of one gap element, before deduplication.
struct RawPair {
  ContactPair pair;
  double area = 0.0;
};

class Pairer {
 public:
  /// axis_problem: gap_axis_problems' verdict on this gap.
  Pairer(const Model& model, std::size_t g, std::optional<std::string> axis_problem)
      : model_(model), gap_(model.gaps->elements[g]), g_(g), axis_problem_(std::move(axis_problem)) {
    x_ = corner_coordinates(model, gap_.nodes, gap_.node_count);
    const double angle = gap_.angle_deg * std::numbers::pi / 180.0;
    n_ = Vec2(std::cos(angle), std::sin(angle));
  }

  /// The element's pairs, or the reason there are none.
  std::optional<std::vector<RawPair>> pairs(std::string& why) {
    // Faces across M, and M across the gap: the model reader's rule too (gap_faces.hpp).
    if (axis_problem_) {
      why = *axis_problem_;
      return std::nullopt;
    }
    const GapFaces faces = gap_faces(x_, gap_.node_count, gap_.angle_deg);
    return gap_.node_count == 4 ? quad_pairs(faces, why) : triangle_pairs(faces, why);
  }

 private:
  int id(int corner) const { return model_.nodes[gap_.nodes[corner]].id; }

  std::optional<std::vector<RawPair>> quad_pairs(const GapFaces& faces, std::string& why) {
    // Corner one[k] of one face faces corner two[k] of the other.
    const std::array<std::array<int, 2>, 2> facing{{{faces.one[0], faces.two[0]}, {faces.one[1], faces.two[1]}}};
    // Face one: the first corners of each facing pair; face two: the second.
    const auto area_one = face_areas(model_, x_[facing[0][0]], x_[facing[1][0]]);
    const auto area_two = face_areas(model_, x_[facing[0][1]], x_[facing[1][1]]);
    const double length = 0.5 * ((x_[facing[1][0]] - x_[facing[0][0]]).norm() + (x_[facing[1][1]] - x_[facing[0][1]]).norm());
    std::vector<RawPair> out;
    int sign = 0;
    for (int k = 0; k < 2; ++k) {
      const int p = facing[k][0], q = facing[k][1];
      const Vec2 d = x_[q] - x_[p];
      const double separation = n_.dot(d);
      const double offset = std::abs(cross(n_, d));
      if (offset > max_facing_offset * length) {
        why = "node " + std::to_string(id(p)) + " does not face node " + std::to_string(id(q)) +
              " along M (offset " + format(offset) + " across M, face length " + format(length) + ")";
        return std::nullopt;
      }
      if (std::abs(separation) <= zero_separation * length) {
        why = "nodes " + std::to_string(id(p)) + " and " + std::to_string(id(q)) +
              " have zero separation along M: the exact mode needs an initial gap > 0";
        return std::nullopt;
      }
      const int s = separation > 0.0 ? 1 : -1;
      if (sign != 0 && s != sign) {
        why = "its faces cross: nodes " + std::to_string(id(facing[0][0])) + "-" + std::to_string(id(facing[0][1])) +
              " and " + std::to_string(id(p)) + "-" + std::to_string(id(q)) + " are separated in opposite directions along M";
        return std::nullopt;
      }
      sign = s;
      RawPair r;
      // Side a is the one M points away from: g0 = n . (x_b - x_a) > 0.
      const int a = s > 0 ? p : q, b = s > 0 ? q : p;
      r.pair.node = {gap_.nodes[a], gap_.nodes[b]};
      r.pair.weight = {-1.0, 1.0};
      r.pair.normal = n_;
      r.area = 0.5 * (area_one[k] + area_two[k]);
      out.push_back(r);
    }
    return out;
  }

  std::optional<std::vector<RawPair>> triangle_pairs(const GapFaces& faces, std::string& why) {
    // The face is the edge most nearly perpendicular to M, the lone node the corner opposite it.
    const int e0 = faces.one[0], e1 = faces.one[1], lone = faces.two[0];
    // The point of the edge x_e0 + s (x_e1 - x_e0) on the line through the lone node along M.
    const Vec2 edge = x_[e1] - x_[e0];
    const double length = edge.norm();
    const double s = cross(x_[lone] - x_[e0], n_) / cross(edge, n_);
    if (s < -1.0e-9 || s > 1.0 + 1.0e-9) {
      why = "node " + std::to_string(id(lone)) + " does not face the edge " + std::to_string(id(e0)) + "-" +
            std::to_string(id(e1)) + " along M (it faces the edge's line at " + format(s) + " of its length)";
      return std::nullopt;
    }
    const double t = std::clamp(s, 0.0, 1.0);
    const double separation = n_.dot(x_[lone] - (x_[e0] + t * edge));
    if (std::abs(separation) <= zero_separation * length) {
      why = "node " + std::to_string(id(lone)) + " has zero separation from the edge " + std::to_string(id(e0)) +
            "-" + std::to_string(id(e1)) + " along M: the exact mode needs an initial gap > 0";
      return std::nullopt;
    }
    const double side = separation > 0.0 ? 1.0 : -1.0;  // +1: the lone node is side b
    RawPair r;
    r.pair.node = {gap_.nodes[lone], gap_.nodes[e0], gap_.nodes[e1]};
    r.pair.weight = {side, -side * (1.0 - t), -side * t};
    r.pair.normal = n_;
    // A triangle's one pair stands for half its edge: in a strip of triangles alternating sides (the
    // usual way to join faces that do not line up) each half-face then has one pair, so a uniform
    // pressure gives every pair lambda = p area, as on quadrilaterals.
    const auto area = face_areas(model_, x_[e0], x_[e1]);
    r.area = 0.5 * (area[0] + area[1]);
    return std::vector<RawPair>{r};
  }

  static std::string format(double v) {
    std::ostringstream text;
    text << v;
    return text.str();
  }

  const Model& model_;
  const GapElement& gap_;
  std::size_t g_;
  std::array<Vec2, 4> x_{};
  Vec2 n_;
  std::optional<std::string> axis_problem_;
};

/// Pairs of the same nodes (and edge) are one constraint: the key is the sorted node list.
std::vector<int> key_of(const ContactPair& p) {
  std::vector<int> key = p.node;
  std::sort(key.begin(), key.end());
  return key;
}

double separation(const Model& model, const ContactPair& p) {
  Vec2 d = Vec2::Zero();
  for (std::size_t k = 0; k < p.node.size(); ++k) d += p.weight[k] * Vec2(model.nodes[p.node[k]].r, model.nodes[p.node[k]].z);
  return p.normal.dot(d);
}

ContactPairs build(const Model& model, std::vector<PairingIssue>& issues) {
  ContactPairs out;
  const std::size_t gaps = model.gap_count();
  out.of_gap.resize(gaps);
  out.share_count.assign(gaps, 0);
  std::map<std::vector<int>, int> index;
  std::vector<Vec2> normal_sum;
  std::vector<std::optional<std::string>> axis_problems = gap_axis_problems(model, model.gaps->elements);
  for (std::size_t g = 0; g < gaps; ++g) {
    std::string why;
    const auto raw = Pairer(model, g, std::move(axis_problems[g])).pairs(why);
    if (!raw) {
      issues.push_back({g, "gap element " + std::to_string(model.gaps->elements[g].id) + " cannot be paired: " + why});
      continue;
    }
    for (const RawPair& r : *raw) {
      const auto [it, inserted] = index.try_emplace(key_of(r.pair), static_cast<int>(out.pairs.size()));
      if (inserted) {
        out.pairs.push_back(r.pair);
        normal_sum.push_back(Vec2::Zero());
      }
      ContactPair& p = out.pairs[it->second];
      // The same pair seen from the other side has its weights negated: align its normal.
      double seen = 0.0;
      for (std::size_t k = 0; k < r.pair.node.size(); ++k) {
        if (r.pair.node[k] == p.node[0]) seen = r.pair.weight[k];
      }
      const double orientation = p.weight[0] * seen > 0.0 ? 1.0 : -1.0;
      normal_sum[it->second] += orientation * r.pair.normal;
      p.area += r.area;
      auto& shares = out.of_gap[g];
      shares[out.share_count[g]++] = {it->second, r.area};
    }
  }
  for (std::size_t i = 0; i < out.pairs.size(); ++i) {
    ContactPair& p = out.pairs[i];
    p.normal = normal_sum[i].normalized();
    p.g0 = separation(model, p);
  }
  // Merged normals could in principle tip a separation to zero: report the gaps that use such a pair.
  for (std::size_t g = 0; g < gaps; ++g) {
    for (int k = 0; k < out.share_count[g]; ++k) {
      const ContactPair& p = out.pairs[out.of_gap[g][k].pair];
      if (!(p.g0 > 0.0)) {
        issues.push_back({g, "gap element " + std::to_string(model.gaps->elements[g].id) +
                                 " cannot be paired: its pair of nodes " + std::to_string(model.nodes[p.node[0]].id) +
                                 " and " + std::to_string(model.nodes[p.node[1]].id) +
                                 " has no positive separation along the mean M axis of the gaps sharing it"});
        break;
      }
    }
  }
  return out;
}

}  // namespace

GapPairingError::GapPairingError(std::vector<PairingIssue> issues)
    : SolverError(issues.empty() ? std::string("gap elements cannot be paired") : issues.front().detail),
      issues_(std::move(issues)) {}

std::vector<PairingIssue> contact_pairing_issues(const Model& model) {
  std::vector<PairingIssue> issues;
  if (model.gaps) build(model, issues);
  return issues;
}

ContactPairs contact_pairs(const Model& model) {
  std::vector<PairingIssue> issues;
  ContactPairs pairs = model.gaps ? build(model, issues) : ContactPairs{};
  if (!issues.empty()) throw GapPairingError(std::move(issues));
  return pairs;
}

}  // namespace saasgaps
