// The separable lower-envelope engine shared by the distance transform, the Voronoi map, the
// power map, the reverse distance transform and the reduced medial axis.
//
// Given initial values F_0(c) (a site c of "weight" -F_0(c); +inf where there is no site), it
// computes for every point x
//     F(x) = min_c F_0(c) + d_p(x, c)^p          (l_p, p finite: sums of p-th powers)
//     F(x) = min_c max(F_0(c), d_inf(x, c))      (l_inf, F_0 >= 0)
// and, on request, a minimising site. One pass per axis (the last, contiguous axis first): in
// each pass every line is independent and is the 1D lower envelope of the functions
// g_i(t) = F(i) + |t - i|^p, computed with the stack and "separator" sweep of Meijster,
// Roerdink and Hesselink (2000), as extended to every l_p by Hirata (1996) and
// Maurer, Qi and Raghavan (2003): for i < u the set {t : g_u(t) < g_i(t)} is an up-set, so
// the separator is a closed form for l_1, l_2, l_inf and otherwise an exact gallop-and-bisect
// search on a table of p-th powers, started from a floating-point Newton guess (the guess
// only chooses where to look; every decision is an integer comparison). Ties go to the site with
// the smaller position on the line (the result is the same for every thread count). A periodic axis
// of extent n is the line of 3n positions holding three copies of the values, queried on the middle
// copy.
//
// Cost: O(N d) per transform for l_1, l_2, l_inf and O(N d log n) for other p, N points.
// Lines of non-contiguous axes are processed in blocks of adjacent lines (gathered into a
// small buffer) so that every cache line read is used; passes split their lines over threads.
// With AVX-512F the int32 engine without sites runs vectorized (separable_engine.cpp), the same
// integers, and with AVX-512F and DQ the int64 engine too (8 lines per vector, lines under 2^30
// points); portable envelopes skip local peaks when only values are asked (details:
// docs/NOTES.md, "kernel/transforms/separable_engine.hpp").
//
// Width: every value and intermediate is bounded at entry by
//     need = 2 (sum_k m_k^p + w_max + L^p) + 2 L
// (m_k the largest coordinate difference on axis k: n_k - 1, or floor(n_k/2) on a torus; L
// the longest line, 3 n_k on a torus; w_max the largest weight). The engine runs on int32
// when need < 2^31, int64, __int128, and GMP integers past that: exact for every input.
#pragma once

#include <zdg/arith/integer.hpp>
#include <zdg/kernel/images/image.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>
#include <zdg/kernel/transforms/lp_metric.hpp>

#include <cstdint>
#include <functional>
#include <type_traits>
#include <vector>

namespace zdg::detail {

enum class ValueWidth { I32, I64, I128, Big };

struct EnvelopeBounds {
  BigInt value_max; // the largest finite value of a transform without weights
  BigInt need;      // the bound on every intermediate (see above)
  ValueWidth width; // the narrowest engine type that holds need
};

/// Checks the options against the domain (torus flags, p) and computes the bounds.
EnvelopeBounds envelope_bounds(const Domain& dom, const TransformOptions& opt,
                               const BigInt& weight_max);

/// Bytes of one value of the engine type of width w (0 for BigInt, whose size varies).
std::uint64_t engine_value_bytes(ValueWidth w);

/// Throws OverflowError when the largest value b.value_max exceeds out_max (the largest value
/// of the output type), naming the metric: "<who>: values up to V (l2) do not fit ...".
void require_output_fits(const EnvelopeBounds& b, const TransformOptions& opt,
                         const BigInt& out_max, const char* who);

/// Throws InvalidArgument unless mask items have 1, 2, 4 or 8 bytes.
void require_mask_item_bytes(int mask_item_bytes, const char* who);

/// Allows (the default) or forbids the vectorized passes (AVX-512F, the int32 engine without
/// sites: the first pass of a one-byte mask, and the envelopes of lines of non-contiguous
/// axes, 16 lines per vector; AVX-512F and DQ, the int64 engine without sites: the same, 8
/// lines per vector); returns the previous setting. The results are the same either way: the
/// tests compare both.
bool set_envelope_simd(bool allowed);

/// Whether this CPU runs the vectorized envelope (AVX-512F; the int64 one also needs DQ).
bool envelope_simd_available();

/// Worker threads actually used for n points.
unsigned resolve_threads(unsigned requested, std::int64_t n);

/// The "no site" value of the engine type V for these bounds.
template <class V>
V envelope_infinity(const EnvelopeBounds& b);

/// Runs the passes in place on f[0, N). mask != nullptr: f is overwritten with the
/// transform of the sites {mask == 0} (all of weight 0); the mask has N items of
/// mask_item_bytes bytes (1, 2, 4 or 8: a point is a site when all its bytes are 0, so any
/// integer or bool array serves in place). Otherwise f holds F_0 (inf where
/// no site). sites (optional): on output the linear index of a minimising site (-1 where
/// there is none); in value mode it is initialised here.
template <class V>
void separable_envelope(const Domain& dom, const TransformOptions& opt, const std::uint8_t* mask,
                        V* f, const V& inf, std::vector<std::int64_t>* sites,
                        int mask_item_bytes = 1);

/// A part of the passes, for transforms that do not hold the whole volume at once
/// (kernel/transforms/out_of_core_transform.hpp). slices: the mask pass (or the identity) and the
/// passes along axes d-1 .. 1, whose lines lie in one slice of axis 0 (run them on a slab of whole
/// slices: a domain with fewer slices and the pointers at the slab's first slice); axis0: the
/// pass along axis 0 restricted to the columns [column_begin, column_end) of a slice (end -1:
/// all), from_mask: the values come from a mask (nonnegative). Running the slices on every slab,
/// then axis 0 on every column range, gives the values of the whole transform, to the bit: each
/// line sees the same operations in the same order.
struct EnvelopePart {
  bool slices = true, axis0 = true, from_mask = true;
  std::int64_t column_begin = 0, column_end = -1;
  std::function<void(int axis)> after_pass; // optional: called after each pass, with its axis
  /// Optional, for int32 and int64 values >= 0 (a distance transform): raised to the largest
  /// finite value the pass along axis 0 writes (d >= 2), read from each unit of lines while it
  /// is in cache instead of by a scan of the whole output after.
  std::uint64_t* max_value = nullptr;
};

template <class V>
void separable_envelope_part(const Domain& dom, const TransformOptions& opt,
                             const std::uint8_t* mask, V* f, const V& inf,
                             std::vector<std::int64_t>* sites, int mask_item_bytes,
                             const EnvelopePart& part);

/// Calls fn(std::type_identity<V>{}) with the engine type of width w.
template <class Fn>
decltype(auto) with_value_type(ValueWidth w, Fn&& fn) {
  switch (w) {
  case ValueWidth::I32:
    return fn(std::type_identity<std::int32_t>{});
  case ValueWidth::I64:
    return fn(std::type_identity<std::int64_t>{});
  case ValueWidth::I128:
    return fn(std::type_identity<int128_t>{});
  default:
    return fn(std::type_identity<BigInt>{});
  }
}

/// Exact conversion of an engine value to BigInt.
template <class V>
BigInt engine_to_bigint(const V& v) {
  if constexpr (std::is_same_v<V, BigInt>) {
    return v;
  } else {
    return int_cast<BigInt>(Int128(static_cast<int128_t>(v)));
  }
}

#define ZDG_ENGINE_EXTERN(V)                                                                       \
  extern template V envelope_infinity<V>(const EnvelopeBounds&);                                   \
  extern template void separable_envelope_part<V>(                                                 \
      const Domain&, const TransformOptions&, const std::uint8_t*, V*, const V&,                   \
      std::vector<std::int64_t>*, int, const EnvelopePart&);                                       \
  extern template void separable_envelope<V>(const Domain&, const TransformOptions&,               \
                                             const std::uint8_t*, V*, const V&,                    \
                                             std::vector<std::int64_t>*, int);
ZDG_ENGINE_EXTERN(std::int32_t)
ZDG_ENGINE_EXTERN(std::int64_t)
ZDG_ENGINE_EXTERN(int128_t)
ZDG_ENGINE_EXTERN(BigInt)
#undef ZDG_ENGINE_EXTERN

} // namespace zdg::detail
