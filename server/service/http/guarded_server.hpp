#pragma once
/// cpp-httplib's server with limits that keep slow or idle clients from starving it:
/// - an elastic thread pool: a connection gets a thread of its own when none is idle (up to
///   max_threads), so a few connections that hold threads cannot leave none for /healthz;
/// - a deadline for each request's head (request line and headers): a client sending a header line
///   per second is dropped when the deadline passes, however often it sends;
/// - idle keep-alive connections are closed after keep_alive_timeout, and after
///   max_requests_per_connection requests;
/// - per-read and per-write timeouts.
/// cpp-httplib 0.11 (Debian 12) reads a request head with a per-read timeout only; the connection
/// loop is replaced here (Server::process_and_close_socket is virtual, Server::process_request is
/// protected, the way its SSLServer does it), and everything else stays cpp-httplib's.

#include <httplib.h>

#include <chrono>
#include <cstddef>

namespace saasgaps::service {

struct ConnectionLimits {
  std::chrono::milliseconds head_deadline{10000};       ///< to receive a request line and its headers
  std::chrono::milliseconds keep_alive_timeout{5000};   ///< idle time before a connection is closed
  std::chrono::milliseconds read_timeout{5000};         ///< any one read of a request body
  std::chrono::milliseconds write_timeout{5000};        ///< any one write of a response
  /// After answering a request refused before its body was read, how long the unread body is
  /// drained before the socket closes. Closing with unread bytes makes the kernel send a reset,
  /// which a client still sending its body (most do: they read only after writing) gets instead
  /// of the answer: a 401 or 415 would arrive as "connection reset" or, without MSG_NOSIGNAL, kill
  /// the client with SIGPIPE.
  std::chrono::milliseconds linger{2000};
  std::size_t max_requests_per_connection = 100;
  std::size_t max_threads = 512;  ///< connections served at once; more wait for a thread
};

class GuardedServer : public httplib::Server {
 public:
  explicit GuardedServer(ConnectionLimits limits);

  /// Asks the connection loop to close the connection once the current response is written (a
  /// request refused before its body was read: the unread body must not be taken for the next
  /// request). Call from a handler, on the thread serving the request.
  static void close_after_response();
  /// When the request being served on this thread began to arrive (for the access log).
  static std::chrono::steady_clock::time_point request_started();

 private:
  bool process_and_close_socket(socket_t sock) override;

  ConnectionLimits limits_;
};

}  // namespace saasgaps::service
