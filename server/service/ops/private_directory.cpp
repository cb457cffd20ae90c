#include "service/ops/private_directory.hpp"

#include <signal.h>
#include <stdlib.h>
#include <unistd.h>

#include <cerrno>
#include <fstream>
#include <regex>
#include <stdexcept>
#include <system_error>

namespace saasgaps::service {

namespace fs = std::filesystem;

namespace {
const std::string upload_prefix = "saasgaps-upload-";
}  // namespace

PrivateDirectory::PrivateDirectory(const std::string& purpose) {
  std::string pattern =
      (fs::temp_directory_path() / (upload_prefix + purpose + "-" + std::to_string(::getpid()) + "-XXXXXX")).string();
  if (::mkdtemp(pattern.data()) == nullptr) {
    throw std::system_error(errno, std::generic_category(), "cannot create a directory for the upload");
  }
  path_ = pattern;
}

PrivateDirectory::~PrivateDirectory() {
  std::error_code ignored;
  fs::remove_all(path_, ignored);
}

void PrivateDirectory::write(const std::string& name, const std::string& content) const {
  std::ofstream out(path_ / name, std::ios::binary);
  out.write(content.data(), static_cast<std::streamsize>(content.size()));
  if (!out) throw std::runtime_error("cannot store the uploaded file " + name);
}

int remove_abandoned_uploads(const fs::path& parent) {
  // mkdtemp's six characters after the process id: the name PrivateDirectory gives and no other.
  static const std::regex name("saasgaps-upload-[a-z]+-([0-9]{1,10})-[A-Za-z0-9]{6}");
  int removed = 0;
  std::error_code error;
  for (fs::directory_iterator it(parent, error), end; !error && it != end; it.increment(error)) {
    std::smatch match;
    const std::string file = it->path().filename().string();
    if (!std::regex_match(file, match, name) || !it->is_directory(error)) continue;
    const long long pid = std::stoll(match[1].str());
    if (pid <= 0 || pid == ::getpid() || pid > 0x7fffffff) continue;
    if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;  // alive, or not ours to judge
    std::error_code ignored;
    if (fs::remove_all(it->path(), ignored) > 0 && !ignored) ++removed;
  }
  return removed;
}

}  // namespace saasgaps::service
