#pragma once
/// A thin RAII layer over SQLite 3: a connection, prepared statements, and write transactions that
/// start with BEGIN IMMEDIATE (so a writer takes the write lock up front instead of failing half
/// way with SQLITE_BUSY) and roll back unless committed.

#include <sqlite3.h>

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace saasgaps::service {

/// A database failure (I/O, corruption, a constraint the code did not expect), with SQLite's primary
/// result code (SQLITE_FULL, SQLITE_IOERR, SQLITE_CORRUPT, ...; 0 when not from SQLite).
class StoreError : public std::runtime_error {
 public:
  explicit StoreError(const std::string& what, int code = 0) : std::runtime_error(what), code_(code) {}
  [[nodiscard]] int code() const { return code_; }
  /// The file system refused to store more (disk full, quota, I/O error while writing).
  [[nodiscard]] bool no_space() const { return code_ == SQLITE_FULL || code_ == SQLITE_IOERR; }

 private:
  int code_;
};

/// How a connection opens its file.
enum class OpenMode {
  shared,     ///< WAL with shared memory: many connections, readers beside the writer
  exclusive,  ///< WAL with the index in heap memory (locking_mode=EXCLUSIVE): one connection only,
              ///< and no -shm file to create, so it opens on a full disk
};

class Statement;

class Connection {
 public:
  /// Page size of databases this code creates (bytes). See docs/performance.md for the measurements.
  static constexpr int page_size = 16384;

  /// Opens (creating if needed) the database file in WAL mode with full-sync commits and a busy
  /// timeout, and foreign keys on.
  explicit Connection(const std::string& path, OpenMode mode = OpenMode::shared);
  ~Connection();
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;

  /// Runs SQL without results (several statements allowed).
  void execute(const std::string& sql);
  [[nodiscard]] Statement prepare(std::string_view sql);
  [[nodiscard]] std::int64_t last_insert_id() const;
  [[nodiscard]] int changes() const;
  [[nodiscard]] sqlite3* handle() const { return db_; }

 private:
  sqlite3* db_ = nullptr;
};

/// A prepared statement; bind parameters by 1-based index, step through rows.
class Statement {
 public:
  Statement(sqlite3* db, std::string_view sql);
  ~Statement();
  Statement(Statement&& other) noexcept;
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;
  Statement& operator=(Statement&&) = delete;

  Statement& bind(int index, std::int64_t value);
  Statement& bind(int index, int value) { return bind(index, static_cast<std::int64_t>(value)); }
  Statement& bind(int index, double value);
  Statement& bind(int index, std::string_view text);
  Statement& bind(int index, const char* text) { return bind(index, std::string_view(text)); }
  Statement& bind(int index, const std::string& text) { return bind(index, std::string_view(text)); }
  Statement& bind_blob(int index, const std::vector<std::uint8_t>& bytes);
  Statement& bind_null(int index);
  template <class T>
  Statement& bind(int index, const std::optional<T>& value) {
    return value ? bind(index, *value) : bind_null(index);
  }

  /// Advances to the next row: true while there is one.
  bool step();
  /// Runs a statement that returns no rows.
  void run();

  [[nodiscard]] bool is_null(int column) const;
  [[nodiscard]] std::int64_t integer(int column) const;
  [[nodiscard]] double real(int column) const;
  [[nodiscard]] std::string text(int column) const;
  [[nodiscard]] std::optional<std::string> optional_text(int column) const;
  [[nodiscard]] std::vector<std::uint8_t> blob(int column) const;

 private:
  sqlite3* db_;
  sqlite3_stmt* stmt_ = nullptr;
};

/// One BLOB or TEXT value read in pieces (sqlite3_blob_open, read-only), so that a large value (a
/// result document of hundreds of megabytes) is never copied whole. The handle holds a read
/// transaction until destroyed; a row changed or deleted meanwhile makes read() throw.
class BlobReader {
 public:
  /// Throws StoreError when the row or value does not exist.
  BlobReader(Connection& connection, const char* table, const char* column, std::int64_t rowid);
  ~BlobReader();
  BlobReader(const BlobReader&) = delete;
  BlobReader& operator=(const BlobReader&) = delete;

  [[nodiscard]] std::size_t size() const { return size_; }
  /// Copies bytes [offset, offset + count) into out; throws StoreError past the end or when the
  /// row has changed since the handle was opened.
  void read(std::size_t offset, char* out, std::size_t count);

 private:
  sqlite3* db_;
  sqlite3_blob* blob_ = nullptr;
  std::size_t size_ = 0;
};

/// BEGIN IMMEDIATE ... COMMIT; rolls back when destroyed uncommitted (an exception on the way).
class WriteTransaction {
 public:
  explicit WriteTransaction(Connection& connection);
  ~WriteTransaction();
  WriteTransaction(const WriteTransaction&) = delete;
  WriteTransaction& operator=(const WriteTransaction&) = delete;
  void commit();

 private:
  Connection& connection_;
  bool done_ = false;
};

}  // namespace saasgaps::service
