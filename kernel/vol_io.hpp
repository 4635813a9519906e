// DGtal .vol volumes (uncompressed, Version 2): a text header of "Key: value" lines ending
// with a line "." (keys X, Y, Z required; Center-X/Y/Z, Voxel-Size, Alpha-Color,
// Voxel-Endian, Int-Endian, Version read and checked), then X*Y*Z bytes with x fastest.
// As an image: shape (Z, Y, X) in C order, lower bound the DGtal domain lower bound
// Center - (size - 1) / 2 (0 when the Center keys are absent). Version 3 (zlib) and
// truncated or malformed files are IoError naming the file and the line; writing is atomic.
#pragma once

#include <zdg/kernel/image.hpp>

#include <cstdint>
#include <string>

namespace zdg {

Image<std::uint8_t> read_vol(const std::string& path);
/// image: 3D with values 0..255 (InvalidArgument otherwise).
void write_vol(const std::string& path, const Image<std::uint64_t>& image);

} // namespace zdg
