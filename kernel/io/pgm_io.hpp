// PGM images (Netpbm P2 ASCII and P5 binary, maxval up to 65535) as 2D images of shape
// (height, width): row y of the file is axis 0 = y, column x is axis 1 = x.
// Malformed or truncated files are IoError naming the file and the line; the raster the
// header announces (width x height, a product checked against overflow) is checked against
// the bytes the file holds before the image is allocated. Header numbers are decimal
// (parse_integer). parse_pgm works on the bytes of a file (the fuzz target). Writing is P5,
// atomic (temporary file + rename), maxval 255 when every value fits, else 65535; values
// above 65535 are InvalidArgument.
#pragma once

#include <zdg/kernel/images/image.hpp>

#include <cstdint>
#include <string>
#include <string_view>

namespace zdg {

/// The image stored in the bytes of a PGM file (source names it in errors).
Image<std::uint16_t> parse_pgm(std::string_view bytes, const std::string& source);
Image<std::uint16_t> read_pgm(const std::string& path);
void write_pgm(const std::string& path, const Image<std::uint64_t>& image);

} // namespace zdg
