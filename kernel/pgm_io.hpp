// PGM images (Netpbm P2 ASCII and P5 binary, maxval up to 65535) as 2D images of shape
// (height, width): row y of the file is axis 0 = y, column x is axis 1 = x.
// Malformed or truncated files are IoError naming the file and the line. Writing is P5,
// atomic (temporary file + rename), maxval 255 when every value fits, else 65535; values
// above 65535 are InvalidArgument.
#pragma once

#include <zdg/kernel/image.hpp>

#include <cstdint>
#include <string>

namespace zdg {

Image<std::uint16_t> read_pgm(const std::string& path);
void write_pgm(const std::string& path, const Image<std::uint64_t>& image);

} // namespace zdg
