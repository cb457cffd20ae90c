#include "cli/common/file_io.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <unistd.h>

namespace saasgaps::cli {

std::string read_file(const std::string& path) {
  // An ifstream opens a directory without complaint and then reads nothing.
  if (std::filesystem::is_directory(path)) throw std::runtime_error("cannot read " + path + ": it is a directory, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path + ": " + std::strerror(errno));
  // Straight into a string of the file's size (a model of 10^6 unknowns is 60 MB): no stream
  // buffer copy. A pipe or device has no size; it is read in pieces.
  std::error_code error;
  const auto size = std::filesystem::is_regular_file(path, error) ? std::filesystem::file_size(path, error) : 0;
  std::string text;
  if (!error && size > 0) {
    text.resize(size);
    in.read(text.data(), static_cast<std::streamsize>(size));
    text.resize(static_cast<std::size_t>(in.gcount()));
  }
  char piece[1 << 16];
  while (in.read(piece, sizeof piece) || in.gcount() > 0) text.append(piece, static_cast<std::size_t>(in.gcount()));
  if (in.bad()) throw std::runtime_error("cannot read " + path + ": " + std::strerror(errno));
  return text;
}

void require_writable(const std::string& path, const std::string& option) {
  namespace fs = std::filesystem;
  if (path.empty()) return;
  const std::string where = option + " " + path + ": ";
  if (fs::is_directory(path)) throw std::runtime_error(where + "is a directory; give a file name");
  // A device or a pipe is written in place (see write_file_atomically): only it must be writable.
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (!error && fs::exists(status) && !fs::is_regular_file(status)) {
    if (access(path.c_str(), W_OK) != 0) throw std::runtime_error(where + "not writable: " + std::strerror(errno));
    return;
  }
  const fs::path parent = fs::path(path).parent_path().empty() ? fs::path(".") : fs::path(path).parent_path();
  if (!fs::exists(parent)) throw std::runtime_error(where + "the directory " + parent.string() + " does not exist");
  if (!fs::is_directory(parent)) throw std::runtime_error(where + parent.string() + " is not a directory");
  if (access(parent.c_str(), W_OK) != 0) {
    throw std::runtime_error(where + "the directory " + parent.string() + " is not writable: " + std::strerror(errno));
  }
}

void write_file_atomically(const std::string& path, const std::string& content) {
  write_file_atomically(path, [&content](std::ostream& out) { out << content; });
}

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
  // A device or a pipe (/dev/null, /dev/stdout, a FIFO) is written in place: renaming a file over
  // it would replace the device itself.
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  const bool in_place = !error && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status);
  const std::string target = in_place ? path : path + ".tmp";
  {
    std::ofstream out(target, std::ios::binary | (in_place ? std::ios::out : std::ios::trunc));
    if (!out) throw std::runtime_error("cannot write " + target + ": " + std::strerror(errno));
    try {
      write(out);
    } catch (const std::ios_base::failure&) {
      out.setstate(std::ios::badbit);  // reported below, naming the file
    }
    out.flush();
    if (!out) throw std::runtime_error("cannot write " + target + ": " + std::strerror(errno));
  }
  if (!in_place) std::filesystem::rename(target, path);
}

std::string read_token_file(const std::string& path) {
  std::string token = read_file(path);
  const auto last = token.find_last_not_of(" \t\r\n");
  token.erase(last == std::string::npos ? 0 : last + 1);
  token.erase(0, token.find_first_not_of(" \t\r\n"));
  if (token.empty()) throw std::runtime_error("the token file " + path + " is empty");
  return token;
}

}  // namespace saasgaps::cli
