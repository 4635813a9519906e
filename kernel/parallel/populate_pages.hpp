// Large buffers faulted in by all the workers at once.
//
// A buffer of hundreds of megabytes (a mesh's indices and vertices) first touched by one
// thread costs one page fault per 4 KiB page: 70,000 faults for 283 MB, about as long as the
// work that fills it, and serial (std::vector's value-initialization). assign_populated()
// reserves the capacity of a vector (untouched: the allocator maps fresh zero pages), has the
// kernel map its pages in `threads` parallel ranges (madvise(MADV_POPULATE_WRITE), Linux 5.14
// and later), then fills it, so that the fill finds them mapped. Where the call is not
// offered (or for element types that are not trivially copyable) it only assigns. The contents
// never depend on it. The range is also advised for transparent huge pages (MADV_HUGEPAGE,
// honoured where the system's setting is "madvise" or "always"): one fault per 2 MiB
// (timings: bench/README.md, "kernel/parallel/populate_pages.hpp").
#pragma once

#include <cstddef>
#include <type_traits>
#include <vector>

namespace zdg {

/// Maps the pages of [p, p + bytes) for writing, split among `threads` workers (0 = all
/// cores); nothing under 4 MiB or where unsupported. Never fails.
void populate_pages(void* p, std::size_t bytes, unsigned threads) noexcept;

/// v.assign(n, value), the new storage's pages mapped by `threads` workers first.
template <class T>
void assign_populated(std::vector<T>& v, std::size_t n, unsigned threads, const T& value = T{}) {
  if constexpr (std::is_trivially_copyable_v<T>) {
    if (v.capacity() < n) {
      std::vector<T>().swap(v);
      v.reserve(n);
      populate_pages(v.data(), n * sizeof(T), threads);
    }
  }
  v.assign(n, value);
}

} // namespace zdg
