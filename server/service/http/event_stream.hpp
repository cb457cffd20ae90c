#pragma once
/// GET /v1/jobs/{id}/events: a job's events as Server-Sent Events, from the one after Last-Event-ID
/// until the job finishes. Each open stream holds one of the server's HTTP threads, so their number
/// is capped.

#include <httplib.h>

#include <atomic>
#include <cstdint>

#include "service/store/event_hub.hpp"
#include "service/store/job_store.hpp"

namespace saasgaps::service {

/// A live stream with nothing new to send: waits up to 15 s for news on the hub (a version other
/// than `seen`, read before the stream's last look at the store); with none, writes the comment line
/// ": keep-alive" so that proxies and clients know the stream is alive. False when the client is
/// gone. Used by every event stream (jobs here, studies in service/studies).
bool wait_or_keep_alive(EventHub& hub, std::uint64_t seen, httplib::DataSink& sink);

class EventStreams {
 public:
  EventStreams(JobStore& store, EventHub& hub, int max_streams)
      : store_(store), hub_(hub), max_streams_(max_streams) {}

  /// Opens a job's stream: 404 for no job, 503 with Retry-After while max_streams are open.
  void serve(const httplib::Request& req, httplib::Response& res);
  /// Streams open now (reported by /healthz and /metrics).
  [[nodiscard]] int open() const { return open_.load(); }
  [[nodiscard]] int max_streams() const { return max_streams_; }

 private:
  JobStore& store_;
  EventHub& hub_;
  int max_streams_;
  std::atomic<int> open_{0};
};

}  // namespace saasgaps::service
