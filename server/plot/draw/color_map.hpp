#pragma once
/// Colours and colour maps: a map takes t in [0, 1] to a colour by linear interpolation between
/// control points. A sequential map colours band k of n at t = k / (n - 1), so the end bands get
/// the end colours; the diverging map colours a band by its value (band_colors).

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
  /// it prints in grey and reads with colour vision deficiency; the default for fields that do not
  /// change sign), "cividis" (the same aims, blue to yellow, tuned for red-green deficiency),
  /// "diverging" (ColorBrewer's RdBu: blue for negative through near-white at zero to red for
  /// positive, lightness falling symmetrically both ways; the default for fields that change sign)
  /// or "rainbow" (blue - cyan - green - yellow - red, the stress analyst's old convention, whose
  /// bright yellow and cyan bands look like features that are not there). "auto" is not a map:
  /// resolve it with for_range first. Unknown names: std::invalid_argument.
  static ColorMap named(std::string_view name);
  /// The maps' names, and "auto".
  static std::vector<std::string> names();
  /// Throws named()'s std::invalid_argument unless name is one of names().
  static void require_name(std::string_view name);
  /// "auto" resolved for a field's range: "diverging" when it spans zero (low < 0 < high), so that
  /// the sign reads at a glance; "viridis" otherwise. Any other name is returned as it is.
  static std::string for_range(std::string_view name, double low, double high);

  /// Colour at t, clamped to [0, 1].
  Rgb at(double t) const;
  /// Colour of band k out of n (0 <= k < n) of a sequential map.
  Rgb band(int k, int n) const;
  /// The colours of the bands between increasing levels. A sequential map: band(k, n). The
  /// diverging map is centred on zero: a band whose middle value is v gets t = 1/2 + v / (2 M),
  /// M = max |level|, so zero is the centre colour, the sign is the hue, and equal magnitudes of
  /// either sign are equally dark.
  std::vector<Rgb> band_colors(const std::vector<double>& levels) const;
  bool centred_on_zero() const { return centred_on_zero_; }

 private:
  ColorMap(std::vector<Stop> stops, bool centred_on_zero = false)
      : stops_(std::move(stops)), centred_on_zero_(centred_on_zero) {}
  std::vector<Stop> stops_;
  bool centred_on_zero_ = false;
};

}  // namespace saasgaps::plot
