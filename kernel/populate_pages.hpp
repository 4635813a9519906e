// Large buffers faulted in by all the workers at once.
//
// A buffer of hundreds of megabytes (a mesh's indices and vertices) first touched by one
// thread costs one page fault per 4 KiB page: 70,000 faults for 283 MB, about as long as the
// work that fills it, and serial (std::vector's value-initialization). reserve_populated()
// reserves the capacity of a vector (untouched: the allocator maps fresh zero pages) and has
// the kernel map its pages in `threads` parallel ranges (madvise(MADV_POPULATE_WRITE), Linux
// 5.14 and later), so that the fill that follows finds them mapped. Where the call is not
// offered it only reserves. The contents never depend on it. (Huge pages were measured too:
// the first fault of a fresh process may then stall in memory compaction, 0.4 s for 300 MB.)
#pragma once

#include <cstddef>
#include <vector>

namespace zdg {

/// Maps the pages of [p, p + bytes) for writing, split among `threads` workers (0 = all
/// cores); nothing under 4 MiB or where unsupported. Never fails.
void populate_pages(void* p, std::size_t bytes, unsigned threads) noexcept;

/// v.reserve(n), with the new storage mapped in parallel.
template <class T>
void reserve_populated(std::vector<T>& v, std::size_t n, unsigned threads) {
  if (v.capacity() >= n) return;
  v.reserve(n);
  populate_pages(v.data(), n * sizeof(T), threads);
}

} // namespace zdg
