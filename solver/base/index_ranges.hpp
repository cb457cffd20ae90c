#pragma once
/// Work over an index range split among the cores: the model-sized setup passes (the stiffness
/// pattern, the assembly's scatter positions) run before anything else could use the second core.

#include <cstddef>
#include <functional>

namespace saasgaps {

/// Calls work(begin, end, r) on consecutive ranges r = 0, 1, ... (range_count of them) that together
/// cover [0, n), each on a thread of its own (the caller's thread takes the first), and returns when
/// all have. Ranges of at least
/// `smallest` indices: small n stays on the calling thread. work must only write what its range
/// owns. An exception from any range propagates once every range is done.
void for_each_range(std::size_t n, const std::function<void(std::size_t begin, std::size_t end, unsigned r)>& work,
                    std::size_t smallest = 4096);

/// The ranges for_each_range uses for n indices: at most parallel_threads(), each of at least
/// `smallest` indices, at least 1.
unsigned range_count(std::size_t n, std::size_t smallest = 4096);

/// Threads one analysis may use for its own parallel passes (these ranges, the result's formatting):
/// the cores', at most 4, until set. A server that solves several jobs side by side sets 1, so that
/// its jobs share the cores instead of each claiming all of them.
unsigned parallel_threads();
void set_parallel_threads(unsigned threads);

}  // namespace saasgaps
