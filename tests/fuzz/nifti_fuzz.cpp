// Fuzz target: NIfTI-1/2 files through read_nifti (the reference library reads from files, so
// each input goes through a temporary file). The first byte picks the name: odd, the rest is
// gzip-compressed into a .nii.gz (so that the header is reached through zlib too); even, the
// rest is written as a .nii. Every input must end in a volume or a zdg::Error.
#include <zdg/arith/error.hpp>
#include <zdg/kernel/io/nifti_io.hpp>

#include <zlib.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <unistd.h>

namespace {

std::string temp_name(bool gz) {
  return "/tmp/zdg_nifti_fuzz_" + std::to_string(::getpid()) + (gz ? ".nii.gz" : ".nii");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const bool gz = (data[0] & 1) != 0;
  const std::string path = temp_name(gz);
  if (gz) {
    gzFile f = gzopen(path.c_str(), "wb1");
    if (f == nullptr) return 0;
    if (size > 1) gzwrite(f, data + 1, static_cast<unsigned>(size - 1));
    gzclose(f);
  } else {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (f == nullptr) return 0;
    std::fwrite(data + 1, 1, size - 1, f);
    std::fclose(f);
  }
  try {
    const auto v = zdg::read_nifti(path);
    if (v.array.bytes.size() > 1032 * size + 4096 && !gz) __builtin_trap();
  } catch (const zdg::Error&) {
  }
  std::remove(path.c_str());
  return 0;
}
