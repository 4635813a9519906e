// Reading an input file whole, with the checks every reader shares: the path names a regular
// file or a pipe (not a folder, not a device such as /dev/zero that never ends), it can be
// opened, and it is not larger than the caller's limit. The parsers themselves work on the
// bytes (parse_npy, parse_pgm, parse_point_file, ...: fuzzed as library functions); the
// read_* functions are this plus the parser.
//
// Cost: one pass over the file; memory: its size. Errors are IoError naming the path.
//
// ArrivingBytes holds the output of a decompressor whose total a header claims: memory is
// taken as the bytes arrive, in pieces of at most 16 MiB, never for the claim alone, so that
// a small corrupt file claiming a large volume takes little memory before its error.
// Resident memory: the bytes that arrived plus one piece. take() joins the pieces into one
// vector (one copy of the bytes), returning each piece to the system as soon as it is copied:
// the pieces are anonymous memory mappings, not heap blocks (a freed heap block can stay
// resident, which would double the peak), so the peak of take() is the bytes plus one piece.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace zdg {

/// Default limit of read_input_file: 4 GiB.
inline constexpr std::uint64_t kMaxInputFileBytes = std::uint64_t{1} << 32;

/// The whole content of the file at path (a regular file, or a pipe such as /dev/stdin read
/// to its end). IoError when it does not exist, is a folder or a device, cannot be read, or
/// holds more than max_bytes.
std::string read_input_file(const std::string& path, std::uint64_t max_bytes = kMaxInputFileBytes);

/// The size of a regular file at path (IoError as read_input_file for anything else).
std::uint64_t input_file_size(const std::string& path);

/// Bytes that arrive in pieces up to a claimed total (see above).
class ArrivingBytes {
public:
  static constexpr std::size_t kPiece = std::size_t{1} << 24;

  explicit ArrivingBytes(std::uint64_t claimed) : claimed_(claimed) {}
  ~ArrivingBytes();
  ArrivingBytes(const ArrivingBytes&) = delete;
  ArrivingBytes& operator=(const ArrivingBytes&) = delete;

  std::uint64_t claimed() const { return claimed_; }
  /// The bytes that arrived so far.
  std::uint64_t size() const { return size_; }
  /// Writable room for the next bytes: min(kPiece, claimed - size()) bytes at most (allocated
  /// now; std::bad_alloc when the system has none), empty once size() == claimed.
  std::span<std::uint8_t> room();
  /// n bytes were written at the start of room() (n <= its size).
  void arrived(std::size_t n);
  /// All the bytes, in order (the object is left empty).
  std::vector<std::uint8_t> take();

private:
  struct Piece {
    std::uint8_t* data = nullptr; // an anonymous mapping of `size` bytes
    std::size_t size = 0;
  };
  static void release(Piece& p);
  std::uint64_t claimed_ = 0, size_ = 0;
  std::vector<Piece> pieces_; // each full but the last
  std::size_t last_used_ = 0; // bytes used in pieces_.back()
};

} // namespace zdg
