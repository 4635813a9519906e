#include <zdg/kernel/parallel/populate_pages.hpp>

#include <zdg/kernel/parallel/parallel_for.hpp>

#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace zdg {

void populate_pages(void* p, std::size_t bytes, unsigned threads) noexcept {
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
  constexpr std::uintptr_t page = 4096;
  if (p == nullptr || bytes < (std::size_t{4} << 20)) return;
  const auto begin = reinterpret_cast<std::uintptr_t>(p);
  const std::uintptr_t lo = (begin + page - 1) & ~(page - 1), hi = (begin + bytes) & ~(page - 1);
  const auto pages = static_cast<std::int64_t>((hi - lo) / page);
#if defined(MADV_HUGEPAGE)
  // Transparent huge pages where the system offers them on request (the common "madvise"
  // setting): one fault per 2 MiB instead of per 4 KiB, and fewer TLB misses for the passes
  // that stride across the buffer. Advice only, like the population below.
  ::madvise(reinterpret_cast<void*>(lo), hi - lo, MADV_HUGEPAGE);
#endif
  try {
    parallel_chunks(pages, threads, [&](std::int64_t b, std::int64_t e) {
      // Advice only: an old kernel answers EINVAL and the pages fault in on first touch.
      ::madvise(reinterpret_cast<void*>(lo + std::uintptr_t(b) * page), std::size_t(e - b) * page,
                MADV_POPULATE_WRITE);
    });
  } catch (...) { // no thread to start: the first touch maps the pages
  }
#else
  (void)p;
  (void)bytes;
  (void)threads;
#endif
}

} // namespace zdg
