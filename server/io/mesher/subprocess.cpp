#include "io/mesher/subprocess.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

extern char** environ;

namespace saasgaps::io {

namespace {

/// A pipe whose ends close themselves.
struct Pipe {
  int fd[2] = {-1, -1};
  Pipe() {
    if (pipe2(fd, O_CLOEXEC) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  }
  ~Pipe() { close_both(); }
  void close_end(int k) {
    if (fd[k] >= 0) ::close(fd[k]);
    fd[k] = -1;
  }
  void close_both() {
    close_end(0);
    close_end(1);
  }
};

std::vector<std::string> merged_environment(const std::vector<std::string>& extra, bool inherit) {
  std::vector<std::string> env;
  for (char** e = inherit ? environ : nullptr; e != nullptr && *e; ++e) {
    const std::string entry = *e;
    const std::string name = entry.substr(0, entry.find('='));
    bool overridden = false;
    for (const std::string& x : extra) overridden = overridden || x.compare(0, name.size() + 1, name + "=") == 0;
    if (!overridden) env.push_back(entry);
  }
  env.insert(env.end(), extra.begin(), extra.end());
  return env;
}

}  // namespace

ProcessResult run_process(const ProcessSpec& spec) {
  Pipe in, out, err;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, in.fd[0], STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&actions, out.fd[1], STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, err.fd[1], STDERR_FILENO);
  // The server's sockets and files are not the program's business (cpp-httplib does not open
  // them close-on-exec).
  posix_spawn_file_actions_addclosefrom_np(&actions, 3);
  std::vector<char*> args;
  for (const std::string& a : spec.argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  std::vector<std::string> env_text = merged_environment(spec.environment, spec.inherit_environment);
  std::vector<char*> env;
  for (std::string& e : env_text) env.push_back(e.data());
  env.push_back(nullptr);
  pid_t pid = -1;
  const int rc = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), env.data());
  posix_spawn_file_actions_destroy(&actions);
  in.close_end(0);
  out.close_end(1);
  err.close_end(1);
  if (rc != 0) throw std::runtime_error("cannot run " + spec.argv[0] + ": " + std::strerror(rc));

  // Feed the input and drain both outputs together, so a full pipe never blocks either side: the
  // input end is non-blocking, so a write takes only what the pipe has room for.
  ProcessResult result;
  std::size_t written = 0;
  const std::string& input = spec.input;
  if (input.empty()) {
    in.close_end(1);
  } else {
    ::fcntl(in.fd[1], F_SETFL, ::fcntl(in.fd[1], F_GETFL) | O_NONBLOCK);
  }
  const auto deadline = std::chrono::steady_clock::now() + spec.limit;
  bool killed = false;
  while (out.fd[0] >= 0 || err.fd[0] >= 0) {
    pollfd fds[3];
    int n = 0;
    if (in.fd[1] >= 0) fds[n++] = {in.fd[1], POLLOUT, 0};
    if (out.fd[0] >= 0) fds[n++] = {out.fd[0], POLLIN, 0};
    if (err.fd[0] >= 0) fds[n++] = {err.fd[0], POLLIN, 0};
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0 || result.output_exceeded) {
      ::kill(pid, SIGKILL);
      killed = true;
      result.timed_out = !result.output_exceeded;
      break;
    }
    if (::poll(fds, static_cast<nfds_t>(n), static_cast<int>(left.count())) < 0 && errno != EINTR) break;
    for (int k = 0; k < n; ++k) {
      if (fds[k].revents == 0) continue;
      if (fds[k].fd == in.fd[1]) {
        const ssize_t w = ::write(in.fd[1], input.data() + written, input.size() - written);
        if (w > 0) written += static_cast<std::size_t>(w);
        // EPIPE: the program stopped reading (SIGPIPE is ignored by the service).
        if ((w < 0 && errno != EAGAIN && errno != EINTR) || written == input.size()) in.close_end(1);
        continue;
      }
      char buffer[4096];
      const ssize_t r = ::read(fds[k].fd, buffer, sizeof buffer);
      const bool is_out = fds[k].fd == out.fd[0];
      Pipe& p = is_out ? out : err;
      if (r <= 0) {
        p.close_end(0);
        continue;
      }
      std::string& text = is_out ? result.out : result.err;
      const std::size_t room = (is_out ? spec.max_output : spec.max_error) - text.size();
      text.append(buffer, std::min(room, static_cast<std::size_t>(r)));
      if (is_out && static_cast<std::size_t>(r) > room) result.output_exceeded = true;
    }
  }
  if (result.output_exceeded && !killed) {
    ::kill(pid, SIGKILL);
    killed = true;
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  result.exit_code = !killed && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  if (result.timed_out) result.err += "\n(killed after " + std::to_string(spec.limit.count()) + " ms)";
  return result;
}

ProcessResult run_process(const std::vector<std::string>& argv, const std::string& input,
                          const std::vector<std::string>& environment, std::chrono::milliseconds limit) {
  ProcessSpec spec;
  spec.argv = argv;
  spec.input = input;
  spec.environment = environment;
  spec.limit = limit;
  return run_process(spec);
}

}  // namespace saasgaps::io
