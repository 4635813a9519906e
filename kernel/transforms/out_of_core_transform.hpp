// The exact distance transform of volumes larger than the memory: slabs of slices, then
// blocks of columns, between a mask read in place (a mapped file) and an output file.
//
// Phase 1: slabs of whole slices, transformed along axes d-1 .. 1, the mask's pages released
// after each slab (madvise) so the resident set stays within the budget; phase 2: blocks of
// columns transformed along axis 0, written with pwrite. The values equal the in-memory
// engine's to the bit, for every metric and torus axis. Memory: slab and block sized to the
// budget (at least one slice, one column); a scratch file of N x sizeof(V) bytes when T is
// narrower than the engine's V. Time: O(N d) (l_1, l_2, l_inf), plus one more write and read of
// the values. Width: the 64-bit engines only (values up to 2^63: every l_1, l_2, l_inf volume
// below 2^20 per side), InvalidArgument beyond, and d >= 2 (design: docs/NOTES.md,
// "kernel/transforms/out_of_core_transform.hpp").
#pragma once

#include <zdg/kernel/images/image.hpp>
#include <zdg/kernel/transforms/lp_metric.hpp>

#include <cstdint>
#include <functional>
#include <string>

namespace zdg {

/// What an out-of-core run reports as it goes: the phase ("slices" or "axis 0"), the part done
/// and the total (slices, or columns), and the bytes read and written so far.
struct OutOfCoreProgress {
  std::string phase;
  std::int64_t done = 0, total = 0;
  std::uint64_t bytes_read = 0, bytes_written = 0;
};

struct OutOfCoreOptions {
  std::uint64_t memory_budget = std::uint64_t{4} << 30; // bytes for the slab or the block
  /// Folder of the scratch file (when T is narrower than the engine's values); "" = none
  /// allowed (InvalidArgument if one is needed).
  std::string scratch_folder;
  /// The mask is a mapping of a file (MappedInput): its pages are released after each slab.
  /// Never set it for ordinary memory, whose released pages would read back as zeros.
  bool mask_is_mapped_file = false;
  std::function<void(const OutOfCoreProgress&)> progress = {};
};

class ReservedFile;

/// The distance transform of the mask (dom.size() items of mask_item_bytes bytes, C order,
/// background = all bytes 0) into the file out, from byte out_offset on (dom.size() values of
/// T, little-endian), by slabs and column blocks. T: std::uint8_t, std::uint16_t,
/// std::uint32_t, std::uint64_t. The values equal distance_transform<T>'s; its errors, plus
/// InvalidArgument for a 1-D domain, a budget below one slice of the mask and values, or
/// values past 2^63, and IoError from the files. Returns the largest value.
template <class T>
T distance_transform_out_of_core(const Domain& dom, const std::uint8_t* mask, int mask_item_bytes,
                                 const TransformOptions& opt, ReservedFile& out,
                                 std::uint64_t out_offset, const OutOfCoreOptions& ooc = {});

/// Bytes the in-memory transform of `dom` with output type T holds at its peak (mask items,
/// output, and the engine's temporary when its width differs from T's), for the choice
/// between the two paths.
template <class T>
std::uint64_t in_memory_transform_bytes(const Domain& dom, const TransformOptions& opt,
                                        int mask_item_bytes);

} // namespace zdg
