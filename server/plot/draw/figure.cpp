#include "plot/draw/figure.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace saasgaps::plot {

Typography typography(const Canvas& canvas) {
  const double base = std::clamp(std::sqrt(static_cast<double>(canvas.width()) * canvas.height()) / 62.0, 10.0, 18.0);
  return {base, 0.85 * base, 1.3 * base, 1.2 * base};
}

Rect draw_header(const Canvas& canvas, std::string_view title, std::string_view subtitle) {
  const Typography t = typography(canvas);
  const double width = canvas.width() - 2.0 * t.margin;
  double y = 0.8 * t.margin;
  canvas.set_color(colors::text);
  canvas.text({t.margin, y}, canvas.fit_text(title, t.title, width, true), t.title, HAlign::left, VAlign::top, true);
  y += 1.35 * t.title;
  for (std::size_t begin = 0; begin < subtitle.size();) {
    const std::size_t end = std::min(subtitle.find('\n', begin), subtitle.size());
    canvas.text({t.margin, y}, canvas.fit_text(subtitle.substr(begin, end - begin), t.base, width), t.base,
                HAlign::left, VAlign::top);
    y += 1.4 * t.base;
    begin = end + 1;
  }
  return {0.0, y, static_cast<double>(canvas.width()), canvas.height() - y};
}

std::string run_summary(std::string_view status, int iterations) {
  const std::string count = std::to_string(iterations) + (iterations == 1 ? " iteration" : " iterations");
  if (status == "converged") return "converged in " + count;
  // A job followed live (the service draws its convergence from the rows stored so far).
  if (status == "running" || status == "queued" || status == "interrupted") return std::string(status) + ", " + count + " so far";
  return "NOT CONVERGED after " + count;
}

}  // namespace saasgaps::plot
