#pragma once
/// Whole-file reads and atomic writes for the command line.

#include <functional>
#include <ostream>
#include <string>

namespace saasgaps::cli {

/// Throws std::runtime_error naming the file when it cannot be read (or is a directory).
std::string read_file(const std::string& path);

/// Checks, before any work starts, that `path` can be written: not a directory, and its directory
/// exists and is writable. Throws std::runtime_error naming `option` (e.g. "-o") and the path.
void require_writable(const std::string& path, const std::string& option);

/// Writes to a temporary file next to path and renames it over path, so a reader (or a crash)
/// never sees half a file. Devices and pipes (/dev/null, /dev/stdout) are written in place.
void write_file_atomically(const std::string& path, const std::string& content);

/// The same, with the content written by `write` to the file's stream as it is produced (a large
/// document need not exist in memory).
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write);

/// A bearer token from a file: its content without surrounding white space; throws when empty.
std::string read_token_file(const std::string& path);

}  // namespace saasgaps::cli
