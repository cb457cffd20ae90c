#pragma once
/// Colours and colour maps: a map takes t in [0, 1] to a colour by linear interpolation between
/// control points; band k of n takes t = k / (n - 1), so the end bands get the end colours.

#include <string>
#include <string_view>
#include <vector>

namespace saasgaps::plot {

struct Rgb {
  double r = 0.0, g = 0.0, b = 0.0;  ///< each 0 .. 1
};

/// Named colours used by several plots.
namespace colors {
inline constexpr Rgb white{1.0, 1.0, 1.0};
inline constexpr Rgb black{0.0, 0.0, 0.0};
inline constexpr Rgb text{0.10, 0.10, 0.10};
inline constexpr Rgb grid{0.88, 0.88, 0.88};
inline constexpr Rgb axis{0.30, 0.30, 0.30};
}  // namespace colors

/// Grey of the given lightness (0 black .. 1 white).
constexpr Rgb grey(double lightness) { return {lightness, lightness, lightness}; }

class ColorMap {
 public:
  struct Stop {
    double t;
    Rgb color;
  };

  /// By name: "viridis" (perceptually uniform: equal steps look equal, lightness rises steadily, so
  /// it prints in grey and reads with colour vision deficiency; the default), "cividis" (the same
  /// aims, blue to yellow, tuned for red-green deficiency) or "rainbow" (blue - cyan - green -
  /// yellow - red, the stress analyst's old convention, whose bright yellow and cyan bands look like
  /// features that are not there). Unknown names: std::invalid_argument.
  static ColorMap named(std::string_view name);
  static std::vector<std::string> names();

  /// Colour at t, clamped to [0, 1].
  Rgb at(double t) const;
  /// Colour of band k out of n (0 <= k < n).
  Rgb band(int k, int n) const;

 private:
  explicit ColorMap(std::vector<Stop> stops) : stops_(std::move(stops)) {}
  std::vector<Stop> stops_;
};

}  // namespace saasgaps::plot
