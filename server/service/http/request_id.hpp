#pragma once
/// Request ids: the client's X-Request-Id when it is a sensible token (1-128 characters from
/// [A-Za-z0-9._:-]), else a new random one (16 hex digits). Echoed in the X-Request-Id response
/// header and written in every log line about the request.

#include <httplib.h>

#include <string>

namespace saasgaps::service {

std::string request_id(const httplib::Request& req);

}  // namespace saasgaps::service
