#pragma once
/// An environment variable set for a scope (a test, a fixture) and put back as it was after: its
/// old value restored, or removed if it had none. Child processes started meanwhile (a server, a
/// fake sbatch) inherit it.

#include <cstdlib>
#include <optional>
#include <string>
#include <utility>

namespace saasgaps::testing {

class EnvironmentVariable {
 public:
  EnvironmentVariable(std::string name, const std::string& value) : name_(std::move(name)) {
    if (const char* old = std::getenv(name_.c_str())) old_ = old;
    ::setenv(name_.c_str(), value.c_str(), 1);
  }
  ~EnvironmentVariable() {
    if (old_) {
      ::setenv(name_.c_str(), old_->c_str(), 1);
    } else {
      ::unsetenv(name_.c_str());
    }
  }
  EnvironmentVariable(const EnvironmentVariable&) = delete;
  EnvironmentVariable& operator=(const EnvironmentVariable&) = delete;

 private:
  std::string name_;
  std::optional<std::string> old_;
};

}  // namespace saasgaps::testing
