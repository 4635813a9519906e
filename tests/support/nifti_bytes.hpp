// NIfTI files built byte by byte (independent of the library's writer), for the tests of
// bad headers: a NIfTI-1 or NIfTI-2 single file of uint8 voxels 0, 1, 2, ... (mod 251), a
// field replaced at its byte offset, and an in-memory gzip for .nii.gz.
//   NIfTI-1 offsets: dim 40 (int16 x 8), datatype 70, bitpix 72, pixdim 76 (float x 8),
//   vox_offset 108 (float), magic 344.   NIfTI-2: magic 4, datatype 12, bitpix 14,
//   dim 16 (int64 x 8), pixdim 104 (double x 8), vox_offset 168 (int64).
#pragma once

#include <zlib.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace zdg::test {

/// bytes with the value v (host order) stored at offset off.
template <class T>
std::string patched(std::string bytes, std::size_t off, T v) {
  std::memcpy(bytes.data() + off, &v, sizeof v);
  return bytes;
}

inline std::string voxel_ramp(std::int64_t n) {
  std::string data(static_cast<std::size_t>(n), '\0');
  for (std::size_t i = 0; i < data.size(); ++i) data[i] = static_cast<char>(i % 251);
  return data;
}

/// NIfTI-2, vox_offset 544 after the 4-byte extension flag; big_endian stores every header
/// field in the other byte order.
inline std::string nifti2_bytes(std::int64_t nx, std::int64_t ny, std::int64_t nz,
                                bool big_endian = false) {
  std::string h(544, '\0');
  auto put = [&](std::size_t off, auto v) {
    unsigned char b[sizeof v];
    std::memcpy(b, &v, sizeof v);
    if (big_endian) std::reverse(b, b + sizeof v);
    std::memcpy(h.data() + off, b, sizeof v);
  };
  put(0, std::int32_t{540});
  std::memcpy(h.data() + 4, "n+2\0\r\n\032\n", 8);
  put(12, std::int16_t{2}); // DT_UINT8
  put(14, std::int16_t{8});
  const std::int64_t dims[8] = {3, nx, ny, nz, 1, 1, 1, 1};
  for (int k = 0; k < 8; ++k) put(16 + 8 * static_cast<std::size_t>(k), dims[k]);
  for (int k = 0; k < 8; ++k) put(104 + 8 * static_cast<std::size_t>(k), 1.0);
  put(168, std::int64_t{544});
  return h + voxel_ramp(nx * ny * nz);
}

/// NIfTI-1 (little-endian), vox_offset 352 after the 4-byte extension flag.
inline std::string nifti1_bytes(std::int16_t nx, std::int16_t ny, std::int16_t nz) {
  std::string h(352, '\0');
  h = patched<std::int32_t>(h, 0, 348);
  const std::int16_t dims[8] = {3, nx, ny, nz, 1, 1, 1, 1};
  for (int k = 0; k < 8; ++k)
    h = patched<std::int16_t>(h, 40 + 2 * static_cast<std::size_t>(k), dims[k]);
  h = patched<std::int16_t>(h, 70, 2); // DT_UINT8
  h = patched<std::int16_t>(h, 72, 8);
  for (int k = 0; k < 8; ++k) h = patched<float>(h, 76 + 4 * static_cast<std::size_t>(k), 1.0f);
  h = patched<float>(h, 108, 352.0f);
  std::memcpy(h.data() + 344, "n+1\0", 4);
  return h + voxel_ramp(std::int64_t{nx} * ny * nz);
}

/// The gzip file of bytes (what a .nii.gz holds).
inline std::string gzip_bytes(const std::string& bytes) {
  z_stream zs{};
  deflateInit2(&zs, 6, Z_DEFLATED, 31, 8, Z_DEFAULT_STRATEGY);
  std::vector<unsigned char> buf(deflateBound(&zs, bytes.size()) + 64);
  zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  zs.avail_in = static_cast<uInt>(bytes.size());
  zs.next_out = buf.data();
  zs.avail_out = static_cast<uInt>(buf.size());
  deflate(&zs, Z_FINISH);
  std::string out(buf.begin(), buf.begin() + static_cast<std::ptrdiff_t>(zs.total_out));
  deflateEnd(&zs);
  return out;
}

} // namespace zdg::test
