#include "io/gmsh_mesh.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <array>
#include <cstdlib>
#include <mutex>
#include <system_error>

namespace saasgaps::io {

namespace {

namespace fs = std::filesystem;

using ReadFunction = void (*)(const fs::path*, GmshMesh*);

/// Where the Gmsh reader module may be: $SAASGAPS_GMSH_MODULE, beside the running program, in
/// ../lib/saasgaps beside it (an installation), and where the build put it.
std::vector<fs::path> module_candidates() {
  std::vector<fs::path> candidates;
  if (const char* given = std::getenv("SAASGAPS_GMSH_MODULE"); given != nullptr && *given != '\0') {
    candidates.emplace_back(given);
  }
  std::error_code ec;
  const fs::path program = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    candidates.push_back(program.parent_path() / "libsaasgaps_gmsh.so");
    candidates.push_back(program.parent_path().parent_path() / "lib" / "saasgaps" / "libsaasgaps_gmsh.so");
  }
  candidates.emplace_back(SAASGAPS_GMSH_MODULE_PATH);
  return candidates;
}

/// Opens the module once per process (dlopen keeps it loaded) and returns its entry point.
ReadFunction gmsh_reader() {
  static std::once_flag once;
  static ReadFunction read = nullptr;
  static std::string failures;
  std::call_once(once, [] {
    for (const fs::path& candidate : module_candidates()) {
      std::error_code ec;
      if (!fs::exists(candidate, ec)) continue;
      void* module = ::dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
      if (module == nullptr) {
        failures += std::string("; ") + ::dlerror();
        continue;
      }
      read = reinterpret_cast<ReadFunction>(::dlsym(module, "saasgaps_read_gmsh_mesh"));
      if (read != nullptr) return;
      failures += "; " + candidate.string() + " has no saasgaps_read_gmsh_mesh";
    }
  });
  if (read == nullptr) {
    throw MeshError("cannot load the Gmsh reader module libsaasgaps_gmsh.so (beside the saasgaps program, or set "
                    "SAASGAPS_GMSH_MODULE)" + failures);
  }
  return read;
}

}  // namespace

std::string dimension_name(int dim) {
  switch (dim) {
    case 0: return "dimension 0 (point)";
    case 1: return "dimension 1 (curve)";
    case 2: return "dimension 2 (surface)";
    default: return "dimension " + std::to_string(dim) + " (volume)";
  }
}

GmshMesh read_gmsh_mesh(const fs::path& path) {
  const ReadFunction read = gmsh_reader();
  GmshMesh mesh;
  read(&path, &mesh);
  return mesh;
}

}  // namespace saasgaps::io
