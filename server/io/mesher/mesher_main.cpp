// saasgaps-mesher DIRECTORY FILE SHOWN MAX_NODES SECONDS MEMORY_BYTES FILE_BYTES ORDER [NAME=VALUE ...]
//
// ORDER: 0 (a .geo's own element order), 1 or 2 (read_gmsh_mesh in io/mesher/gmsh_mesh.hpp).
// NAME=VALUE: a .geo's parameter, set in Gmsh's parser before the file runs (-setnumber).
// Reads DIRECTORY/FILE with Gmsh inside the sandbox of io/mesher_sandbox.hpp (DIRECTORY becomes
// "/", nothing outside it exists), with the size field on standard input as its background mesh
// size when there is one (io/mesher_protocol.hpp; read, bounded, before the sandbox), and writes the mesh to standard output in the encoding of
// io/mesher_protocol.hpp; errors go to standard error, named as SHOWN, with the exit codes of
// mesher::Exit. Started by io/gmsh_mesh.cpp for every mesh read, never by hand.
#include <unistd.h>

#include <charconv>
#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <string_view>

#include "io/mesher/geo_constants.hpp"
#include "io/mesher/gmsh_reader.hpp"
#include "io/mesher/mesher_protocol.hpp"
#include "io/mesher/mesher_sandbox.hpp"

namespace {

using namespace saasgaps::io;

template <class T>
bool parse(std::string_view text, T& value) {
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && end == text.data() + text.size();
}

int report(int code, const std::string& message) {
  const std::string line = message + "\n";
  (void)!::write(STDERR_FILENO, line.data(), line.size());
  return code;
}

/// Standard input, or false when it passes `limit` bytes.
bool read_input(std::string& bytes, std::size_t limit) {
  char buffer[65536];
  for (;;) {
    const ssize_t n = ::read(STDIN_FILENO, buffer, sizeof buffer);
    if (n == 0) return true;
    if (n < 0) return false;
    bytes.append(buffer, static_cast<std::size_t>(n));
    if (bytes.size() > limit) return false;
  }
}

bool write_all(const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(STDOUT_FILENO, bytes.data() + done, bytes.size() - done);
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  // Only standard input, output and error: nothing the parent had open is the geometry's business.
  ::close_range(3, ~0U, 0);
  std::size_t max_nodes = 0;
  SandboxLimits limits;
  int order = 0;
  if (argc < 9 || !parse(argv[4], max_nodes) || !parse(argv[5], limits.cpu_seconds) ||
      !parse(argv[6], limits.memory_bytes) || !parse(argv[7], limits.file_bytes) || limits.cpu_seconds < 1 ||
      !parse(argv[8], order) || order < 0 || order > 2) {
    return report(mesher::usage,
                  "usage: saasgaps-mesher DIRECTORY FILE SHOWN MAX_NODES SECONDS MEMORY_BYTES FILE_BYTES ORDER "
                  "[NAME=VALUE ...]");
  }
  MeshParameters parameters;
  for (int i = 9; i < argc; ++i) {
    const std::string_view item = argv[i];
    const std::size_t equals = item.find('=');
    double value = 0.0;
    if (equals == std::string_view::npos || !geo_identifier(item.substr(0, equals)) ||
        !parse(item.substr(equals + 1), value)) {
      return report(mesher::usage, "saasgaps-mesher: a parameter is NAME=VALUE, got \"" + std::string(item) + "\"");
    }
    parameters[std::string(item.substr(0, equals))] = value;
  }
  const std::string file = argv[2];
  const std::string shown = argv[3];
  if (file.empty() || file.find('/') != std::string::npos || file == "." || file == "..") {
    return report(mesher::usage, "saasgaps-mesher: FILE must be a plain file name, got \"" + file + "\"");
  }
  std::string input;
  if (!read_input(input, mesher::size_input_limit(max_nodes))) {
    return report(mesher::mesh_error, "the size field for " + shown + " is larger than its bound of " +
                                          std::to_string(mesher::size_input_limit(max_nodes)) + " bytes");
  }
  SizeField sizes;
  try {
    if (!input.empty()) sizes = mesher::decode_sizes(input, max_nodes);
  } catch (const MeshError& e) {
    return report(mesher::mesh_error, e.what());
  }
  std::string{}.swap(input);
  try {
    enter_sandbox(argv[1], limits);
  } catch (const SandboxError& e) {
    return report(mesher::no_sandbox, "cannot confine Gmsh to the directory of " + shown + " (" + e.what() +
                                          "); a mesh is read only inside that sandbox");
  }
  try {
    const GmshMesh mesh = read_with_gmsh("/" + file, shown, max_nodes, order, sizes.size.empty() ? nullptr : &sizes,
                                         parameters);
    return write_all(mesher::encode(mesh)) ? mesher::ok : report(mesher::mesh_error, "cannot write the mesh");
  } catch (const MeshTooLarge& e) {
    return report(mesher::too_many_nodes, e.what());
  } catch (const MeshError& e) {
    return report(mesher::mesh_error, e.what());
  } catch (const std::bad_alloc&) {
    return report(mesher::out_of_memory, "out of memory");
  } catch (const std::exception& e) {
    return report(mesher::mesh_error, std::string("Gmsh cannot read ") + shown + ": " + e.what());
  }
}
