#include "plot/result/gap_row.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <unordered_map>

#include "plot/draw/figure.hpp"
#include "plot/result/field.hpp"

namespace saasgaps::plot {

RowAxis row_axis(const std::string& name) {
  if (name == "index") return RowAxis::index;
  if (name == "position") return RowAxis::position;
  if (name == "r") return RowAxis::r;
  if (name == "z") return RowAxis::z;
  throw std::invalid_argument("a gap row runs along 'index', 'position', 'r' or 'z', not '" + name + "'");
}

namespace {

int parse_id(std::string_view text, const std::string& whole) {
  int value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size() || value < 1) {
    throw std::invalid_argument("gap ids are positive integers or ranges like 81-98, separated by commas; '" +
                                std::string(text) + "' in '" + whole + "' is not");
  }
  return value;
}

}  // namespace

std::vector<int> parse_gap_ids(const std::string& text) {
  constexpr std::size_t max_ids = 1'000'000;
  std::vector<int> ids;
  for (std::size_t begin = 0; begin <= text.size();) {
    const std::size_t end = std::min(text.find(',', begin), text.size());
    const std::string_view item = std::string_view(text).substr(begin, end - begin);
    const std::size_t dash = item.find('-');
    const int first = parse_id(item.substr(0, dash), text);
    const int last = dash == std::string_view::npos ? first : parse_id(item.substr(dash + 1), text);
    if (last < first) throw std::invalid_argument("the gap id range '" + std::string(item) + "' runs backwards");
    if (ids.size() + static_cast<std::size_t>(last - first) + 1 > max_ids) {
      throw std::invalid_argument("more than a million gap ids in '" + text.substr(0, 40) + "...'");
    }
    for (int id = first; id <= last; ++id) ids.push_back(id);
    begin = end + 1;
  }
  return ids;
}

namespace {

/// The gap's centroid (mean of its nodes, undeformed) and its length along the face: the extent
/// of its nodes perpendicular to M.
struct GapShape {
  std::array<double, 2> centre;
  double length;
};

GapShape gap_shape(const ResultMesh& mesh, const GapElement& g) {
  const double a = g.angle_deg * std::numbers::pi / 180.0;
  const std::array<double, 2> along{-std::sin(a), std::cos(a)};
  double r = 0.0, z = 0.0, lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const int n : g.nodes) {
    r += mesh.nodes[n].r;
    z += mesh.nodes[n].z;
    const double t = mesh.nodes[n].r * along[0] + mesh.nodes[n].z * along[1];
    lo = std::min(lo, t);
    hi = std::max(hi, t);
  }
  const double count = static_cast<double>(g.nodes.size());
  return {{r / count, z / count}, hi - lo};
}

}  // namespace

bool gaps_connected(const ResultMesh& mesh, const GapElement& a, const GapElement& b) {
  for (const int n : a.nodes) {
    if (std::find(b.nodes.begin(), b.nodes.end(), n) != b.nodes.end()) return true;
  }
  const GapShape p = gap_shape(mesh, a), q = gap_shape(mesh, b);
  return std::hypot(q.centre[0] - p.centre[0], q.centre[1] - p.centre[1]) <= 0.6 * (p.length + q.length);
}

void GapRow::set_points(Series& series, const std::vector<double>& y, std::size_t from, std::size_t to) const {
  to = std::min(to, gaps.size());
  for (std::size_t i = from; i < to; ++i) {
    if (i > from && part[i] != part[i - 1]) {
      series.x.push_back(x[i]);
      series.y.push_back(std::numeric_limits<double>::quiet_NaN());
    }
    series.x.push_back(x[i]);
    series.y.push_back(y[i]);
  }
}

std::pair<std::size_t, std::size_t> GapRow::part_range(int k) const {
  const auto begin = std::find(part.begin(), part.end(), k);
  const auto end = std::find_if(begin, part.end(), [k](int p) { return p != k; });
  return {static_cast<std::size_t>(begin - part.begin()), static_cast<std::size_t>(end - part.begin())};
}

GapRow select_gap_row(const ResultMesh& mesh, const GapRowOptions& options, int max_labels) {
  GapRow row;
  if (options.gap_ids.empty()) {
    for (std::size_t g = 0; g < mesh.gaps.size(); ++g) row.gaps.push_back(g);
  } else {
    std::unordered_map<int, std::size_t> index;
    for (std::size_t g = 0; g < mesh.gaps.size(); ++g) index.emplace(mesh.gaps[g].id, g);
    for (const int id : options.gap_ids) {
      const auto found = index.find(id);
      if (found == index.end()) {
        throw std::invalid_argument("gap " + std::to_string(id) + " is not a gap element of this result");
      }
      row.gaps.push_back(found->second);
    }
  }
  if (row.gaps.empty()) throw std::invalid_argument("the result has no gap elements to plot along");
  row.part.push_back(0);
  for (std::size_t i = 1; i < row.gaps.size(); ++i) {
    const bool connected = gaps_connected(mesh, mesh.gaps[row.gaps[i - 1]], mesh.gaps[row.gaps[i]]);
    row.part.push_back(row.part.back() + (connected ? 0 : 1));
  }

  // Centroids of the undeformed gaps.
  std::vector<std::array<double, 2>> centre;
  for (const std::size_t g : row.gaps) {
    double r = 0.0, z = 0.0;
    for (const int n : mesh.gaps[g].nodes) {
      r += mesh.nodes[n].r;
      z += mesh.nodes[n].z;
    }
    const double count = static_cast<double>(mesh.gaps[g].nodes.size());
    centre.push_back({r / count, z / count});
  }
  const std::string length_unit = with_unit("", Quantity::length, mesh.units);
  const char* r_name = mesh.plane() ? "x" : "r";
  const char* z_name = mesh.plane() ? "y" : "z";
  switch (options.along) {
    case RowAxis::index: {
      const int n = static_cast<int>(row.gaps.size());
      for (int i = 0; i < n; ++i) row.x.push_back(i + 1);
      row.axis.min = 0.5;
      row.axis.max = n + 0.5;
      // Every gap labelled by its id while the labels fit, else every k-th.
      max_labels = std::max(2, max_labels);
      const int every = std::max(1, (n + max_labels - 1) / max_labels);
      for (int i = 0; i < n; i += every) {
        row.axis.ticks.push_back(i + 1);
        row.axis.labels.push_back(std::to_string(mesh.gaps[row.gaps[i]].id));
      }
      row.axis.title = options.gap_ids.empty() ? "gap element id (in model order)" : "gap element id (in the row's order)";
      return row;
    }
    case RowAxis::position: {
      double s = 0.0;
      for (std::size_t i = 0; i < centre.size(); ++i) {
        if (i > 0) s += std::hypot(centre[i][0] - centre[i - 1][0], centre[i][1] - centre[i - 1][1]);
        row.x.push_back(s);
      }
      row.axis = numeric_axis(0.0, std::max(s, 1e-12),
                              "distance along the gaps from gap " + std::to_string(mesh.gaps[row.gaps.front()].id) +
                                  length_unit);
      return row;
    }
    case RowAxis::r:
    case RowAxis::z: {
      const int k = options.along == RowAxis::r ? 0 : 1;
      for (const auto& c : centre) row.x.push_back(c[k]);
      const auto [lo, hi] = std::minmax_element(row.x.begin(), row.x.end());
      row.axis = numeric_axis(*lo, std::max(*hi, *lo + 1e-12),
                              std::string(k == 0 ? r_name : z_name) + " of the gap centre" + length_unit);
      return row;
    }
  }
  return row;
}

int gap_labels_that_fit(const Canvas& canvas, const ResultMesh& mesh) {
  const Typography t = typography(canvas);
  int widest = 1;
  for (const GapElement& g : mesh.gaps) widest = std::max(widest, g.id);
  const double label = canvas.text_width(std::string(std::to_string(widest).size(), '0'), t.small);
  // Each label with most of its width again beside it, over the plot's share of the width.
  return std::max(2, static_cast<int>(0.75 * canvas.width() / (1.8 * label)));
}

}  // namespace saasgaps::plot
