#pragma once
/// The items of a large JSON array formatted on several threads and written in order: the nodes and
/// elements of a result document at 10^6 unknowns are 300 MB of text, and turning doubles into
/// their shortest decimals is most of the time a result takes to write (docs/performance.md).
///
/// The array is cut into pieces of consecutive items. Each thread (the caller's included) takes the
/// next piece, formats it into a text of its own with a JsonWriter::continuation() of the writer,
/// and the calling thread hands the texts to the writer in order (JsonWriter::items()): the sink is
/// only ever called from the calling thread, and the document is byte for byte the one the items
/// written one after the other give, compact or pretty.

#include <cstddef>
#include <functional>

#include "io/json/json_writer.hpp"

namespace saasgaps::io {

struct ItemPieces {
  std::size_t items = 256;  ///< items per piece; arrays of one piece are written on the calling thread
  /// Formatting threads in all, the caller's included; 0: parallel_threads() (the cores', at most 4,
  /// unless a server solving several jobs at once set 1).
  unsigned threads = 0;
  std::size_t ahead = 16;   ///< pieces formatted and not yet written, at most (bounds the memory held)
};

/// Writes item(writer, i) for i = 0 .. count - 1 into the array `out` is writing (after begin_array(),
/// before end_array()): the same text as item(out, i) for each i in turn. item is called from several
/// threads at once, each call with its own writer, so it must only read what it writes. An
/// exception from item or from the sink stops every thread and propagates to the caller.
void write_items(JsonWriter& out, std::size_t count, const std::function<void(JsonWriter&, std::size_t)>& item,
                 const ItemPieces& pieces = {});

}  // namespace saasgaps::io
