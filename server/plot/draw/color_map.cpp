#include "plot/draw/color_map.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace saasgaps::plot {

namespace {

constexpr Rgb hex(unsigned value) {
  return {static_cast<double>((value >> 16) & 0xFFU) / 255.0, static_cast<double>((value >> 8) & 0xFFU) / 255.0,
          static_cast<double>(value & 0xFFU) / 255.0};
}

}  // namespace

ColorMap ColorMap::named(std::string_view name) {
  if (name == "rainbow") {
    // Dark blue for the most negative through red for the most positive, as in the report's era of
    // contour plots; the dark ends keep the extreme bands distinguishable from their neighbours.
    return ColorMap({{0.00, {0.00, 0.00, 0.70}},
                     {0.15, {0.00, 0.35, 1.00}},
                     {0.32, {0.00, 0.85, 1.00}},
                     {0.50, {0.25, 0.85, 0.25}},
                     {0.68, {1.00, 0.90, 0.00}},
                     {0.85, {1.00, 0.45, 0.00}},
                     {1.00, {0.78, 0.00, 0.00}}});
  }
  if (name == "viridis") {
    // matplotlib's viridis at tenths.
    return ColorMap({{0.0, hex(0x440154)}, {0.1, hex(0x482475)}, {0.2, hex(0x414487)}, {0.3, hex(0x355f8d)},
                     {0.4, hex(0x2a788e)}, {0.5, hex(0x21918c)}, {0.6, hex(0x22a884)}, {0.7, hex(0x44bf70)},
                     {0.8, hex(0x7ad151)}, {0.9, hex(0xbddf26)}, {1.0, hex(0xfde725)}});
  }
  if (name == "diverging") {
    // ColorBrewer's RdBu (Brewer, colorbrewer2.org), 11 classes, reversed so that negative
    // (compression) is blue and positive (tension) red; the centre is the near-white f7f7f7.
    return ColorMap({{0.0, hex(0x053061)}, {0.1, hex(0x2166ac)}, {0.2, hex(0x4393c3)}, {0.3, hex(0x92c5de)},
                     {0.4, hex(0xd1e5f0)}, {0.5, hex(0xf7f7f7)}, {0.6, hex(0xfddbc7)}, {0.7, hex(0xf4a582)},
                     {0.8, hex(0xd6604d)}, {0.9, hex(0xb2182b)}, {1.0, hex(0x67001f)}},
                    true);
  }
  if (name == "cividis") {
    // Nunez, Anderton and Renslow's cividis (matplotlib's), at fifths: readable with red-green
    // colour vision deficiency, lightness increasing linearly.
    return ColorMap({{0.0, hex(0x00224e)}, {0.2, hex(0x35456c)}, {0.4, hex(0x666970)}, {0.6, hex(0x948e77)},
                     {0.8, hex(0xc8b866)}, {1.0, hex(0xfee838)}});
  }
  std::string known;
  for (const std::string& n : names()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown colour map '" + std::string(name) + "'; colour maps: " + known);
}

std::vector<std::string> ColorMap::names() { return {"auto", "viridis", "cividis", "diverging", "rainbow"}; }

void ColorMap::require_name(std::string_view name) {
  if (name != "auto") named(name);
}

std::string ColorMap::for_range(std::string_view name, double low, double high) {
  if (name != "auto") return std::string(name);
  return low < 0.0 && high > 0.0 ? "diverging" : "viridis";
}

Rgb ColorMap::at(double t) const {
  t = std::clamp(t, 0.0, 1.0);
  const auto upper = std::upper_bound(stops_.begin(), stops_.end(), t,
                                      [](double value, const Stop& s) { return value < s.t; });
  if (upper == stops_.begin()) return stops_.front().color;
  if (upper == stops_.end()) return stops_.back().color;
  const Stop& a = *(upper - 1);
  const Stop& b = *upper;
  const double w = (t - a.t) / (b.t - a.t);
  return {a.color.r + w * (b.color.r - a.color.r), a.color.g + w * (b.color.g - a.color.g),
          a.color.b + w * (b.color.b - a.color.b)};
}

Rgb ColorMap::band(int k, int n) const {
  return n <= 1 ? at(0.5) : at(static_cast<double>(k) / static_cast<double>(n - 1));
}

std::vector<Rgb> ColorMap::band_colors(const std::vector<double>& levels) const {
  const int bands = static_cast<int>(levels.size()) - 1;
  std::vector<Rgb> colors;
  double largest = 0.0;
  for (const double l : levels) largest = std::max(largest, std::abs(l));
  for (int k = 0; k < bands; ++k) {
    if (!centred_on_zero_) {
      colors.push_back(band(k, bands));
    } else {
      const double middle = (levels[k] + levels[k + 1]) / 2.0;
      colors.push_back(at(largest > 0.0 ? 0.5 + middle / (2.0 * largest) : 0.5));
    }
  }
  return colors;
}

}  // namespace saasgaps::plot
