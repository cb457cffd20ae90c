#pragma once
/// Checks every request's head before routing (cpp-httplib's pre-routing handler), in this order:
/// 1. message framing: two Content-Length values that differ, or Content-Length together with
///    Transfer-Encoding, are refused (400, RFC 9112 section 6.3): a proxy and this server could
///    otherwise read different requests out of the same bytes; a Content-Length beyond --max-body
///    is refused (413) before a byte of the body is read;
/// 2. Host: without a token the server answers only to the names it listens on (loopback names, the
///    --host address, and --allow-host names), so a DNS-rebinding page cannot reach it (421);
/// 3. Origin: a state-changing request (POST, PUT, PATCH, DELETE) whose Origin is not this server is
///    refused (403): a page elsewhere cannot submit, cancel or delete jobs;
/// 4. Content-Type: a POST with a body must say JSON (415): an HTML form cannot send one (the
///    upload route POST /v1/imports takes only multipart/form-data, guarded by rule 3, and answers
///    415 to any other body, JSON included; the remote worker
///    routes POST /v1/jobs/{id}/lease and /work/{iterations,finish} take application/cbor);
/// 5. Idempotency-Key: printable ASCII, 1 to 255 characters (400);
/// 6. authentication, with a token: `Authorization: Bearer TOKEN` (scheme case-insensitive, RFC 9110
///    section 11.1), or `?access_token=TOKEN` on the GET links the dashboard opens without headers
///    (event streams, plots and downloads of one job).
/// A refused request's body is never read, so its connection is closed after the answer.

#include <httplib.h>

#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace saasgaps::service {

struct GuardOptions {
  std::optional<std::string> token;
  std::string listen_host = "127.0.0.1";
  std::vector<std::string> allowed_hosts;  ///< extra Host names accepted without a token
  std::size_t max_body = std::numeric_limits<std::size_t>::max();  ///< --max-body, bytes
};

class RequestGuard {
 public:
  explicit RequestGuard(GuardOptions options);

  /// Writes the refusal into `res` and returns false when the request must not be served.
  bool admit(const httplib::Request& req, httplib::Response& res) const;

 private:
  [[nodiscard]] bool host_allowed(const std::string& host_header) const;
  [[nodiscard]] bool origin_allowed(const httplib::Request& req) const;
  [[nodiscard]] bool authorized(const httplib::Request& req) const;

  GuardOptions options_;
};

/// Whether ?access_token= may stand in for the Authorization header on this request.
bool accepts_access_token(const std::string& method, const std::string& path);

/// The host part of a Host header or an Origin's authority, lower case, without port or brackets.
std::string host_name(std::string_view authority);

}  // namespace saasgaps::service
