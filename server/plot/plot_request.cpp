#include "plot/plot_request.hpp"

#include <algorithm>
#include <charconv>
#include <stdexcept>

#include "plot/convergence_plot.hpp"
#include "plot/field.hpp"

namespace saasgaps::plot {

void set_deformation(const std::string& text, ContourOptions& contour) {
  if (text.empty()) return;
  if (text == "auto") {
    contour.automatic_deformation = true;
    return;
  }
  double scale = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), scale);
  if (error != std::errc() || end != text.data() + text.size() || !(scale > 0.0)) {
    throw std::invalid_argument("the deformation takes a positive magnification or 'auto', not '" + text + "'");
  }
  contour.deformation_scale = scale;
}

ClosureAxis closure_axis(const std::string& name) {
  if (name == "index") return ClosureAxis::gap_index;
  if (name == "position") return ClosureAxis::position;
  throw std::invalid_argument("the closure plot runs along 'index' or 'position', not '" + name + "'");
}

std::vector<std::string> plot_names() {
  std::vector<std::string> names;
  for (const FieldInfo& f : fields()) names.emplace_back(f.name);
  names.emplace_back("convergence");
  return names;
}

void require_plot_name(const std::string& name) {
  const std::vector<std::string> names = plot_names();
  if (std::find(names.begin(), names.end(), name) != names.end()) return;
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown field '" + name + "'; fields: " + list);
}

std::string render_plot(const nlohmann::json& result, const PlotRequest& request) {
  require_plot_name(request.name);
  Canvas canvas(request.format, request.width, request.height);
  if (request.name == "convergence") {
    draw_convergence_plot(canvas, result);
  } else if (find_field(request.name).location == FieldLocation::gap) {
    draw_closure_plot(canvas, result, request.closure);
  } else {
    ContourOptions contour = request.contour;
    contour.field = request.name;
    draw_contour_plot(canvas, result, contour);
  }
  return canvas.finish();
}

}  // namespace saasgaps::plot
