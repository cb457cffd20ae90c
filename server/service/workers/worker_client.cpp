#include "service/workers/worker_client.hpp"

#include <httplib.h>

#include <algorithm>
#include <atomic>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <thread>

#include "io/model/model_reader.hpp"
#include "service/workers/worker_protocol.hpp"

namespace saasgaps::service {

namespace {

namespace protocol = worker_protocol;
using nlohmann::json;

/// A JSON answer of the service, read within the limits of io/json_limits.hpp; a broken one is a
/// failure of the run (exit 1), not a bad model.
json answer_json(const std::string& body) {
  try {
    return io::parse_document(body);
  } catch (const ModelError& e) {
    throw std::runtime_error("the service's answer is not JSON the worker can read: " + e.issues().front().pointer +
                             " " + e.issues().front().detail);
  }
}

/// The service, with bounded retries: connection failures and 5xx answers are tried again after a
/// growing pause (doubling, at most 5 s) until options.retry_for has passed.
class ServiceConnection {
 public:
  explicit ServiceConnection(const WorkerOptions& options) : options_(options), client_(options.server) {
    if (!client_.is_valid()) throw std::runtime_error("--server " + options.server + " is not an http:// URL");
    client_.set_connection_timeout(std::chrono::seconds(5));
    client_.set_read_timeout(std::chrono::minutes(2));
    client_.set_write_timeout(std::chrono::minutes(2));
    if (options.token) client_.set_bearer_token_auth(*options.token);
  }

  /// The one credential header every request carries from now on (the ticket, then the lease).
  void set_header(const char* name, const std::string& value) { headers_ = {{name, value}}; }

  /// The successful answer's body. LeaseLost on 409, ServiceUnreachable when retries run out,
  /// std::runtime_error for any other refusal (a bug or a misconfiguration: do not retry).
  std::string send(const std::string& method, const std::string& path, const std::string& body = {},
                   const char* content_type = protocol::cbor_type) {
    const auto deadline = std::chrono::steady_clock::now() + options_.retry_for;
    auto pause = options_.first_backoff;
    for (int attempt = 1;; ++attempt) {
      const httplib::Result r = method == "GET" ? client_.Get(path, headers_)
                                                : client_.Post(path, headers_, body, content_type);
      std::string why;
      if (!r) {
        why = httplib::to_string(r.error());
      } else if (r->status / 100 == 2) {
        return r->body;
      } else if (r->status == 409) {
        throw LeaseLost(method + " " + path + ": " + problem_detail(r->body));
      } else if (r->status < 500) {
        throw std::runtime_error(method + " " + path + " answered " + std::to_string(r->status) + ": " +
                                 problem_detail(r->body));
      } else {
        why = "status " + std::to_string(r->status) + ": " + problem_detail(r->body);
      }
      if (std::chrono::steady_clock::now() + pause > deadline) {
        throw ServiceUnreachable(method + " " + path + " failed " + std::to_string(attempt) + " times (last: " + why +
                                 "); giving up");
      }
      log(method + " " + path + " failed (" + why + "); retrying in " + std::to_string(pause.count()) + " ms");
      std::this_thread::sleep_for(pause);
      pause = std::min(pause * 2, std::chrono::milliseconds(5000));
    }
  }

  void log(const std::string& line) const {
    if (options_.log) options_.log(line);
  }

 private:
  static std::string problem_detail(const std::string& body) {
    json j;
    try {
      j = io::parse_document(body);
    } catch (const ModelError&) {
      return body.substr(0, 200);
    }
    if (j.is_object() && j.contains("detail") && j["detail"].is_string()) return j["detail"];
    return body.substr(0, 200);
  }

  const WorkerOptions& options_;
  httplib::Client client_;
  httplib::Headers headers_;
};

/// The remote sink: each call is one request, committed by the service before it answers.
class HttpSink final : public RunSink {
 public:
  HttpSink(ServiceConnection& service, std::string job_path, std::string model_digest)
      : service_(service), path_(std::move(job_path)), model_digest_(std::move(model_digest)) {}

  void iteration(int iteration, const std::string& row, const std::vector<std::uint8_t>& state) override {
    const json answer = answer_json(service_.send("POST", path_ + "/work/iterations",
                                                  protocol::encode_iteration(iteration, row, state)));
    stop_ = answer.value("stop", false);
    service_.log("iteration " + std::to_string(iteration) + " committed" + (stop_.load() ? "; a stop was requested" : ""));
  }

  void thermal(int index, const std::string& row) override {
    service_.send("POST", path_ + "/work/thermal", protocol::encode_thermal(index, row));
  }

  bool stop_requested() override { return stop_; }

  void finish(JobState state, const std::optional<std::string>& result, const std::optional<std::string>& message,
              const std::optional<std::string>& error) override {
    service_.send("POST", path_ + "/work/finish", protocol::encode_finish({state, result, message, error, model_digest_}));
    service_.log(std::string("finished: ") + to_string(state) + (message ? " (" + *message + ")" : "") +
                 (error ? " error: " + *error : ""));
  }

 private:
  ServiceConnection& service_;
  std::string path_;
  std::string model_digest_;
  std::atomic<bool> stop_{false};  // set on the commit thread, read on the solver's
};

}  // namespace

int run_worker(const WorkerOptions& options) {
  ServiceConnection service(options);
  const std::string path = "/v1/jobs/" + std::to_string(options.job);
  try {
    Lease lease;
    if (options.lease) {
      lease = *options.lease;
    } else if (options.ticket) {
      // Single use: a retry after a lost answer finds the ticket spent (409, exit 5), and the service
      // resubmits the run when its Slurm job ends.
      service.set_header(protocol::ticket_header, protocol::format_lease(*options.ticket));
      const json granted = answer_json(service.send("POST", path + "/lease", "", "application/json"));
      lease = {granted.at("attempt").get<int>(), granted.at("secret").get<std::string>()};
    } else {
      throw std::invalid_argument("run_worker needs the run's lease or its ticket");
    }
    service.set_header(protocol::lease_header, protocol::format_lease(lease));
    protocol::Work work = protocol::decode_work(service.send("GET", path + "/work"));
    service.log("job " + std::to_string(work.job) + ", attempt " + std::to_string(work.attempt) +
                (work.input.state ? ": resuming" : ": starting"));
    // Read here (execute_run takes it as read); the finish carries the model's digest: the service
    // refuses a result for another model. A model that does not read fails in execute_run.
    try {
      work.input.parsed = parse_run_model(work.input.model);
    } catch (const std::exception&) {
      work.input.parsed = nullptr;
    }
    HttpSink sink(service, path, work.input.parsed ? io::model_text_digest(work.input.model) : std::string());
    const std::atomic<bool> never{false};
    execute_run(work.input, sink, never);
    return 0;
  } catch (const LeaseLost& e) {
    service.log(std::string("the service refused this run: ") + e.what());
    return worker_exit_lease_lost;
  } catch (const ServiceUnreachable& e) {
    service.log(e.what());
    return worker_exit_unreachable;
  }
}

}  // namespace saasgaps::service
