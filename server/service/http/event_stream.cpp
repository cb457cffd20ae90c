#include "service/http/event_stream.hpp"

#include <charconv>
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "service/http/job_path.hpp"
#include "service/http/problem.hpp"

namespace saasgaps::service {

namespace {

/// Releases an event-stream slot when the stream ends, however it ends.
struct StreamSlot {
  std::atomic<int>& open;
  ~StreamSlot() { --open; }
};

}  // namespace

bool wait_or_keep_alive(EventHub& hub, std::uint64_t seen, httplib::DataSink& sink) {
  if (hub.wait(seen, std::chrono::seconds(15)) == seen) {
    static const std::string keep_alive = ": keep-alive\n\n";
    return sink.write(keep_alive.data(), keep_alive.size());
  }
  return true;
}

void EventStreams::serve(const httplib::Request& req, httplib::Response& res) {
  const std::int64_t id = job_in_path(req);
  (void)store_.get(id);  // 404 before a stream is opened
  if (++open_ > max_streams_) {
    --open_;
    res.set_header("Retry-After", "5");
    throw HttpError(503, "Service Unavailable",
                    "too many open event streams (" + std::to_string(max_streams_) + "); poll " +
                        "/v1/jobs/" + std::to_string(id) + "/iterations?after=N instead, or retry later");
  }
  auto slot = std::make_shared<StreamSlot>(open_);
  std::int64_t last = 0;
  const std::string last_header = req.get_header_value("Last-Event-ID");
  if (!last_header.empty()) std::from_chars(last_header.data(), last_header.data() + last_header.size(), last);
  auto cursor = std::make_shared<std::int64_t>(last);
  res.set_header("Cache-Control", "no-cache");
  res.set_header("X-Accel-Buffering", "no");
  res.set_chunked_content_provider(
      "text/event-stream",
      [this, id, cursor](std::size_t, httplib::DataSink& sink) {
        const std::uint64_t seen = hub_.version();
        const std::vector<JobEvent> events = store_.events(id, *cursor, 100);
        if (!events.empty()) {
          std::string text;
          for (const JobEvent& e : events) {
            text += "id: " + std::to_string(e.id) + "\nevent: " + e.kind + "\ndata: " + e.data + "\n\n";
            *cursor = e.id;
          }
          return sink.write(text.data(), text.size());
        }
        // Nothing new. A job that will not change again ends its stream; a live one waits for news,
        // with a comment line now and then so proxies and clients know the stream is alive.
        const JobState state = store_.get(id).state;
        if (is_finished(state)) {
          sink.done();
          return true;
        }
        return wait_or_keep_alive(hub_, seen, sink);
      },
      [slot](bool) {});
}

}  // namespace saasgaps::service
