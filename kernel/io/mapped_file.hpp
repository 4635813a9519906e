// Input files mapped into memory and output files reserved on the disk, for volumes the size of
// RAM: `zdg transform dt` reads its input through a mapping (no read buffer next to the image)
// and writes its output into a reserved file, so a volume is never held twice.
//
//   MappedInput in("mask.npy");                  // read-only, shared with the page cache
//   ReservedFile out(staged, bytes);             // space reserved on the disk first
//   out.write(0, header.data(), header.size());  // then the values, at their offsets
//   out.finish();                                // closed: then rename it
//
// ReservedFile reserves the whole file with posix_fallocate, so a disk that is too small is an
// IoError at construction ("does not fit on the disk: needs N bytes, M free"), before any work.
// Outputs are written with pwrite, not through a shared mapping: the passes of a transform
// modify every value several times, and a mapped output larger than the kernel's dirty-page
// threshold is written back to the disk again at each modification (measured: 700 GB written
// for a 4 GB output). Below it (shared_mapping_fits: half the background threshold, where the
// kernel starts writing back), SharedMapping maps a ReservedFile for writing, so that values
// computed in place are the file's pages with no buffer beside them and no copy (issue #40
// item 3: a 512^3 uint32 output, 537 MB). All failures are IoError naming the file and the
// reason. Cost: the mapping is O(1), its pages are read as they are touched (the resident set
// counts them).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace zdg {

/// A regular file mapped read-only (the whole file).
class MappedInput {
public:
  explicit MappedInput(const std::string& path);
  ~MappedInput();
  MappedInput(const MappedInput&) = delete;
  MappedInput& operator=(const MappedInput&) = delete;

  const unsigned char* data() const { return data_; }
  std::uint64_t size() const { return size_; }

private:
  const unsigned char* data_ = nullptr;
  std::uint64_t size_ = 0;
};

/// A new file of `size` bytes (created or truncated), its blocks reserved on the disk at
/// construction, written and read back at offsets (pwrite, pread). finish() closes it; the
/// destructor closes without the checks.
class ReservedFile {
public:
  ReservedFile(const std::string& path, std::uint64_t size);
  ~ReservedFile();
  ReservedFile(const ReservedFile&) = delete;
  ReservedFile& operator=(const ReservedFile&) = delete;

  std::uint64_t size() const { return size_; }
  /// Writes bytes at offset (within the reserved size); IoError on failure.
  void write(std::uint64_t offset, const void* data, std::uint64_t bytes);
  /// Reads bytes at offset; IoError on failure or a short file.
  void read(std::uint64_t offset, void* data, std::uint64_t bytes) const;
  /// Closes the file; IoError on failure.
  void finish();

private:
  friend class SharedMapping;
  std::string path_;
  std::uint64_t size_ = 0;
  int fd_ = -1;
};

/// The whole of an open ReservedFile mapped for reading and writing (MAP_SHARED): what is stored
/// through data() lands in the file's pages in the page cache, written back by the kernel as a
/// write's would be (its blocks are reserved: no disk-full error can follow). The pages are
/// advised for huge pages and mapped by `threads` workers at construction (populate_pages).
/// Unmapped by the destructor; close the file after. IoError when the mapping fails.
class SharedMapping {
public:
  SharedMapping(const ReservedFile& file, unsigned threads);
  ~SharedMapping();
  SharedMapping(const SharedMapping&) = delete;
  SharedMapping& operator=(const SharedMapping&) = delete;

  unsigned char* data() const { return data_; }

private:
  unsigned char* data_ = nullptr;
  std::uint64_t size_ = 0;
};

/// Whether an output of `bytes` may be written through a SharedMapping: at most half the
/// kernel's background dirty-page threshold (/proc/sys/vm/dirty_background_bytes, else
/// dirty_background_ratio percent of MemAvailable), so that the kernel does not write it back
/// while it is still being modified. False where these cannot be read.
bool shared_mapping_fits(std::uint64_t bytes);

/// Writes n values of T (little-endian, as in memory) at byte `offset` of `out`, in pieces of
/// 4 MiB by `threads` workers (positional writes of disjoint ranges), and returns the largest
/// value: each piece's maximum is taken just before its write, while the piece is in cache.
/// The copies into the page cache themselves take the file's lock in turn (ext4 and xfs
/// serialize buffered writes to one file: perf shows a second writer spinning on it), so the
/// workers overlap one's maximum with another's copy, not two copies; one worker writing every
/// piece measured the same wall time. The copy costs what the page cache costs: 56-96 ms for
/// 512 MB on the development VM when the guest's free pages are backed by the host, over 0.6 s
/// when they are not (bench/transform_bench, OutputWrite). T: std::uint8_t, std::uint16_t,
/// std::uint32_t, std::uint64_t. IoError from the writes.
template <class T>
T write_values_max(ReservedFile& out, std::uint64_t offset, const T* values, std::int64_t n,
                   unsigned threads);

} // namespace zdg
