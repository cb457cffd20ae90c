#include "cli/file_io.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace saasgaps::cli {

std::string read_file(const std::string& path) {
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
