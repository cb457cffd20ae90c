#include "cli/common/http_client.hpp"

#include <csignal>

#include <nlohmann/json.hpp>

namespace saasgaps::cli {

namespace {

std::string string_member(const nlohmann::json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_string() ? it->get<std::string>() : std::string();
}

}  // namespace

ProblemError::ProblemError(int status, std::string title, std::string detail, std::vector<ProblemIssue> errors)
    : std::runtime_error(title + (detail.empty() ? "" : ": " + detail)),
      status_(status),
      title_(std::move(title)),
      detail_(std::move(detail)),
      errors_(std::move(errors)) {}

ProblemError problem_of(int status, const std::string& body) {
  const nlohmann::json j = nlohmann::json::parse(body, nullptr, false);
  if (!j.is_object() || !j.contains("title")) {
    // Not a problem document (a proxy's page, say): show its beginning rather than nothing.
    return {status, "unexpected answer", body.substr(0, 200), {}};
  }
  std::vector<ProblemIssue> errors;
  if (const auto list = j.find("errors"); list != j.end() && list->is_array()) {
    for (const nlohmann::json& e : *list) {
      if (e.is_object()) errors.push_back({string_member(e, "pointer"), string_member(e, "detail")});
    }
  }
  return {status, string_member(j, "title"), string_member(j, "detail"), std::move(errors)};
}

void EventStreamParser::feed(const char* data, std::size_t size) {
  pending_.append(data, size);
  std::size_t start = 0;
  for (std::size_t end; (end = pending_.find('\n', start)) != std::string::npos; start = end + 1) {
    std::string text = pending_.substr(start, end - start);
    if (!text.empty() && text.back() == '\r') text.pop_back();
    line(text);
  }
  pending_.erase(0, start);
}

void EventStreamParser::line(const std::string& text) {
  if (text.empty()) {  // a blank line ends an event
    if (has_data_) on_event_(event_);
    event_ = ServerEvent{};
    has_data_ = false;
    return;
  }
  if (text[0] == ':') return;  // a comment: the server's keep-alive
  const std::size_t colon = text.find(':');
  const std::string field = text.substr(0, colon);
  std::string value = colon == std::string::npos ? std::string() : text.substr(colon + 1);
  if (!value.empty() && value[0] == ' ') value.erase(0, 1);
  if (field == "data") {
    if (has_data_) event_.data += '\n';
    event_.data += value;
    has_data_ = true;
  } else if (field == "event") {
    event_.name = value;
  } else if (field == "id") {
    event_.id = value;
  }
}

ServiceClient::ServiceClient(const std::string& url, const std::string& token) : url_(url), client_(url) {
  if (!client_.is_valid() || url.rfind("http://", 0) != 0) {
    throw std::runtime_error("--server " + url + " is not an http://HOST:PORT URL");
  }
  // cpp-httplib 0.11 sends without MSG_NOSIGNAL: a server that answers before reading the whole
  // body (a 401, a 413) and closes would end this process with SIGPIPE instead of an error message.
  std::signal(SIGPIPE, SIG_IGN);
  client_.set_connection_timeout(std::chrono::seconds(10));
  // The event stream sends a keep-alive comment every 15 s; a minute of silence is a dead link.
  client_.set_read_timeout(std::chrono::seconds(60));
  client_.set_write_timeout(std::chrono::seconds(60));
  if (!token.empty()) client_.set_bearer_token_auth(token);
}

void ServiceClient::unreachable(const std::string& what, httplib::Error error) const {
  throw std::runtime_error(what + " " + url_ + " failed: " + httplib::to_string(error) +
                           " (is `saasgaps serve` running there? --server or SAASGAPS_SERVER name it)");
}

std::string ServiceClient::get(const std::string& path) {
  const httplib::Result r = client_.Get(path);
  if (!r) unreachable("GET " + path + " at", r.error());
  if (r->status / 100 != 2) throw problem_of(r->status, r->body);
  return r->body;
}

std::string ServiceClient::post_json(const std::string& path, const std::string& body, std::string* location) {
  const httplib::Result r = client_.Post(path, body, "application/json");
  if (!r) unreachable("POST " + path + " at", r.error());
  if (r->status / 100 != 2) throw problem_of(r->status, r->body);
  if (location != nullptr) *location = r->get_header_value("Location");
  return r->body;
}

bool ServiceClient::follow_events(const std::string& path, const std::string& last_event_id,
                                  const std::function<void(const ServerEvent&)>& on_event) {
  httplib::Headers headers;
  if (!last_event_id.empty()) headers.emplace("Last-Event-ID", last_event_id);
  int status = 0;
  std::string refusal;  // the body of an answer that is not a stream
  EventStreamParser parser(on_event);
  const httplib::Result r = client_.Get(
      path, headers,
      [&](const httplib::Response& response) {
        status = response.status;
        return true;
      },
      [&](const char* data, std::size_t size) {
        if (status == 200) {
          parser.feed(data, size);
        } else {
          refusal.append(data, size);
        }
        return true;
      });
  if (status != 0 && status != 200) throw problem_of(status, refusal);
  if (!r) {
    if (status == 0) unreachable("GET " + path + " at", r.error());
    return false;  // the stream was open and broke
  }
  return true;
}

}  // namespace saasgaps::cli
