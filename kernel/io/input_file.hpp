// Reading an input file whole, with the checks every reader shares: the path names a regular
// file or a pipe (not a folder, not a device such as /dev/zero that never ends), it can be
// opened, and it is not larger than the caller's limit. The parsers themselves work on the
// bytes (parse_npy, parse_pgm, parse_point_file, ...: fuzzed as library functions); the
// read_* functions are this plus the parser.
//
// Cost: one pass over the file; memory: its size. Errors are IoError naming the path.
#pragma once

#include <cstdint>
#include <string>

namespace zdg {

/// Default limit of read_input_file: 4 GiB.
inline constexpr std::uint64_t kMaxInputFileBytes = std::uint64_t{1} << 32;

/// The whole content of the file at path (a regular file, or a pipe such as /dev/stdin read
/// to its end). IoError when it does not exist, is a folder or a device, cannot be read, or
/// holds more than max_bytes.
std::string read_input_file(const std::string& path, std::uint64_t max_bytes = kMaxInputFileBytes);

/// The size of a regular file at path (IoError as read_input_file for anything else).
std::uint64_t input_file_size(const std::string& path);

} // namespace zdg
