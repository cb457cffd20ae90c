#pragma once
/// What a request's query asks for, read one way for every route: integer parameters within bounds,
/// and the options of a plot. A value out of place is HttpError 400 naming the parameter.

#include <httplib.h>

#include <cstdint>
#include <optional>
#include <string>

#include "plot/pictures/plot_request.hpp"

namespace saasgaps::service {

/// An optional integer query parameter within [low, high]; 400 naming it otherwise.
std::optional<std::int64_t> integer_parameter(const httplib::Request& req, const std::string& name,
                                              std::int64_t low, std::int64_t high);

/// The plot a request asks for: the name and format from the path, options from the query.
plot::PlotRequest plot_request(const httplib::Request& req);

}  // namespace saasgaps::service
