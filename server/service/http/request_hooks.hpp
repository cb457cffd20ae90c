#pragma once
/// What runs around every route: the pre-routing guard (request ids, RequestGuard's checks, 405
/// before the body of a method no route takes is read), problem details for exceptions and for
/// errors without a body (405 naming the methods a path has), and the access log with the request
/// counters.

#include <httplib.h>

#include "service/http/request_guard.hpp"

namespace saasgaps::service {

/// Sets the server's exception, error and pre-routing handlers and its logger; `guard` must outlive
/// the server.
void install_request_hooks(httplib::Server& server, const RequestGuard& guard);

}  // namespace saasgaps::service
