#include "service/http/problem.hpp"

#include "io/json/json_limits.hpp"
#include "io/json/json_text.hpp"
#include "io/mesher/gmsh_mesh.hpp"
#include "io/model/model_reader.hpp"
#include "service/ops/log.hpp"
#include "service/runs/metrics.hpp"
#include "service/store/job_store.hpp"
#include "solver/base/errors.hpp"
#include "solver/base/plural.hpp"

namespace saasgaps::service {

using nlohmann::json;

namespace {
const char* reason(int status) {
  switch (status) {
    case 400: return "Bad Request";
    case 401: return "Unauthorized";
    case 404: return "Not Found";
    case 405: return "Method Not Allowed";
    case 409: return "Conflict";
    case 413: return "Content Too Large";
    case 422: return "Unprocessable Content";
    case 503: return "Service Unavailable";
    case 507: return "Insufficient Storage";
    default: return status >= 500 ? "Internal Server Error" : "Error";
  }
}
}  // namespace

void write_problem(httplib::Response& res, int status, const std::string& title, const std::string& detail,
                   const json& errors) {
  json body = {{"type", "about:blank"}, {"title", title}, {"status", status}, {"detail", detail}};
  if (!errors.is_null()) body["errors"] = errors;
  res.status = status;
  res.set_content(io::json_text(body), "application/problem+json");
}

void respond_to_exception(const httplib::Request& req, httplib::Response& res, std::exception_ptr error) {
  try {
    std::rethrow_exception(error);
  } catch (const HttpError& e) {
    write_problem(res, e.status(), e.title(), e.what(), e.errors());
  } catch (const io::NotJsonText& e) {
    // The issue reads "the document is not valid JSON: <the parser's message> (byte N)".
    std::string detail = e.issues().front().detail;
    if (const auto colon = detail.find(": "); colon != std::string::npos) detail.erase(0, colon + 2);
    write_problem(res, 400, "Bad Request", "the request body is not JSON: " + detail, nullptr);
  } catch (const io::NestingTooDeep& e) {
    // 422, not 413: the body is within --max-body and is JSON; one of its values breaks a documented
    // rule of every document (docs/operations.md, "Limits"), at a place the client can find.
    const InputIssue& issue = e.issues().front();
    write_problem(res, 422, "Document nested too deeply", issue.pointer + ": " + issue.detail,
                  json::array({{{"pointer", issue.pointer}, {"detail", issue.detail}}}));
  } catch (const ModelError& e) {
    json errors = json::array();
    for (const InputIssue& issue : e.issues()) errors.push_back({{"pointer", issue.pointer}, {"detail", issue.detail}});
    // Titled by the document the pointers point into: "Invalid assembly", "2 errors in the assembly
    // document"; resume settings are a request body, not a document.
    const std::string& document = e.document();
    write_problem(res, 422, "Invalid " + document,
                  plural(static_cast<long long>(e.issues().size()), "error") + " in the " + document +
                      (document == "resume settings" ? "" : " document"),
                  errors);
  } catch (const io::MeshTooLarge& e) {
    write_problem(res, 413, "Content Too Large", e.what(), json::array({{{"pointer", "/mesh"}, {"detail", e.what()}}}));
  } catch (const JobNotFound& e) {
    write_problem(res, 404, "Not Found", e.what());
  } catch (const JobConflict& e) {
    write_problem(res, 409, "Conflict", e.what());
  } catch (const StoreUnavailable& e) {
    res.set_header("Retry-After", "60");
    write_problem(res, 503, "Service Unavailable", e.what());
  } catch (const StoreError& e) {
    Metrics::global().count_store_error();
    log_error("store_error", {{"method", req.method}, {"path", req.path}, {"error", e.what()},
                              {"request_id", res.get_header_value("X-Request-Id")}});
    if (e.no_space()) {
      write_problem(res, 507, "Insufficient Storage",
                    req.method + " " + req.path + ": the database could not be written (" + e.what() +
                        "); nothing was changed. Free disk space and retry.");
    } else {
      write_problem(res, 500, "Internal Server Error", req.method + " " + req.path + " failed: " + e.what());
    }
  } catch (const std::exception& e) {
    log_error("request_failed", {{"method", req.method}, {"path", req.path}, {"error", e.what()},
                                 {"request_id", res.get_header_value("X-Request-Id")}});
    write_problem(res, 500, "Internal Server Error", std::string(req.method + " " + req.path + " failed: ") + e.what());
  } catch (...) {
    write_problem(res, 500, "Internal Server Error", req.method + " " + req.path + " failed");
  }
}

void fill_error_body(const httplib::Request& req, httplib::Response& res) {
  if (!res.body.empty()) return;
  std::string detail = req.method + " " + req.path;
  switch (res.status) {
    case 404: detail += ": no such resource"; break;
    case 413: detail += ": the request body is larger than the server accepts (--max-body)"; break;
    case 400:
      detail += req.has_header("Content-Length") ? ": the request could not be read"
                                                 : ": a POST needs a body, even an empty one (curl -d '' or --json '{}')";
      break;
    default: detail += ": " + std::string(reason(res.status)); break;
  }
  write_problem(res, res.status, reason(res.status), detail);
}

}  // namespace saasgaps::service
