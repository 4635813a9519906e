// DGtal .vol volumes, Version 2 (raw) and Version 3 (zlib): read and write 3D uint8 images.
//
// File layout: a text header of "Key: value" lines ending with a line "." (keys X, Y, Z
// required; Center-X/Y/Z, Voxel-Size, Alpha-Color, Voxel-Endian, Int-Endian, Version read and
// checked; a missing Version is read as 2), then the X*Y*Z voxel bytes, x fastest, then y,
// then z. Version 2 stores them as they are; Version 3 stores them as ONE zlib stream (RFC
// 1950, what DGtal's VolWriter writes by default through boost::iostreams::zlib_compressor).
// As an image: shape (Z, Y, X) in C order, lower bound Center - (size - 1) / 2 per axis (the
// inverse of DGtal's VolWriter, which writes Center = lower + (upper - lower) / 2; 0 when
// the Center keys are absent).
//
// Reading is hardened against hostile files (every failure is one IoError naming the file
// and the problem, before any allocation the header cannot justify):
//   - at most 64 header lines of at most 256 bytes, each key at most once;
//   - every header number is range-checked before any arithmetic: X, Y, Z in [1, 2^31 - 1],
//     Center-X/Y/Z in [-2^61, 2^61] (so every coordinate lies in (-2^62, 2^62) and the
//     difference of two fits in 64 bits); sums and products are computed with overflow checks;
//   - Version 2: the payload must be exactly X*Y*Z bytes (truncated or trailing data is an
//     error); Version 3: X*Y*Z must not exceed 1032 times the compressed size plus 64 (the
//     largest expansion deflate allows), the stream must inflate to exactly X*Y*Z bytes and
//     end at the end of the file (truncated, corrupt or trailing data is an error);
//   - Version 3 takes memory as the inflated bytes arrive (kernel/io/input_file.hpp's
//     ArrivingBytes), not for the claim: a small corrupt file claiming a large volume fails
//     with little memory taken.
// Cost: O(X*Y*Z) time, memory the compressed payload plus the image (Version 3: plus one
// 16 MiB piece while the pieces are joined). Writing is atomic
// (kernel/io/output_files.hpp); Version 3 uses zlib's default level (6), as DGtal does.
#pragma once

#include <zdg/kernel/images/image.hpp>

#include <cstdint>
#include <istream>
#include <string>

namespace zdg {

/// Reads a .vol file (Version 2 or 3).
Image<std::uint8_t> read_vol(const std::string& path);
/// Reads a .vol file from a seekable stream; `name` is the file name used in error messages.
Image<std::uint8_t> read_vol(std::istream& in, const std::string& name);

/// The bytes of a .vol file of `image` (3D) in Version 2 or 3 (InvalidArgument otherwise).
std::string vol_file_bytes(const Image<std::uint8_t>& image, int version = 3);
/// Writes image (3D) atomically as a .vol file of this Version (2 or 3).
void write_vol(const std::string& path, const Image<std::uint8_t>& image, int version = 3);
/// Same for values 0..255 held in a wider type (InvalidArgument for a larger value).
void write_vol(const std::string& path, const Image<std::uint64_t>& image, int version = 3);

} // namespace zdg
