// Distance transform of a binary image in the l_p metrics, exact.
//
// For every point x of the domain, DT(x) = min { d_p(x, y)^p : y background } for finite p
// (so the squared Euclidean distance for l_2) and min { d_inf(x, y) } for l_inf, where the
// background is the set of points of value 0 and d is periodic along the torus axes
// (DESIGN.md, "Distance transform"). Background points get 0.
//
// Algorithm: separable lower envelopes, one pass per axis (kernel/transforms/separable_engine.hpp;
// Hirata 1996, Meijster et al. 2000, Maurer et al. 2003), O(N d) for l_1, l_2, l_inf and
// O(N d log n) for other p; multi-threaded, the result does not depend on the thread count.
//
// Width: the largest value is distance_transform_max_value() = sum_k m_k^p (max_k m_k for
// l_inf) with m_k = n_k - 1, or floor(n_k / 2) on a torus axis. distance_transform<T> checks at
// entry that it fits T (OverflowError otherwise: use a wider T, BigInt always fits); the
// computation itself runs on the narrowest of int32 / int64 / __int128 / GMP that its
// intermediates need. An image without background is an InvalidArgument.
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

/// The same on buffers: the mask is dom.size() items of mask_item_bytes bytes (1, 2, 4 or 8, C
/// order; an item is background when all its bytes are 0), read where it lies (e.g. a mapped
/// .npy file, kernel/io/mapped_file.hpp), and the values go to out[0 .. dom.size()) (e.g. a mapped
/// output file). T: std::uint8_t, std::uint16_t, std::uint32_t, std::uint64_t or std::int64_t.
/// Memory beyond the two buffers: the per-thread line buffers of the engine, plus one temporary
/// of the engine's width when it differs from T's (none when they agree: the engine works in
/// the output). The checks and errors of distance_transform. progress (optional) is called
/// after each of the d passes with (passes done, d), from the calling thread, e.g. to show a
/// long transform's progress on a terminal (`zdg transform dt`).
template <class T>
void distance_transform_into(const Domain& dom, const std::uint8_t* mask, int mask_item_bytes,
                             const TransformOptions& opt, T* out,
                             const std::function<void(int done, int total)>& progress = {});

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
