#pragma once
/// What every figure shares: type sizes that scale with the image, and the title block at the top.

#include <string>
#include <string_view>

#include "plot/draw/canvas.hpp"

namespace saasgaps::plot {

/// Type sizes in px. base = clamp(sqrt(width height) / 62, 10, 18): about 16 px on 1200 x 800, so
/// labels stay legible when the image is shrunk into a report page.
struct Typography {
  double base;
  double small;  ///< 0.85 base: tick labels, legends
  double title;  ///< 1.3 base, bold
  double margin; ///< 1.2 base: space round panels
};

Typography typography(const Canvas& canvas);

/// Draws the title (bold) and the subtitle lines (separated by '\n') under it, each shortened to fit
/// the width, and returns the area below them.
Rect draw_header(const Canvas& canvas, std::string_view title, std::string_view subtitle);

/// A status note for subtitles: "converged in 10 iterations", "NOT CONVERGED after 40 iterations", or
/// for a job still going "running, 3 iterations so far".
std::string run_summary(std::string_view status, int iterations);

}  // namespace saasgaps::plot
