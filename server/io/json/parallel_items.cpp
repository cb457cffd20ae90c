#include "io/json/parallel_items.hpp"

#include "solver/base/index_ranges.hpp"

#include <algorithm>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace saasgaps::io {

namespace {

/// The pieces' texts and who does what next; guarded by `mutex`.
struct Pieces {
  std::mutex mutex;
  std::condition_variable changed;  // a piece formatted, a piece written, or a stop
  std::vector<std::string> texts;
  std::vector<char> formatted;
  std::vector<std::string> spare;  // the strings of pieces written, kept for the next ones
  std::size_t next = 0;     // the next piece to format
  std::size_t written = 0;  // pieces handed to the writer, in order
  bool stop = false;
  std::exception_ptr failure;
};

}  // namespace

void write_items(JsonWriter& out, std::size_t count, const std::function<void(JsonWriter&, std::size_t)>& item,
                 const ItemPieces& options) {
  const std::size_t per = std::max<std::size_t>(options.items, 1);
  const std::size_t piece_count = (count + per - 1) / per;
  const auto threads =
      static_cast<unsigned>(std::min<std::size_t>(options.threads > 0 ? options.threads : parallel_threads(), piece_count));
  if (threads <= 1) {
    for (std::size_t i = 0; i < count; ++i) item(out, i);
    return;
  }
  const std::size_t ahead = std::max<std::size_t>(options.ahead, threads);

  // Every thread continues from this copy of the writer's place, never from `out`, which the calling
  // thread changes as it writes.
  const JsonWriter origin = out.continuation([](std::string_view) {}, 0);
  // text: a spare piece's string, so that its memory is reused rather than allocated and faulted
  // in again for every piece.
  const auto format = [&](std::size_t k, std::string text) {
    text.clear();
    JsonWriter piece = origin.continuation(string_sink(text), k * per);
    const std::size_t end = std::min(count, (k + 1) * per);
    for (std::size_t i = k * per; i < end; ++i) item(piece, i);
    piece.flush();
    return text;
  };

  Pieces p;
  p.texts.resize(piece_count);
  p.formatted.assign(piece_count, 0);
  // Taking a piece never runs further than `ahead` past the last one written, so that the texts
  // held stay a few megabytes whatever the array's size.
  const auto can_take = [&] { return p.next < piece_count && p.next < p.written + ahead; };
  const auto take_spare = [&] {
    std::string text;
    if (!p.spare.empty()) {
      text = std::move(p.spare.back());
      p.spare.pop_back();
    }
    return text;
  };
  const auto formatter = [&] {
    std::unique_lock lock(p.mutex);
    for (;;) {
      p.changed.wait(lock, [&] { return p.stop || p.next >= piece_count || can_take(); });
      if (p.stop || p.next >= piece_count) return;
      const std::size_t k = p.next++;
      std::string text = take_spare();
      lock.unlock();
      try {
        text = format(k, std::move(text));
      } catch (...) {
        lock.lock();
        if (!p.failure) p.failure = std::current_exception();
        p.stop = true;
        p.changed.notify_all();
        return;
      }
      lock.lock();
      p.texts[k] = std::move(text);
      p.formatted[k] = 1;
      p.changed.notify_all();
    }
  };

  std::vector<std::thread> helpers;
  const auto stop_helpers = [&] {
    {
      const std::lock_guard lock(p.mutex);
      p.stop = true;
    }
    p.changed.notify_all();
    for (std::thread& t : helpers) t.join();
  };
  try {
    for (unsigned t = 1; t < threads; ++t) helpers.emplace_back(formatter);
    // The calling thread writes every piece that is ready, in order, and formats pieces itself
    // while the next one to write is still being formatted elsewhere.
    std::unique_lock lock(p.mutex);
    while (p.written < piece_count && !p.failure) {
      const std::size_t k = p.written;
      if (p.formatted[k]) {
        std::string text = std::move(p.texts[k]);
        lock.unlock();
        out.items(text, std::min(count, (k + 1) * per) - k * per);
        lock.lock();
        p.spare.push_back(std::move(text));
        ++p.written;
        p.changed.notify_all();
      } else if (can_take()) {
        const std::size_t mine = p.next++;
        std::string text = take_spare();
        lock.unlock();
        text = format(mine, std::move(text));
        lock.lock();
        p.texts[mine] = std::move(text);
        p.formatted[mine] = 1;
      } else {
        p.changed.wait(lock);
      }
    }
  } catch (...) {
    stop_helpers();
    throw;
  }
  stop_helpers();
  if (p.failure) std::rethrow_exception(p.failure);
}

}  // namespace saasgaps::io
