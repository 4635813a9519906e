// A compressed stream that starts well and turns to garbage: `good` zero bytes deflated
// and sync-flushed (no final block, so the stream goes on), then `garbage` pseudo-random
// bytes (seeded) on which inflate fails. gzip selects the gzip wrapper (a .nii.gz) instead
// of zlib's (a .vol Version 3). For the tests that a small corrupt file claiming a large
// volume fails before the claim is allocated.
#pragma once

#include <zlib.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace zdg::test {

inline std::string good_then_garbage(const std::string& prefix, std::size_t good,
                                     std::size_t garbage, bool gzip, std::uint64_t seed = 41) {
  z_stream zs{};
  deflateInit2(&zs, 6, Z_DEFLATED, gzip ? 31 : 15, 8, Z_DEFAULT_STRATEGY);
  std::vector<unsigned char> in(prefix.begin(), prefix.end());
  in.resize(prefix.size() + good, 0);
  std::vector<unsigned char> buf(deflateBound(&zs, in.size()) + 64);
  zs.next_in = in.data();
  zs.avail_in = static_cast<uInt>(in.size());
  zs.next_out = buf.data();
  zs.avail_out = static_cast<uInt>(buf.size());
  deflate(&zs, Z_SYNC_FLUSH);
  std::string out(buf.begin(), buf.begin() + static_cast<std::ptrdiff_t>(zs.total_out));
  deflateEnd(&zs);
  std::uint64_t x = seed * 0x9E3779B97F4A7C15ull + 1;
  for (std::size_t i = 0; i < garbage; ++i) {
    x ^= x << 13;
    x ^= x >> 7;
    x ^= x << 17;
    out.push_back(static_cast<char>(x >> 24));
  }
  return out;
}

} // namespace zdg::test
