// Distance transform of a binary image in the l_p metrics, exact: DT(x) = min d_p(x, y)^p over
// the background points y (value 0; d_inf for l_inf; periodic on the torus axes, see
// (ARCHITECTURE.md, Conventions)), 0 on the background. Separable lower envelopes
// (kernel/transforms/separable_engine.hpp; Hirata 1996, Meijster et al. 2000, Maurer et al.
// 2003): O(N d) for l_1, l_2, l_inf, O(N d log n) otherwise; the thread count does not change
// the result. Width: the largest value sum_k m_k^p (m_k = n_k - 1, floor(n_k / 2) on a torus
// axis) must fit T (OverflowError; BigInt always fits); the engine runs on the narrowest of
// int32 / int64 / __int128 / GMP. No background: InvalidArgument.
#pragma once

#include <zdg/arith/integer.hpp>
#include <zdg/kernel/images/image.hpp>
#include <zdg/kernel/transforms/lp_metric.hpp>

#include <cstdint>
#include <functional>

namespace zdg {

/// The largest value a distance transform on this domain can take.
BigInt distance_transform_max_value(const Domain& domain, const TransformOptions& opt);

/// The distance transform of `shape` (nonzero = foreground). T: std::uint8_t, std::uint16_t,
/// std::uint32_t, std::uint64_t, std::int64_t or BigInt.
template <class T>
Image<T> distance_transform(const Image<std::uint8_t>& shape, const TransformOptions& opt = {});

/// The same on buffers: the mask is dom.size() items of mask_item_bytes (1, 2, 4 or 8) bytes, C
/// order, background when all bytes are 0, read in place (e.g. a mapped .npy); the values go to
/// out[0 .. dom.size()). T: std::uint8_t .. std::uint64_t or std::int64_t. Extra memory: the
/// engine's line buffers, and a temporary when its width differs from T's. Errors as above.
/// progress (optional): called after each of the d passes with (passes done, d), same thread.
/// max_value (optional): set to the largest value written, taken while the last pass's lines are
/// in cache (no scan of the output after).
template <class T>
void distance_transform_into(const Domain& dom, const std::uint8_t* mask, int mask_item_bytes,
                             const TransformOptions& opt, T* out,
                             const std::function<void(int done, int total)>& progress = {},
                             std::uint64_t* max_value = nullptr);

/// Throws InvalidArgument when `shape` has no background point (value 0).
void require_background(const Image<std::uint8_t>& shape, const TransformOptions& opt);
/// The same for a mask of dom.size() items of mask_item_bytes bytes (1, 2, 4, 8) in C order
/// read in place (an item is background when all its bytes are 0).
void require_background(const Domain& dom, const std::uint8_t* mask, const TransformOptions& opt,
                        int mask_item_bytes = 1);

namespace detail {
/// The error of require_background (for transforms that look for background in parts).
[[noreturn]] void throw_no_background(const TransformOptions& opt);
} // namespace detail

} // namespace zdg
