#include "plot/pictures/plot_request.hpp"

#include <algorithm>
#include <charconv>
#include <stdexcept>

#include "plot/pictures/adaptation_plot.hpp"
#include "plot/pictures/contact_plot.hpp"
#include "plot/pictures/convergence_plot.hpp"
#include "plot/pictures/force_plot.hpp"
#include "plot/pictures/friction_plot.hpp"
#include "plot/result/field.hpp"

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

void set_centre(const std::string& text, PlanePoint& centre) {
  if (text.empty()) return;
  try {
    centre = parse_point(text);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("the centre is a point r,z (x,y in a plane model): ") + e.what());
  }
}

void set_gap_row(const std::string& ids, const std::string& along, GapRowOptions& row) {
  row.gap_ids = ids.empty() ? std::vector<int>{} : parse_gap_ids(ids);
  if (!along.empty()) row.along = row_axis(along);
}

std::vector<std::string> plot_names() {
  std::vector<std::string> names;
  for (const FieldInfo& f : fields()) names.emplace_back(f.name);
  names.emplace_back("convergence");
  names.emplace_back("friction");
  names.emplace_back("force");
  names.emplace_back("adaptation");
  return names;
}

io::ResultSelection result_selection_for(const PlotRequest& request) {
  // The convergence plot reads the history and the gaps, the friction plot the contact pairs: no mesh.
  if (request.name == "convergence" || request.name == "friction" || request.name == "force" ||
      request.name == "adaptation") {
    return {.mesh = false, .element_keys = {}};
  }
  // Every other plot draws the mesh (result_mesh.cpp), and an element field reads its stored
  // values (field.cpp). (Callers have checked the name: every plot but convergence is a field.)
  io::ResultSelection selection;
  for (const std::string_view k : element_keys(find_field(request.name))) selection.element_keys.emplace_back(k);
  return selection;
}

void require_plot_name(const std::string& name) {
  const std::vector<std::string> names = plot_names();
  if (std::find(names.begin(), names.end(), name) != names.end()) return;
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown field '" + name + "'; fields: " + list);
}

namespace {

/// Draws the plot; for the line plots that have one, returns their data table.
std::optional<DataTable> draw(const Canvas& canvas, const PlotResult& result, const PlotRequest& request) {
  require_plot_name(request.name);
  if (request.path) {
    if (request.name == "convergence" || request.name == "friction" || request.name == "force" ||
        request.name == "adaptation") {
      throw std::invalid_argument("the " + request.name + " plot does not run along a path");
    }
    return draw_path_plot(canvas, result, request.name, *request.path, request.centre);
  }
  if (request.name == "convergence") {
    draw_convergence_plot(canvas, result.document());
  } else if (request.name == "friction") {
    return draw_friction_plot(canvas, result.document());
  } else if (request.name == "force") {
    return draw_force_plot(canvas, result.document(), request.set);
  } else if (request.name == "adaptation") {
    return draw_adaptation_plot(canvas, result.document());
  } else if (request.name == "contact_pressure") {
    return draw_contact_plot(canvas, result, request.row);
  } else if (request.name == "closure") {
    // Contact surfaces have no closure history: their closure is the gap along side A.
    if (array_member(result.document(), "gaps").empty() && has_contact_points(result.document())) {
      return draw_surface_contact_plot(canvas, result.document(), request.row.along);
    }
    return draw_closure_plot(canvas, result, request.row, request.closure);
  } else {
    ContourOptions contour = request.contour;
    contour.field = request.name;
    contour.centre = request.centre;
    draw_contour_plot(canvas, result, contour);
  }
  return std::nullopt;
}

}  // namespace

std::string render_plot(const PlotResult& result, const PlotRequest& request) {
  Canvas canvas(request.format, request.width, request.height);
  draw(canvas, result, request);
  return canvas.finish();
}

std::string render_table(const PlotResult& result, const PlotRequest& request) {
  // The table gives px positions: lay the plot out on a canvas of the image's size, never encoded.
  Canvas canvas(ImageFormat::png, request.width, request.height);
  const std::optional<DataTable> table = draw(canvas, result, request);
  if (!table) {
    throw std::invalid_argument("a data table (.csv) is made for closure, contact_pressure, friction, force, adaptation and a "
                                "field along a path, "
                                "not for '" + request.name + "'");
  }
  return table->csv();
}

}  // namespace saasgaps::plot
