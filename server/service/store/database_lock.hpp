#pragma once
/// An exclusive advisory lock (flock) on the database file itself: one server per database, whatever
/// name reaches it (a hard link or another path to the same inode takes the same lock). Released by
/// the kernel when the process dies, even by kill -9. Must outlive every connection to the file: the
/// descriptor stays open until then, since closing a descriptor of the file would drop SQLite's own
/// POSIX locks on it.

#include <string>

namespace saasgaps::service {

class DatabaseLock {
 public:
  explicit DatabaseLock(const std::string& database_path);
  ~DatabaseLock();
  DatabaseLock(const DatabaseLock&) = delete;
  DatabaseLock& operator=(const DatabaseLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace saasgaps::service
