#pragma once
/// Errors as RFC 9457 problem details (application/problem+json), and the one place where
/// exceptions become HTTP responses.

#include <httplib.h>

#include <exception>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

namespace saasgaps::service {

/// A request the service refuses, with its HTTP status: raised by route handlers.
class HttpError : public std::runtime_error {
 public:
  HttpError(int status, std::string title, const std::string& detail, nlohmann::json errors = nullptr)
      : std::runtime_error(detail), status_(status), title_(std::move(title)), errors_(std::move(errors)) {}
  [[nodiscard]] int status() const { return status_; }
  [[nodiscard]] const std::string& title() const { return title_; }
  [[nodiscard]] const nlohmann::json& errors() const { return errors_; }

 private:
  int status_;
  std::string title_;
  nlohmann::json errors_;
};

/// Writes a problem document: {type, title, status, detail[, errors]}.
void write_problem(httplib::Response& res, int status, const std::string& title, const std::string& detail,
                   const nlohmann::json& errors = nullptr);

/// Maps any exception from a handler to its response: HttpError as raised, ModelError 422 with
/// every {pointer, detail}, io::MeshTooLarge 413 (at /mesh), JobNotFound 404, JobConflict 409, anything else 500.
void respond_to_exception(const httplib::Request& req, httplib::Response& res, std::exception_ptr error);

/// Fills an error status that has no body yet (404 of an unknown route, 413 from the size limit).
void fill_error_body(const httplib::Request& req, httplib::Response& res);

}  // namespace saasgaps::service
