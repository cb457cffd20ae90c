#include "service/http/guarded_server.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <thread>

namespace saasgaps::service {

namespace {

using Clock = std::chrono::steady_clock;

thread_local bool close_requested = false;
thread_local Clock::time_point started = Clock::now();

/// Waits until `fd` is readable (or writable) or `timeout` passes; false on timeout or error.
bool wait_for(int fd, short events, std::chrono::milliseconds timeout) {
  pollfd p{fd, events, 0};
  for (;;) {
    const int n = ::poll(&p, 1, static_cast<int>(std::max<std::int64_t>(timeout.count(), 0)));
    if (n > 0) return (p.revents & (events | POLLHUP | POLLERR)) != 0;
    if (n == 0) return false;
    if (errno != EINTR) return false;
  }
}

/// A connection's socket as cpp-httplib's Stream, buffered, with the head deadline: until the blank
/// line that ends a request's headers has been read, no read may end after the deadline.
class DeadlineStream final : public httplib::Stream {
 public:
  DeadlineStream(socket_t sock, const ConnectionLimits& limits) : sock_(sock), limits_(limits) {}

  /// A new request starts: its head must arrive within the deadline from now.
  void start_request() {
    deadline_ = Clock::now() + limits_.head_deadline;
    in_head_ = true;
    matched_ = 0;
  }
  [[nodiscard]] bool has_buffered() const { return position_ < size_; }
  /// A read of the head failed (timed out, or the deadline passed): the client is too slow or gone.
  [[nodiscard]] bool head_failed() const { return head_failed_; }

  bool is_readable() const override {
    return has_buffered() || wait_for(sock_, POLLIN, read_budget());
  }
  bool is_writable() const override { return wait_for(sock_, POLLOUT, limits_.write_timeout); }

  ssize_t read(char* ptr, size_t size) override {
    if (!has_buffered()) {
      if (!wait_for(sock_, POLLIN, read_budget())) {
        head_failed_ = head_failed_ || in_head_;
        return -1;
      }
      ssize_t n = 0;
      do {
        n = ::recv(sock_, buffer_.data(), buffer_.size(), 0);
      } while (n < 0 && errno == EINTR);
      if (n <= 0) {
        head_failed_ = head_failed_ || in_head_;
        return n;
      }
      position_ = 0;
      size_ = static_cast<std::size_t>(n);
    }
    const std::size_t count = std::min(size, size_ - position_);
    std::copy_n(buffer_.data() + position_, count, ptr);
    position_ += count;
    if (in_head_) track_head(ptr, count);
    return static_cast<ssize_t>(count);
  }

  ssize_t write(const char* ptr, size_t size) override {
    if (!is_writable()) return -1;
    ssize_t n = 0;
    do {
      n = ::send(sock_, ptr, size, MSG_NOSIGNAL);
    } while (n < 0 && errno == EINTR);
    return n;
  }

  void get_remote_ip_and_port(std::string& ip, int& port) const override { address(::getpeername, ip, port); }
  void get_local_ip_and_port(std::string& ip, int& port) const override { address(::getsockname, ip, port); }
  socket_t socket() const override { return sock_; }

 private:
  /// How long the next read may wait: the read timeout, cut short by the head deadline.
  [[nodiscard]] std::chrono::milliseconds read_budget() const {
    if (!in_head_) return limits_.read_timeout;
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline_ - Clock::now());
    return std::min(left, limits_.read_timeout);
  }

  /// Follows "\r\n\r\n" across reads: the end of the head.
  void track_head(const char* data, std::size_t count) {
    static constexpr char end[] = "\r\n\r\n";
    for (std::size_t k = 0; k < count && in_head_; ++k) {
      matched_ = data[k] == end[matched_] ? matched_ + 1 : (data[k] == '\r' ? 1 : 0);
      if (matched_ == 4) in_head_ = false;
    }
  }

  template <class Query>
  void address(Query query, std::string& ip, int& port) const {
    sockaddr_storage addr{};
    socklen_t length = sizeof addr;
    if (query(sock_, reinterpret_cast<sockaddr*>(&addr), &length) != 0) return;
    char text[INET6_ADDRSTRLEN] = {};
    if (addr.ss_family == AF_INET) {
      const auto* a = reinterpret_cast<const sockaddr_in*>(&addr);
      ::inet_ntop(AF_INET, &a->sin_addr, text, sizeof text);
      port = ntohs(a->sin_port);
    } else if (addr.ss_family == AF_INET6) {
      const auto* a = reinterpret_cast<const sockaddr_in6*>(&addr);
      ::inet_ntop(AF_INET6, &a->sin6_addr, text, sizeof text);
      port = ntohs(a->sin6_port);
    }
    ip = text;
  }

  socket_t sock_;
  const ConnectionLimits& limits_;
  std::array<char, 8192> buffer_{};
  std::size_t position_ = 0, size_ = 0;
  Clock::time_point deadline_{};
  bool in_head_ = false;
  bool head_failed_ = false;
  int matched_ = 0;
};

/// Threads made when a task finds none idle, up to a cap; a thread idle for a while ends.
class ElasticPool final : public httplib::TaskQueue {
 public:
  explicit ElasticPool(std::size_t max_threads) : max_threads_(max_threads) {}
  ~ElasticPool() override { shutdown(); }

  void enqueue(std::function<void()> fn) override {
    std::unique_lock lock(mutex_);
    tasks_.push_back(std::move(fn));
    // Idle threads that were woken but have not yet taken a task are still counted idle: compare
    // with the tasks waiting, not with zero.
    if (tasks_.size() > idle_ && live_ < max_threads_) {
      ++live_;
      std::thread([this] { work(); }).detach();
    } else {
      ready_.notify_one();
    }
  }

  void shutdown() override {
    std::unique_lock lock(mutex_);
    stopping_ = true;
    ready_.notify_all();
    ended_.wait(lock, [&] { return live_ == 0; });
  }

 private:
  void work() {
    std::unique_lock lock(mutex_);
    for (;;) {
      ++idle_;
      const bool woke = ready_.wait_for(lock, std::chrono::seconds(30), [&] { return !tasks_.empty() || stopping_; });
      --idle_;
      if (tasks_.empty() && (stopping_ || !woke)) break;
      if (tasks_.empty()) continue;
      std::function<void()> task = std::move(tasks_.front());
      tasks_.pop_front();
      lock.unlock();
      task();
      lock.lock();
    }
    --live_;
    ended_.notify_all();
  }

  const std::size_t max_threads_;
  std::mutex mutex_;
  std::condition_variable ready_, ended_;
  std::deque<std::function<void()>> tasks_;
  std::size_t live_ = 0, idle_ = 0;
  bool stopping_ = false;
};

/// Takes "br" out of Accept-Encoding. cpp-httplib prefers Brotli whenever a client offers it, at
/// its slowest quality: a 6 MB SVG plot took 33 s to compress (gzip: 2.3 s, 10 % larger), a thread
/// and a core that any browser could tie up per request.
void refuse_brotli(httplib::Request& req) {
  for (auto [it, end] = req.headers.equal_range("Accept-Encoding"); it != end; ++it) {
    std::string kept;
    std::size_t start = 0;
    while (start <= it->second.size()) {
      std::size_t comma = it->second.find(',', start);
      if (comma == std::string::npos) comma = it->second.size();
      std::string token = it->second.substr(start, comma - start);
      token.erase(0, token.find_first_not_of(' '));
      if (!token.empty() && token.rfind("br", 0) != 0) kept += (kept.empty() ? "" : ", ") + token;
      start = comma + 1;
    }
    it->second = kept.empty() ? "identity" : kept;
  }
}

/// The lingering close: says "no more answers" (FIN), then reads and discards what the client is
/// still sending until it closes its side or `linger` passes, then closes. Bounded by time, not
/// size, so a client cannot hold the thread longer than `linger`.
void drain_then_close(socket_t sock, std::chrono::milliseconds linger) {
  ::shutdown(sock, SHUT_WR);
  const Clock::time_point until = Clock::now() + linger;
  std::array<char, 65536> sink{};
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(until - Clock::now());
    if (left.count() <= 0 || !wait_for(sock, POLLIN, left)) break;
    const ssize_t n = ::recv(sock, sink.data(), sink.size(), 0);
    if (n == 0 || (n < 0 && errno != EINTR)) break;
  }
  ::close(sock);
}

}  // namespace

GuardedServer::GuardedServer(ConnectionLimits limits) : limits_(limits) {
  new_task_queue = [max = limits_.max_threads] { return new ElasticPool(max); };
  // What cpp-httplib writes in its Keep-Alive response header.
  set_keep_alive_timeout(std::chrono::duration_cast<std::chrono::seconds>(limits_.keep_alive_timeout).count());
  set_keep_alive_max_count(limits_.max_requests_per_connection);
}

void GuardedServer::close_after_response() { close_requested = true; }

Clock::time_point GuardedServer::request_started() { return started; }

bool GuardedServer::process_and_close_socket(socket_t sock) {
  DeadlineStream stream(sock, limits_);
  bool ok = true;
  bool refused_unread = false;
  for (std::size_t served = 0; served < limits_.max_requests_per_connection && is_running(); ++served) {
    // An idle connection waits for its next request no longer than the keep-alive timeout.
    if (!stream.has_buffered() && !wait_for(sock, POLLIN, limits_.keep_alive_timeout)) break;
    stream.start_request();
    started = Clock::now();
    close_requested = false;
    bool connection_closed = false;
    const bool last = served + 1 == limits_.max_requests_per_connection;
    ok = process_request(stream, last, connection_closed, refuse_brotli);
    // A head that did not arrive in time was answered 400; what the client sends next is not a
    // request either.
    if (!ok || connection_closed || close_requested || stream.head_failed()) {
      refused_unread = close_requested;
      break;
    }
  }
  close_requested = false;
  if (refused_unread) {
    drain_then_close(sock, limits_.linger);
  } else {
    ::shutdown(sock, SHUT_RDWR);
    ::close(sock);
  }
  return ok;
}

}  // namespace saasgaps::service
