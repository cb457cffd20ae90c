#include "plot/result/point_locator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "plot/result/element_map.hpp"


namespace saasgaps::plot {

namespace {

struct Box {
  double r0, z0, r1, z1;
};

Box element_box(const ResultMesh& mesh, const SolidElement& e) {
  Box b{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(),
        -std::numeric_limits<double>::max()};
  const auto include = [&b](double r, double z) {
    b.r0 = std::min(b.r0, r);
    b.z0 = std::min(b.z0, z);
    b.r1 = std::max(b.r1, r);
    b.z1 = std::max(b.z1, z);
  };
  const std::size_t count = e.nodes.size();
  const bool quadratic = count == 6 || count == 8;
  for (std::size_t k = 0; k < count; ++k) {
    const MeshNode& p = mesh.nodes[e.nodes[k]];
    include(p.r, p.z);
    if (quadratic && k % 2 == 1) {  // a mid-side node: its curve's control point
      const MeshNode& a = mesh.nodes[e.nodes[k - 1]];
      const MeshNode& c = mesh.nodes[e.nodes[(k + 1) % count]];
      include(2.0 * p.r - (a.r + c.r) / 2.0, 2.0 * p.z - (a.z + c.z) / 2.0);
    }
  }
  return b;
}

}  // namespace

PointLocator::PointLocator(const ResultMesh& mesh) : mesh_(mesh) {
  if (mesh.solids.empty()) return;
  std::vector<Box> boxes;
  Box all{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(),
          -std::numeric_limits<double>::max()};
  for (const SolidElement& e : mesh.solids) {
    boxes.push_back(element_box(mesh, e));
    all = {std::min(all.r0, boxes.back().r0), std::min(all.z0, boxes.back().z0), std::max(all.r1, boxes.back().r1),
           std::max(all.z1, boxes.back().z1)};
  }
  // About one bucket per element, shaped like the mesh.
  const double width = std::max(all.r1 - all.r0, 1e-300), height = std::max(all.z1 - all.z0, 1e-300);
  const double count = static_cast<double>(mesh.solids.size());
  columns_ = std::clamp(static_cast<int>(std::sqrt(count * width / height)), 1, 4096);
  rows_ = std::clamp(static_cast<int>(count / columns_), 1, 4096);
  r0_ = all.r0;
  z0_ = all.z0;
  cell_r_ = width / columns_;
  cell_z_ = height / rows_;
  const auto column_of = [this](double r) { return std::clamp(static_cast<int>((r - r0_) / cell_r_), 0, columns_ - 1); };
  const auto row_of = [this](double z) { return std::clamp(static_cast<int>((z - z0_) / cell_z_), 0, rows_ - 1); };
  // Two passes (count, then fill) build the bucket lists without a vector per bucket.
  first_.assign(static_cast<std::size_t>(columns_) * rows_ + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<std::size_t> next(first_.begin(), first_.end() - 1);
    if (pass == 1) elements_.resize(first_.back());
    for (std::size_t e = 0; e < boxes.size(); ++e) {
      for (int j = row_of(boxes[e].z0); j <= row_of(boxes[e].z1); ++j) {
        for (int i = column_of(boxes[e].r0); i <= column_of(boxes[e].r1); ++i) {
          const std::size_t bucket = static_cast<std::size_t>(j) * columns_ + i;
          if (pass == 0) ++first_[bucket + 1];
          else elements_[next[bucket]++] = e;
        }
      }
    }
    if (pass == 0) {
      for (std::size_t b = 1; b < first_.size(); ++b) first_[b] += first_[b - 1];
    }
  }
}

std::vector<Location> PointLocator::locate_all(double r, double z) const {
  std::vector<Location> found;
  if (elements_.empty()) return found;
  const double fr = (r - r0_) / cell_r_, fz = (z - z0_) / cell_z_;
  // A point a hair outside the box (round-off on the boundary) still looks in the edge bucket.
  if (fr < -1e-9 || fz < -1e-9 || fr > columns_ + 1e-9 || fz > rows_ + 1e-9) return found;
  const int i = std::clamp(static_cast<int>(fr), 0, columns_ - 1);
  const int j = std::clamp(static_cast<int>(fz), 0, rows_ - 1);
  const std::size_t bucket = static_cast<std::size_t>(j) * columns_ + i;
  for (std::size_t k = first_[bucket]; k < first_[bucket + 1]; ++k) {
    if (const auto at = inverse_map(mesh_, mesh_.solids[elements_[k]], r, z)) found.push_back({elements_[k], *at});
  }
  std::sort(found.begin(), found.end(), [](const Location& a, const Location& b) { return a.element < b.element; });
  return found;
}

std::optional<Location> PointLocator::locate(double r, double z) const {
  std::vector<Location> all = locate_all(r, z);
  if (all.empty()) return std::nullopt;
  return all.front();
}

}  // namespace saasgaps::plot
