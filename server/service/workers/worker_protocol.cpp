#include "service/workers/worker_protocol.hpp"

#include <charconv>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string_view>

#include "io/json/fingerprint.hpp"
#include "io/json/json_limits.hpp"

#include "io/restart/read_card.hpp"
#include "io/restart/state_codec.hpp"

namespace saasgaps::service::worker_protocol {

using nlohmann::json;

namespace {

/// The body as a tree, within io::max_json_depth (the decoder recurses per level: io/json_limits.hpp).
/// Throws io::NestingTooDeep (422) past the limit.
json decode(const std::string& body) {
  json j;
  try {
    j = io::parse_cbor(std::string_view(body));
  } catch (const json::exception&) {
    throw std::invalid_argument("the body is not a CBOR map");
  }
  if (!j.is_object()) throw std::invalid_argument("the body is not a CBOR map");
  return j;
}

/// Whether the JSON text in the body's member `name` is JSON within io::max_json_depth: the service
/// stores it and serves it (and parses it for plots), so it must be as good as what it writes itself.
void require_json(const std::string& text, const char* name) {
  try {
    if (io::accept_json(text)) return;
  } catch (const io::NestingTooDeep& e) {
    const InputIssue& issue = e.issues().front();
    throw io::NestingTooDeep({{issue.pointer, std::string("in the JSON text of the body's \"") + name + "\": " + issue.detail}});
  }
  throw std::invalid_argument(std::string("the body's \"") + name + "\" is not JSON");
}

template <class T>
T field(const json& j, const char* name) {
  if (!j.contains(name)) throw std::invalid_argument(std::string("the body has no \"") + name + "\"");
  try {
    return j.at(name).get<T>();
  } catch (const json::exception&) {
    throw std::invalid_argument(std::string("the body's \"") + name + "\" has the wrong type");
  }
}

std::optional<std::string> optional_text(const json& j, const char* name) {
  if (!j.contains(name) || j.at(name).is_null()) return std::nullopt;
  return field<std::string>(j, name);
}

std::vector<std::uint8_t> bytes(const json& j, const char* name) {
  if (!j.contains(name) || !j.at(name).is_binary()) {
    throw std::invalid_argument(std::string("the body's \"") + name + "\" must be a byte string");
  }
  return j.at(name).get_binary();
}

}  // namespace

std::string body_digest(const std::string& body) {
  io::Fingerprint f;
  f.add(body);
  return f.hex();
}

std::string format_lease(const Lease& lease) { return std::to_string(lease.attempt) + ":" + lease.secret; }

std::optional<Lease> parse_lease(std::string_view text) {
  const auto colon = text.find(':');
  if (colon == std::string_view::npos || colon + 1 == text.size()) return std::nullopt;
  Lease lease;
  const auto [end, error] = std::from_chars(text.data(), text.data() + colon, lease.attempt);
  if (error != std::errc() || end != text.data() + colon || lease.attempt < 1) return std::nullopt;
  lease.secret = std::string(text.substr(colon + 1));
  return lease;
}

std::string encode_work(const ClaimedJob& claimed) {
  json j = {{"job", claimed.job.id},
            {"attempt", claimed.lease.attempt},
            {"model", claimed.model},
            {"state", claimed.state ? json::binary(*claimed.state) : json(nullptr)},
            {"settings", io::stored_read_card_text(claimed.job.settings)}};
  const std::vector<std::uint8_t> cbor = json::to_cbor(j);
  return {cbor.begin(), cbor.end()};
}

Work decode_work(const std::string& body) {
  const json j = decode(body);
  Work work;
  work.job = field<std::int64_t>(j, "job");
  work.attempt = field<int>(j, "attempt");
  work.input.model = field<std::string>(j, "model");
  if (!j.at("state").is_null()) work.input.state = bytes(j, "state");
  work.input.settings = io::stored_read_card(field<std::string>(j, "settings"));
  work.input.job = work.job;
  return work;
}

std::string encode_iteration(int iteration, const std::string& row, const std::vector<std::uint8_t>& state) {
  const std::vector<std::uint8_t> cbor = json::to_cbor(json{{"iteration", iteration}, {"row", row}, {"state", json::binary(state)}});
  return {cbor.begin(), cbor.end()};
}

Iteration decode_iteration(const std::string& body) {
  const json j = decode(body);
  Iteration it{field<int>(j, "iteration"), field<std::string>(j, "row"), bytes(j, "state")};
  if (it.iteration < 1) throw std::invalid_argument("the body's \"iteration\" must be >= 1");
  // The row is stored and served as JSON text: it must be JSON.
  require_json(it.row, "row");
  return it;
}

std::string encode_thermal(int index, const std::string& row) {
  const std::vector<std::uint8_t> cbor = json::to_cbor(json{{"index", index}, {"row", row}});
  return {cbor.begin(), cbor.end()};
}

ThermalRow decode_thermal(const std::string& body) {
  const json j = decode(body);
  ThermalRow t{field<int>(j, "index"), field<std::string>(j, "row")};
  if (t.index < 1) throw std::invalid_argument("the body's \"index\" must be >= 1");
  require_json(t.row, "row");
  return t;
}

std::string encode_finish(const Finish& finish) {
  json j = {{"state", to_string(finish.state)}};
  if (finish.result) j["result"] = *finish.result;
  if (finish.message) j["message"] = *finish.message;
  if (finish.error) j["error"] = *finish.error;
  j["model_digest"] = finish.model_digest;
  const std::vector<std::uint8_t> cbor = json::to_cbor(j);
  return {cbor.begin(), cbor.end()};
}

Finish decode_finish(const std::string& body) {
  const json j = decode(body);
  Finish finish;
  const std::optional<JobState> state = parse_job_state(field<std::string>(j, "state"));
  // A run ends converged, not_converged, failed or cancelled; interrupted is for the service to decide,
  // so that every interruption is counted.
  if (!state || !is_finished(*state)) {
    throw std::invalid_argument("the body's \"state\" must be a state a run ends in");
  }
  finish.state = *state;
  finish.result = optional_text(j, "result");
  finish.message = optional_text(j, "message");
  finish.error = optional_text(j, "error");
  finish.model_digest = field<std::string>(j, "model_digest");
  if (finish.result) require_json(*finish.result, "result");
  return finish;
}

}  // namespace saasgaps::service::worker_protocol
