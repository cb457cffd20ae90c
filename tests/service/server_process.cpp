#include "service/server_process.hpp"

#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <thread>

extern char** environ;

namespace saasgaps::testing {

namespace {

/// posix_spawn with stdout (and optionally stderr) into a pipe; returns the read end.
pid_t spawn(const std::vector<std::string>& arguments, int& read_end, bool merge_stderr) {
  int pipe_fds[2];
  if (pipe(pipe_fds) != 0) throw std::runtime_error("pipe failed");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], STDOUT_FILENO);
  if (merge_stderr) posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], STDERR_FILENO);
  posix_spawn_file_actions_addclose(&actions, pipe_fds[0]);
  std::vector<char*> argv;
  for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = -1;
  const int rc = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(pipe_fds[1]);
  if (rc != 0) {
    close(pipe_fds[0]);
    throw std::runtime_error("cannot start " + arguments[0]);
  }
  read_end = pipe_fds[0];
  return pid;
}

}  // namespace

ServerProcess::ServerProcess(const std::filesystem::path& database, const std::vector<std::string>& arguments,
                             const std::filesystem::path& log_file)
    : log_path_(log_file.empty() ? std::filesystem::path(database.string() + ".log") : log_file) {
  std::vector<std::string> command = {SAASGAPS_BINARY, "serve", "--db", database.string()};
  // A caller that needs the same port across a restart gives --port itself.
  if (std::find(arguments.begin(), arguments.end(), "--port") == arguments.end()) {
    command.insert(command.end(), {"--port", "0"});
  }
  command.insert(command.end(), arguments.begin(), arguments.end());
  const int log_fd = ::open(log_path_.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (log_fd < 0) throw std::runtime_error("cannot open " + log_path_.string());
  const auto start_offset = static_cast<std::size_t>(lseek(log_fd, 0, SEEK_END));
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, log_fd, STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, log_fd, STDERR_FILENO);
  std::vector<char*> argv;
  for (const std::string& a : command) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const int rc = posix_spawnp(&pid_, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(log_fd);
  if (rc != 0) throw std::runtime_error("cannot start " + command[0]);
  // The server prints where it listens: "... listening on http://127.0.0.1:PORT (...)".
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  for (;;) {
    const std::string text = log().substr(std::min(start_offset, log().size()));
    const auto at = text.find("listening on http://127.0.0.1:");
    if (at != std::string::npos && text.find('\n', at) != std::string::npos) {
      port_ = std::stoi(text.substr(at + 30));
      return;
    }
    int status = 0;
    if (waitpid(pid_, &status, WNOHANG) == pid_) {
      pid_ = -1;
      throw std::runtime_error("the server did not start: " + text);
    }
    if (std::chrono::steady_clock::now() > deadline) {
      kill_hard();
      throw std::runtime_error("the server did not start within 60 s: " + text);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

std::string ServerProcess::log() const {
  std::ifstream in(log_path_);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

ServerProcess::~ServerProcess() {
  if (pid_ > 0) kill_hard();
}

httplib::Client ServerProcess::client() const {
  httplib::Client c("127.0.0.1", port_);
  c.set_read_timeout(std::chrono::seconds(30));
  return c;
}

void ServerProcess::kill_hard() {
  if (pid_ <= 0) return;
  ::kill(pid_, SIGKILL);
  int status = 0;
  waitpid(pid_, &status, 0);
  pid_ = -1;
}

int ServerProcess::stop() {
  if (pid_ <= 0) return -1;
  ::kill(pid_, SIGTERM);
  int status = 0;
  waitpid(pid_, &status, 0);
  pid_ = -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

int free_port() {
  const int s = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ::bind(s, reinterpret_cast<sockaddr*>(&address), sizeof address);
  socklen_t length = sizeof address;
  ::getsockname(s, reinterpret_cast<sockaddr*>(&address), &length);
  ::close(s);
  return ntohs(address.sin_port);
}

CommandResult run_command(const std::vector<std::string>& arguments) {
  int out = -1;
  const pid_t pid = spawn(arguments, out, true);
  CommandResult result;
  char buffer[4096];
  ssize_t n = 0;
  while ((n = read(out, buffer, sizeof buffer)) > 0) result.output.append(buffer, static_cast<std::size_t>(n));
  close(out);
  int status = 0;
  waitpid(pid, &status, 0);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

nlohmann::json get_json(httplib::Client& client, const std::string& path) {
  const httplib::Result r = client.Get(path);
  if (!r) throw std::runtime_error("GET " + path + " failed: " + httplib::to_string(r.error()));
  if (r->status / 100 != 2) throw std::runtime_error("GET " + path + " answered " + std::to_string(r->status) + ": " + r->body);
  return nlohmann::json::parse(r->body);
}

nlohmann::json wait_for_state(httplib::Client& client, std::int64_t job, const std::vector<std::string>& states,
                              std::chrono::seconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    nlohmann::json j = get_json(client, "/v1/jobs/" + std::to_string(job));
    if (std::find(states.begin(), states.end(), j["state"].get<std::string>()) != states.end()) return j;
    if (std::chrono::steady_clock::now() > deadline) {
      throw std::runtime_error("job " + std::to_string(job) + " still " + j["state"].get<std::string>());
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

nlohmann::json result_numbers(nlohmann::json result) {
  for (auto& row : result["history"]) {
    row.erase("seconds");
    row.erase("attempt");
  }
  return result;
}

}  // namespace saasgaps::testing
