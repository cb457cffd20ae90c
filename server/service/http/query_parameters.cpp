#include "service/http/query_parameters.hpp"

#include <charconv>
#include <stdexcept>

#include "plot/draw/color_map.hpp"
#include "service/http/problem.hpp"

namespace saasgaps::service {

std::optional<std::int64_t> integer_parameter(const httplib::Request& req, const std::string& name,
                                              std::int64_t low, std::int64_t high) {
  if (!req.has_param(name)) return std::nullopt;
  const std::string text = req.get_param_value(name);
  std::int64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value < low || value > high) {
    throw HttpError(400, "Bad Request",
                    "query parameter " + name + " must be an integer from " + std::to_string(low) + " to " +
                        std::to_string(high) + ", got \"" + text + "\"");
  }
  return value;
}

plot::PlotRequest plot_request(const httplib::Request& req) {
  plot::PlotRequest request;
  request.name = req.matches[2];
  request.format = req.matches[3] == "svg" ? plot::ImageFormat::svg : plot::ImageFormat::png;
  constexpr int least = plot::Canvas::min_side, most = plot::Canvas::max_side;
  request.width = static_cast<int>(integer_parameter(req, "width", least, most).value_or(request.width));
  request.height = static_cast<int>(integer_parameter(req, "height", least, most).value_or(request.height));
  request.contour.max_bands = static_cast<int>(integer_parameter(req, "bands", 2, 40).value_or(request.contour.max_bands));
  request.contour.mesh = req.get_param_value("mesh") == "1" || req.get_param_value("mesh") == "true";
  const int samples = static_cast<int>(integer_parameter(req, "samples", 2, 100000).value_or(201));
  try {
    plot::set_deformation(req.get_param_value("deformed"), request.contour);
    if (req.has_param("colormap")) {
      request.contour.color_map = req.get_param_value("colormap");
      plot::ColorMap::require_name(request.contour.color_map);
    }
    if (req.has_param("levels")) request.contour.levels = plot::level_rule(req.get_param_value("levels"));
    plot::set_centre(req.get_param_value("centre"), request.centre);
    plot::set_gap_row(req.get_param_value("gaps"), req.get_param_value("along"), request.row);
    if (req.has_param("path")) request.path = plot::PathOptions{plot::parse_path(req.get_param_value("path")), samples};
  } catch (const std::invalid_argument& e) {
    throw HttpError(400, "Bad Request",
                    std::string("query parameters deformed, colormap, levels, centre, gaps, along, path: ") + e.what());
  }
  return request;
}

}  // namespace saasgaps::service
