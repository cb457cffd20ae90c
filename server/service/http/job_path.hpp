#pragma once
/// The job id in a request path (/v1/jobs/{id}/...), read one way for every route.

#include <httplib.h>

#include <cstdint>

namespace saasgaps::service {

/// The id of the route's first match, which the route pattern limits to digits. Only the canonical
/// decimal form names a job: no leading zeros, no percent-encoded digits (cpp-httplib decodes the
/// path before routing, so /v1/jobs/%31 would otherwise be job 1), at most INT64_MAX. Anything
/// else names no job: HttpError 404. One spelling per job keeps URLs, logs, ETags and caches in
/// agreement.
std::int64_t job_in_path(const httplib::Request& req);

}  // namespace saasgaps::service
