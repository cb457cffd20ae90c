#include "solver/lac/cache_file.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <fstream>
#include <string>

namespace saasgaps {

bool read_words(std::istream& in, Index* out, std::size_t count) {
  // The stream's own buffer is small: large reads go straight into the destination.
  constexpr std::size_t chunk = 1 << 16;
  for (std::size_t done = 0; done < count;) {
    const std::size_t take = std::min(count - done, chunk);
    if (!in.read(reinterpret_cast<char*>(out + done), static_cast<std::streamsize>(take * sizeof(Index)))) return false;
    done += take;
  }
  return true;
}

bool write_atomically(const std::filesystem::path& target, const std::function<void(std::ostream&)>& write) {
  std::error_code error;
  std::filesystem::create_directories(target.parent_path(), error);
  if (error) return false;
  static std::atomic<unsigned> calls{0};
  std::filesystem::path temporary = target;
  temporary += ".tmp" + std::to_string(::getpid()) + "-" + std::to_string(calls++);
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (out) write(out);
    out.close();
    if (!out) {
      std::filesystem::remove(temporary, error);
      return false;
    }
  }
  std::filesystem::rename(temporary, target, error);
  if (error) {
    std::filesystem::remove(temporary, error);
    return false;
  }
  return true;
}

}  // namespace saasgaps
