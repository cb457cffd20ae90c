#include "service/store/stored_result.hpp"

#include <cstddef>

namespace saasgaps::service {
namespace detail {

namespace {

/// A result's blob handle on a connection of its own (opened for the purpose: a pool lease cannot
/// outlive the call that takes it).
class BlobResult final : public JobStore::StoredResult {
 public:
  BlobResult(std::unique_ptr<Connection> connection, std::int64_t id)
      : connection_(std::move(connection)), blob_(*connection_, "results", "document", id) {}
  [[nodiscard]] std::size_t size() const override { return blob_.size(); }
  void read(std::size_t offset, char* out, std::size_t count) override { blob_.read(offset, out, count); }

 private:
  std::unique_ptr<Connection> connection_;
  BlobReader blob_;
};

/// A result read whole, for a read-only store: its one exclusive connection cannot be shared with
/// a blob handle's connection of its own.
class TextResult final : public JobStore::StoredResult {
 public:
  explicit TextResult(std::string text) : text_(std::move(text)) {}
  [[nodiscard]] std::size_t size() const override { return text_.size(); }
  void read(std::size_t offset, char* out, std::size_t count) override { text_.copy(out, count, offset); }

 private:
  std::string text_;
};

}  // namespace

std::unique_ptr<JobStore::StoredResult> blob_result(std::unique_ptr<Connection> connection, std::int64_t id) {
  return std::make_unique<BlobResult>(std::move(connection), id);
}

std::unique_ptr<JobStore::StoredResult> text_result(std::string text) {
  return std::make_unique<TextResult>(std::move(text));
}

}  // namespace detail
}  // namespace saasgaps::service
