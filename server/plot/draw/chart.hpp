#pragma once
/// An x-y line chart in a rectangle of the canvas: axes with tick labels and titles, a light grid,
/// curves clipped to the plotting area, reference lines, and a legend column to the right of the
/// plot (outside it, so that it never hides a curve).

#include <string>
#include <vector>

#include "plot/draw/canvas.hpp"
#include "plot/draw/color_map.hpp"
#include "plot/draw/figure.hpp"

namespace saasgaps::plot {

struct Axis {
  double min = 0.0, max = 1.0;
  std::vector<double> ticks;
  std::vector<std::string> labels;  ///< one per tick
  std::string title;
};

/// Round ticks over [lo, hi] (at most max_ticks intervals), the range widened to the outer ticks.
Axis numeric_axis(double lo, double hi, std::string title, int max_ticks = 8);
/// Whole-number ticks (iterations, counts): the step is at least 1; the range reaches `padding`
/// beyond the end ticks (0.5 keeps the end markers off the frame).
Axis integer_axis(int lo, int hi, std::string title, int max_ticks = 10, double padding = 0.0);

/// A logarithmic axis over [lo, hi] (both > 0): its coordinates are log10 of the values (a series
/// on it gives log10 of its values), ticks at the decades (and at 2 and 5 of each when the range
/// spans fewer than three decades) labelled with the values themselves.
Axis log_axis(double lo, double hi, std::string title);

struct Series {
  std::string name;  ///< legend text; empty: not in the legend
  std::vector<double> x, y;
  Rgb color = colors::black;
  double width = 1.5;  ///< px
  bool dashed = false;
  bool markers = false;  ///< a dot at each point
};

/// Widths beside the plotting area, px: the y labels and title on the left, the legend on the right.
struct Gutters {
  double left = 0.0;
  double right = 0.0;
};

/// The legend entry of a reference line drawn with Chart::draw_reference.
Series reference_series(std::string name, Rgb color);

class Chart {
 public:
  /// The gutters a chart with this y axis and legend needs; charts stacked above one another take
  /// the larger of theirs, so that their plotting areas line up.
  static Gutters gutters_for(const Canvas& canvas, const Axis& y, const std::vector<Series>& legend);

  /// Lays the chart out in `area`: room for the y tick labels and title on the left, the x ones
  /// below, and a legend column for the named series on the right (at least `at_least`).
  Chart(const Canvas& canvas, Rect area, Axis x, Axis y, const std::vector<Series>& legend, Gutters at_least = {});

  Point to_device(double x, double y) const;
  const Rect& plot_area() const { return plot_; }
  const Axis& x_axis() const { return x_; }
  const Axis& y_axis() const { return y_; }

  /// Grid, frame, ticks with labels and axis titles.
  void draw_axes() const;
  void draw(const Series& series) const;
  /// A horizontal reference line across the plot (name it in the legend with reference_series).
  void draw_reference(double y, Rgb color) const;
  /// The legend column (named series of the constructor's list).
  void draw_legend() const;

 private:
  const Canvas& canvas_;
  Typography type_;
  Axis x_, y_;
  std::vector<Series> legend_;
  Rect plot_;
  Rect legend_area_;
};

}  // namespace saasgaps::plot
