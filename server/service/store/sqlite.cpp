#include "service/store/sqlite.hpp"

namespace saasgaps::service {

namespace {

[[noreturn]] void fail(sqlite3* db, const std::string& what) {
  throw StoreError(what + ": " + (db != nullptr ? sqlite3_errmsg(db) : "out of memory"),
                   db != nullptr ? sqlite3_errcode(db) & 0xff : SQLITE_NOMEM);
}

}  // namespace

Connection::Connection(const std::string& path, OpenMode mode) {
  const int flags = SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_NOMUTEX;
  if (sqlite3_open_v2(path.c_str(), &db_, flags, nullptr) != SQLITE_OK) {
    const std::string message = db_ != nullptr ? sqlite3_errmsg(db_) : "out of memory";
    sqlite3_close(db_);
    db_ = nullptr;
    throw StoreError("cannot open database " + path + ": " + message, SQLITE_CANTOPEN);
  }
  try {
    // Before the first access to the WAL: the exclusive mode keeps the WAL index in heap memory.
    if (mode == OpenMode::exclusive) execute("PRAGMA locking_mode=EXCLUSIVE");
    // Writers wait for each other rather than failing; readers never block writers in WAL mode.
    sqlite3_busy_timeout(db_, 10000);
    // synchronous=FULL: a commit is on disk (WAL fsynced) before it returns, so a kill -9 or power
    // loss after an iteration's commit cannot lose that iteration.
    // A new database gets large pages: a job writes megabytes of restart state and result per
    // commit, which 4 KiB pages split into thousands of page writes, each twice (WAL, then the
    // checkpoint). The page size of an existing database stays as it is (a no-op there).
    execute("PRAGMA page_size=" + std::to_string(page_size) + ";");
    execute("PRAGMA journal_mode=WAL; PRAGMA synchronous=FULL; PRAGMA foreign_keys=ON;");
  } catch (...) {
    sqlite3_close_v2(db_);
    throw;
  }
}

Connection::~Connection() { sqlite3_close_v2(db_); }

void Connection::execute(const std::string& sql) {
  char* error = nullptr;
  const int rc = sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &error);
  if (rc != SQLITE_OK) {
    const std::string message = error != nullptr ? error : "unknown error";
    sqlite3_free(error);
    throw StoreError("SQL failed: " + message, rc & 0xff);
  }
}

Statement Connection::prepare(std::string_view sql) { return Statement(db_, sql); }

std::int64_t Connection::last_insert_id() const { return sqlite3_last_insert_rowid(db_); }

int Connection::changes() const { return sqlite3_changes(db_); }

Statement::Statement(sqlite3* db, std::string_view sql) : db_(db) {
  if (sqlite3_prepare_v2(db, sql.data(), static_cast<int>(sql.size()), &stmt_, nullptr) != SQLITE_OK) {
    fail(db, "cannot prepare \"" + std::string(sql) + "\"");
  }
}

Statement::Statement(Statement&& other) noexcept : db_(other.db_), stmt_(other.stmt_) { other.stmt_ = nullptr; }

Statement::~Statement() { sqlite3_finalize(stmt_); }

Statement& Statement::bind(int index, std::int64_t value) {
  if (sqlite3_bind_int64(stmt_, index, value) != SQLITE_OK) fail(db_, "bind");
  return *this;
}

Statement& Statement::bind(int index, double value) {
  if (sqlite3_bind_double(stmt_, index, value) != SQLITE_OK) fail(db_, "bind");
  return *this;
}

Statement& Statement::bind(int index, std::string_view text) {
  if (sqlite3_bind_text(stmt_, index, text.data(), static_cast<int>(text.size()), SQLITE_TRANSIENT) != SQLITE_OK) {
    fail(db_, "bind");
  }
  return *this;
}

Statement& Statement::bind_blob(int index, const std::vector<std::uint8_t>& bytes) {
  if (sqlite3_bind_blob64(stmt_, index, bytes.data(), bytes.size(), SQLITE_TRANSIENT) != SQLITE_OK) fail(db_, "bind");
  return *this;
}

Statement& Statement::bind_null(int index) {
  if (sqlite3_bind_null(stmt_, index) != SQLITE_OK) fail(db_, "bind");
  return *this;
}

bool Statement::step() {
  const int rc = sqlite3_step(stmt_);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  fail(db_, "step");
}

void Statement::run() {
  while (step()) {
  }
}

bool Statement::is_null(int column) const { return sqlite3_column_type(stmt_, column) == SQLITE_NULL; }

std::int64_t Statement::integer(int column) const { return sqlite3_column_int64(stmt_, column); }

double Statement::real(int column) const { return sqlite3_column_double(stmt_, column); }

std::string Statement::text(int column) const {
  const auto* p = reinterpret_cast<const char*>(sqlite3_column_text(stmt_, column));
  return p != nullptr ? std::string(p, static_cast<std::size_t>(sqlite3_column_bytes(stmt_, column))) : std::string();
}

std::optional<std::string> Statement::optional_text(int column) const {
  if (is_null(column)) return std::nullopt;
  return text(column);
}

std::vector<std::uint8_t> Statement::blob(int column) const {
  const auto* p = static_cast<const std::uint8_t*>(sqlite3_column_blob(stmt_, column));
  const auto n = static_cast<std::size_t>(sqlite3_column_bytes(stmt_, column));
  return p != nullptr ? std::vector<std::uint8_t>(p, p + n) : std::vector<std::uint8_t>();
}

BlobReader::BlobReader(Connection& connection, const char* table, const char* column, std::int64_t rowid)
    : db_(connection.handle()) {
  if (sqlite3_blob_open(db_, "main", table, column, rowid, 0, &blob_) != SQLITE_OK) {
    const std::string message = sqlite3_errmsg(db_);
    sqlite3_blob_close(blob_);  // a failed open may still allocate a handle; closing null is a no-op
    blob_ = nullptr;
    throw StoreError(std::string("cannot read ") + table + "." + column + " of row " + std::to_string(rowid) + ": " +
                     message);
  }
  size_ = static_cast<std::size_t>(sqlite3_blob_bytes(blob_));
}

BlobReader::~BlobReader() { sqlite3_blob_close(blob_); }

void BlobReader::read(std::size_t offset, char* out, std::size_t count) {
  if (offset > size_ || count > size_ - offset) throw StoreError("read past the end of a stored value");
  if (sqlite3_blob_read(blob_, out, static_cast<int>(count), static_cast<int>(offset)) != SQLITE_OK) {
    throw StoreError(std::string("reading a stored value failed: ") + sqlite3_errmsg(db_));
  }
}

WriteTransaction::WriteTransaction(Connection& connection) : connection_(connection) {
  connection_.execute("BEGIN IMMEDIATE");
}

WriteTransaction::~WriteTransaction() {
  if (done_) return;
  try {
    connection_.execute("ROLLBACK");
  } catch (...) {
    // A failed rollback leaves SQLite to roll back when the connection closes; nothing better to do
    // inside a destructor.
  }
}

void WriteTransaction::commit() {
  connection_.execute("COMMIT");
  done_ = true;
}

}  // namespace saasgaps::service
