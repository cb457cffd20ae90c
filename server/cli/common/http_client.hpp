#pragma once
/// The command line's side of the HTTP API (docs/http-api.md): requests to a `saasgaps serve` at a
/// URL with an optional bearer token, refusals as ProblemError (the RFC 9457 problem document the
/// server answered), and the Server-Sent Events of a job read one event at a time.

#include <httplib.h>

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace saasgaps::cli {

/// One entry of a problem's `errors`: where in the document, and what is wrong there.
struct ProblemIssue {
  std::string pointer;
  std::string detail;
};

/// The server refused a request: its status and problem document (title, detail, errors). Where
/// the answer was not a problem document, title is the status line and detail the start of the body.
class ProblemError : public std::runtime_error {
 public:
  ProblemError(int status, std::string title, std::string detail, std::vector<ProblemIssue> errors);
  [[nodiscard]] int status() const { return status_; }
  [[nodiscard]] const std::string& title() const { return title_; }
  [[nodiscard]] const std::string& detail() const { return detail_; }
  [[nodiscard]] const std::vector<ProblemIssue>& errors() const { return errors_; }

 private:
  int status_;
  std::string title_;
  std::string detail_;
  std::vector<ProblemIssue> errors_;
};

/// The ProblemError for an answer with a status outside 2xx.
ProblemError problem_of(int status, const std::string& body);

/// One Server-Sent Event: its id (empty when none), event name ("message" when none) and data.
struct ServerEvent {
  std::string id;
  std::string name = "message";
  std::string data;
};

/// Splits a text/event-stream into events as its bytes arrive (in chunks cut anywhere). Comment
/// lines (": keep-alive") are skipped; multi-line data is joined with '\n' (the SSE rules).
class EventStreamParser {
 public:
  explicit EventStreamParser(std::function<void(const ServerEvent&)> on_event) : on_event_(std::move(on_event)) {}
  void feed(const char* data, std::size_t size);

 private:
  void line(const std::string& text);
  std::function<void(const ServerEvent&)> on_event_;
  std::string pending_;  // a line not yet ended
  ServerEvent event_;
  bool has_data_ = false;
};

/// A service at a URL. Connection failures throw std::runtime_error naming the URL; answers outside
/// 2xx throw ProblemError.
class ServiceClient {
 public:
  /// `url` is http://HOST:PORT; `token` (may be empty) is sent as a bearer token.
  ServiceClient(const std::string& url, const std::string& token);

  /// The body of a successful answer; `location` (optional) receives its Location header.
  std::string get(const std::string& path);
  std::string post_json(const std::string& path, const std::string& body, std::string* location = nullptr);

  /// Reads the event stream at `path` until the server ends it, handing each event to `on_event`.
  /// Returns false when the connection broke before the server ended the stream.
  bool follow_events(const std::string& path, const std::string& last_event_id,
                     const std::function<void(const ServerEvent&)>& on_event);

  [[nodiscard]] const std::string& url() const { return url_; }

 private:
  [[noreturn]] void unreachable(const std::string& what, httplib::Error error) const;
  std::string url_;
  httplib::Client client_;
};

}  // namespace saasgaps::cli
