// Raw volumes: the values of a C-order array (x fastest), little-endian, nothing else in the
// file. The shape and the dtype come from the user (`--raw-shape Z,Y,X --raw-dtype uint8`),
// so the file size must be exactly the product of the shape times the dtype's size: a
// different size is an IoError naming the file and both sizes (checked before anything is
// allocated, the product with overflow checks). Writing stores the bytes of the array
// atomically (kernel/io/output_files.hpp). Cost: O(size) time and memory.
#pragma once

#include <zdg/kernel/images/scalar_volume.hpp>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace zdg {

/// "Z,Y,X" or "Y,X": 2 or 3 positive decimal integers (InvalidArgument otherwise).
std::vector<std::int64_t> parse_raw_shape(const std::string& text);

/// Reads a raw file of this shape (2 or 3 axes) and dtype.
ScalarVolume read_raw(const std::string& path, const std::vector<std::int64_t>& shape, DType dtype);
/// The same from bytes in memory; `name` is used in messages.
ScalarVolume read_raw_bytes(std::string_view bytes, const std::string& name,
                            const std::vector<std::int64_t>& shape, DType dtype);
/// Writes the array's bytes (little-endian, C order) atomically.
void write_raw(const std::string& path, const ScalarVolume& volume);

} // namespace zdg
