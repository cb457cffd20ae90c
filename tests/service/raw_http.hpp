#pragma once
/// Raw HTTP over a loopback TCP socket, for requests a well-behaved client library will not send
/// (bytes that are not UTF-8 in a header, two Content-Length headers, a head sent slowly).

#include <chrono>
#include <string>

namespace saasgaps::testing {

/// A connected loopback socket, closed when destroyed.
class RawConnection {
 public:
  explicit RawConnection(int port);
  ~RawConnection();
  RawConnection(const RawConnection&) = delete;
  RawConnection& operator=(const RawConnection&) = delete;

  bool send(const std::string& bytes);
  void finish_sending();  ///< half-close: the server reads end-of-file after what was sent
  /// Reads until the server closes or `timeout` passes; `timed_out` says which.
  std::string receive_all(std::chrono::milliseconds timeout, bool* timed_out = nullptr);
  /// True once the server has closed the connection (a read returns end-of-file or an error).
  bool closed_by_server(std::chrono::milliseconds wait);

 private:
  int fd_ = -1;
};

/// Sends `request` on a new connection, half-closes, and returns everything the server answers.
std::string raw_exchange(int port, const std::string& request, std::chrono::milliseconds timeout = std::chrono::seconds(10),
                         bool* timed_out = nullptr);

/// The status code of the first response in `response` ("HTTP/1.1 400 ..."), or 0 when there is none.
int status_of(const std::string& response);

}  // namespace saasgaps::testing
