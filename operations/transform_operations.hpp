// The lean distance transform of zdg transform dt (issue #15): an .npy file in, an .npy file
// out, without holding either as an image. The input is mapped and read in place (items of any
// integer width or bool: background where all bytes are 0, as npy_to_mask reads them); the
// values are computed in one buffer of the output's type (the output file's own pages, mapped,
// when it is well below the kernel's dirty-page threshold), or out of core within a memory
// budget (kernel/transforms/out_of_core_transform.hpp), and written once, in the narrowest
// unsigned dtype that holds the largest possible value (distance_transform_max_value). The
// peak memory is about the input's bytes plus the output's (in memory), or the budget (out of
// core). O(N d) for l1, l2, l_inf and O(N d log) otherwise (kernel/transforms/
// distance_transform.hpp); the values are exact integers (d^p, or d for l_inf).
//
// Errors: IoError for an unreadable or malformed file, a 0-dimensional or empty array, a disk
// too small (the output's space is reserved first); InvalidArgument for lower bounds of the
// wrong length, an image without background (transform options), and, when out of core is
// asked, a file it does not take (Fortran order, float items, values past 64 bits).
#pragma once

#include <zdg/kernel/io/npy_io.hpp>
#include <zdg/kernel/transforms/distance_transform.hpp>
#include <zdg/kernel/transforms/out_of_core_transform.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace zdg {

struct NpyTransformOptions {
  std::string input;               ///< an .npy file
  std::string output;              ///< the .npy file written (e.g. an OutputSet's staging file)
  std::vector<std::int64_t> lower; ///< the domain's lower bounds (empty: 0)
  TransformOptions transform;
  /// Out of core when asked, or when the in-memory transform would need more than the budget
  /// (none given: in memory, and a 4 GiB budget out of core).
  bool out_of_core = false;
  std::optional<std::uint64_t> memory_budget;
  std::function<void(const OutOfCoreProgress&)> out_of_core_progress;
  std::function<void(int, int)> pass_progress; ///< (passes done, passes) in memory
  /// In memory, the values are computed in the output file's own pages through a shared mapping
  /// (true: no buffer beside them, no copy) or in a buffer then written (false); by default the
  /// first where the output fits shared_mapping_fits (kernel/io/mapped_file.hpp). The same bytes.
  std::optional<bool> shared_output;
};

struct NpyTransformResult {
  Domain domain;
  DType dtype = DType::U8;
  std::uint64_t max_value = 0;
  double seconds = 0;
  bool out_of_core = false;
  std::uint64_t memory_budget = 0, in_memory_bytes = 0;
};

/// The transform of the file, or nothing (nothing read past the header, nothing written) for a
/// file the lean path does not take (Fortran order, float items, values past 64 bits) when out
/// of core is not asked: the caller then reads it as an image.
std::optional<NpyTransformResult> npy_distance_transform(const NpyTransformOptions& options);

/// The narrowest unsigned dtype that holds every value up to `bound` (none past 64 bits).
std::optional<DType> narrowest_unsigned(const BigInt& bound);

/// fn(std::type_identity<T>{}) with T the unsigned integer type of the dtype (uint8, uint16,
/// uint32; uint64 for any other): the type of the values written in that dtype.
template <class Fn>
void with_unsigned(DType dtype, Fn&& fn) {
  switch (dtype) {
  case DType::U8:
    return fn(std::type_identity<std::uint8_t>{});
  case DType::U16:
    return fn(std::type_identity<std::uint16_t>{});
  case DType::U32:
    return fn(std::type_identity<std::uint32_t>{});
  default:
    return fn(std::type_identity<std::uint64_t>{});
  }
}

} // namespace zdg
