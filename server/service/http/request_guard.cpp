#include "service/http/request_guard.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <regex>

#include "service/http/guarded_server.hpp"
#include "service/http/problem.hpp"
#include "web/web_assets.hpp"

namespace saasgaps::service {

namespace {

std::string lower(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

/// Compares every byte whatever the first difference, so timing does not reveal the token.
bool same_secret(const std::string& given, const std::string& expected) {
  unsigned char difference = given.size() == expected.size() ? 0 : 1;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    difference |= static_cast<unsigned char>(expected[i] ^ (i < given.size() ? given[i] : 0));
  }
  return difference == 0;
}

/// Whether a Content-Length value is at most `limit`. Text that is not a decimal count is left to
/// cpp-httplib (400); a count beyond 64 bits is beyond any limit.
bool fits(const std::string& length, std::size_t limit) {
  std::uint64_t bytes = 0;
  const auto [end, error] = std::from_chars(length.data(), length.data() + length.size(), bytes);
  if (error == std::errc::result_out_of_range) return false;
  return error != std::errc() || end != length.data() + length.size() || bytes <= limit;
}

bool is_public(const std::string& path) {
  if (path == "/healthz" || path == "/readyz") return true;
  for (const web::Asset& asset : web::assets()) {
    if (path == asset.path) return true;
  }
  return false;
}

bool changes_state(const std::string& method) {
  return method == "POST" || method == "PUT" || method == "PATCH" || method == "DELETE";
}

/// The media type of a Content-Type value, lower case, without parameters.
std::string bare_media_type(const std::string& content_type) {
  const std::string type = lower(content_type.substr(0, content_type.find(';')));
  const auto last = type.find_last_not_of(" \t");
  return type.substr(0, last == std::string::npos ? 0 : last + 1);
}

bool is_json_media_type(const std::string& content_type) {
  const std::string bare = bare_media_type(content_type);
  return bare == "application/json" || (bare.rfind("application/", 0) == 0 && bare.size() > 5 &&
                                        bare.compare(bare.size() - 5, 5, "+json") == 0);
}

bool is_media_type(const std::string& content_type, const std::string& type) { return bare_media_type(content_type) == type; }

/// The routes of the remote worker protocol (worker_api.cpp) that take a body.
bool is_worker_route(const std::string& path) {
  static const std::regex worker(R"(/v1/jobs/\d+/(lease|work/iterations|work/thermal|work/finish))");
  return std::regex_match(path, worker);
}

void refuse(httplib::Response& res, int status, const std::string& title, const std::string& detail) {
  res.set_header("Connection", "close");
  GuardedServer::close_after_response();
  write_problem(res, status, title, detail);
}

}  // namespace

std::string host_name(std::string_view authority) {
  std::string host = lower(authority);
  if (!host.empty() && host.front() == '[') {
    const auto close = host.find(']');
    return close == std::string::npos ? host : host.substr(1, close - 1);
  }
  // One colon separates the port; more colons are an unbracketed IPv6 address.
  const auto colon = host.find(':');
  if (colon != std::string::npos && host.find(':', colon + 1) == std::string::npos) host.erase(colon);
  return host;
}

bool accepts_access_token(const std::string& method, const std::string& path) {
  static const std::regex links(R"(/v1/jobs/\d+/(events|model|iterations|result|result\.vtu|plots/\w+\.(png|svg)))");
  return (method == "GET" || method == "HEAD") && std::regex_match(path, links);
}

RequestGuard::RequestGuard(GuardOptions options) : options_(std::move(options)) {
  for (std::string& h : options_.allowed_hosts) h = host_name(h);
}

bool RequestGuard::host_allowed(const std::string& host_header) const {
  const std::string host = host_name(host_header);
  if (host == "localhost" || host == "::1" || host.rfind("127.", 0) == 0) return true;
  if (host == host_name(options_.listen_host)) return true;
  return std::find(options_.allowed_hosts.begin(), options_.allowed_hosts.end(), host) != options_.allowed_hosts.end();
}

bool RequestGuard::origin_allowed(const httplib::Request& req) const {
  if (!req.has_header("Origin")) return true;  // not sent by a browser page: nothing cross-site
  const std::string origin = lower(req.get_header_value("Origin"));
  const auto scheme = origin.find("://");
  if (scheme == std::string::npos) return false;  // "null" and other opaque origins
  // Same origin: the page was loaded from the very authority this request is sent to.
  return origin.substr(scheme + 3) == lower(req.get_header_value("Host"));
}

bool RequestGuard::authorized(const httplib::Request& req) const {
  if (!options_.token || is_public(req.path)) return true;
  const std::string header = req.get_header_value("Authorization");
  if (!header.empty()) {
    const auto space = header.find(' ');
    if (space == std::string::npos || lower(header.substr(0, space)) != "bearer") return false;
    const auto start = header.find_first_not_of(' ', space);
    return start != std::string::npos && same_secret(header.substr(start), *options_.token);
  }
  // EventSource, <img> and download links cannot send headers: the page passes the token in the URL.
  if (req.has_param("access_token") && accepts_access_token(req.method, req.path)) {
    return same_secret(req.get_param_value("access_token"), *options_.token);
  }
  return false;
}

bool RequestGuard::admit(const httplib::Request& req, httplib::Response& res) const {
  const auto lengths = req.headers.equal_range("Content-Length");
  for (auto it = lengths.first; it != lengths.second; ++it) {
    if (it->second != lengths.first->second) {
      refuse(res, 400, "Bad Request", "the request has Content-Length values that differ; send one");
      return false;
    }
  }
  if (lengths.first != lengths.second && req.has_header("Transfer-Encoding")) {
    refuse(res, 400, "Bad Request", "the request has both Content-Length and Transfer-Encoding; send one of them");
    return false;
  }
  if (lengths.first != lengths.second && !fits(lengths.first->second, options_.max_body)) {
    // cpp-httplib would skip a body beyond its limit by reading it, until the body deadline closes
    // the connection without an answer (issue 17: a Content-Length of 10^12).
    refuse(res, 413, "Content Too Large",
           "the request body of Content-Length " + lengths.first->second + " bytes is larger than the " +
               std::to_string(options_.max_body) + " bytes the server accepts (--max-body)");
    return false;
  }
  if (req.get_header_value_count("Host") > 1) {
    refuse(res, 400, "Bad Request", "the request has more than one Host header");
    return false;
  }
  if (!options_.token && !host_allowed(req.get_header_value("Host"))) {
    refuse(res, 421, "Misdirected Request",
           "this server does not answer to the host \"" + req.get_header_value("Host") +
               "\"; it answers to loopback names and " + options_.listen_host + " (add names with --allow-host)");
    return false;
  }
  if (changes_state(req.method) && !origin_allowed(req)) {
    refuse(res, 403, "Forbidden",
           "cross-site request refused: Origin " + req.get_header_value("Origin") + " is not this server");
    return false;
  }
  const bool has_body = (req.has_header("Content-Length") && req.get_header_value("Content-Length") != "0") ||
                        req.has_header("Transfer-Encoding");
  // The upload routes take multipart/form-data (an assembly, or a study of one, and its mesh
  // files); a foreign page posting a form there is stopped by the Origin rule above.
  const bool imports = req.path == "/v1/imports";
  const bool upload = (imports || req.path == "/v1/studies") &&
                      lower(req.get_header_value("Content-Type")).rfind("multipart/form-data", 0) == 0;
  // Remote workers post CBOR (worker_protocol.hpp) to their own routes, which an HTML form cannot
  // reach with a body they accept either.
  const bool worker_body = is_worker_route(req.path) && is_media_type(req.get_header_value("Content-Type"), "application/cbor");
  if (req.method == "POST" && has_body && imports && !upload) {
    refuse(res, 415, "Unsupported Media Type",
           "POST /v1/imports takes multipart/form-data (a part \"assembly\" and one part per file it names, "
           "e.g. curl -F assembly=@a.json -F mesh=@a.msh), got \"" + req.get_header_value("Content-Type") + "\"");
    return false;
  }
  if (req.method == "POST" && has_body && !upload && !worker_body && !is_json_media_type(req.get_header_value("Content-Type"))) {
    refuse(res, 415, "Unsupported Media Type",
           "a POST body must be JSON (Content-Type: application/json), got \"" + req.get_header_value("Content-Type") + "\"");
    return false;
  }
  if (req.has_header("Idempotency-Key")) {
    const std::string key = req.get_header_value("Idempotency-Key");
    const bool printable = std::all_of(key.begin(), key.end(), [](char c) { return c >= 0x20 && c <= 0x7e; });
    if (key.empty() || key.size() > 255 || !printable) {
      refuse(res, 400, "Bad Request", "Idempotency-Key must be 1 to 255 printable ASCII characters");
      return false;
    }
  }
  if (!authorized(req)) {
    res.set_header("WWW-Authenticate", "Bearer");
    refuse(res, 401, "Unauthorized", "this server requires an Authorization: Bearer token");
    return false;
  }
  return true;
}

}  // namespace saasgaps::service
