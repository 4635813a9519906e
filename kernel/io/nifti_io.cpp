#include <zdg/kernel/io/nifti_io.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/io/input_file.hpp>
#include <zdg/kernel/io/output_files.hpp>

#include <nifti2_io.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <mutex>
#include <unistd.h>

namespace zdg {

namespace {

// The library keeps its options in globals and reports problems on stderr.
std::mutex& nifti_mutex() {
  static std::mutex m;
  return m;
}

// While alive, whatever is written on file descriptor 2 goes to a temporary file; text()
// returns it. The library's diagnostics end up in zdg's one-line error instead of on the
// terminal. (Only used under nifti_mutex, while no other zdg thread writes on stderr.)
class StderrCapture {
public:
  StderrCapture() {
    std::fflush(stderr);
    tmp_ = std::tmpfile();
    if (tmp_ == nullptr) return;
    saved_ = ::dup(2);
    if (saved_ < 0 || ::dup2(::fileno(tmp_), 2) < 0) {
      if (saved_ >= 0) ::close(saved_);
      saved_ = -1;
    }
  }
  ~StderrCapture() {
    restore();
    if (tmp_ != nullptr) std::fclose(tmp_);
  }
  StderrCapture(const StderrCapture&) = delete;
  StderrCapture& operator=(const StderrCapture&) = delete;

  /// The captured text, as one line (at most 200 characters), "" when nothing was written.
  std::string text() {
    restore();
    if (tmp_ == nullptr) return "";
    std::rewind(tmp_);
    std::string s;
    for (int c; s.size() < 400 && (c = std::fgetc(tmp_)) != EOF;)
      s.push_back(c == '\n' || c == '\r' || c == '\t' ? ' ' : static_cast<char>(c));
    while (!s.empty() && s.back() == ' ') s.pop_back();
    while (!s.empty() && s.front() == ' ') s.erase(s.begin());
    if (s.size() > 200) s = s.substr(0, 197) + "...";
    return s;
  }

private:
  void restore() {
    if (saved_ < 0) return;
    std::fflush(stderr);
    ::dup2(saved_, 2);
    ::close(saved_);
    saved_ = -1;
  }
  std::FILE* tmp_ = nullptr;
  int saved_ = -1;
};

struct NimFree {
  void operator()(nifti_image* nim) const {
    if (nim != nullptr) nifti_image_free(nim);
  }
};
using NimPtr = std::unique_ptr<nifti_image, NimFree>;

struct TypeMap {
  DType dtype;
  int code;
};
constexpr TypeMap kTypes[] = {
    {DType::U8, DT_UINT8},    {DType::I8, DT_INT8},    {DType::U16, DT_UINT16},
    {DType::I16, DT_INT16},   {DType::U32, DT_UINT32}, {DType::I32, DT_INT32},
    {DType::U64, DT_UINT64},  {DType::I64, DT_INT64},  {DType::F32, DT_FLOAT32},
    {DType::F64, DT_FLOAT64}, {DType::Bool, DT_UINT8},
};

std::string with_library_message(const std::string& what, const std::string& library) {
  return library.empty() ? what : what + " (nifti library: " + library + ")";
}

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

std::string lower_case(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

} // namespace

namespace {

// The header fields zdg and the library's conversion use, read by zdg from the raw bytes and
// checked before the library sees them (the library trusts dim[0] as a loop bound, and
// vox_offset, pixdim, the offsets and the scaling as they are).
struct CheckedHeader {
  int version = 1;      // 1 or 2
  bool swapped = false; // stored in the other byte order than the machine's
  std::int64_t dim[8] = {};
  DType dtype = DType::U8;
  int datatype = 0;             // its NIfTI code
  std::uint64_t data_bytes = 0; // nx * ny * nz * bytes per voxel
  std::uint64_t vox_offset = 0;
};

template <class T>
T field(const unsigned char* h, std::size_t offset, bool swapped) {
  unsigned char b[sizeof(T)];
  std::memcpy(b, h + offset, sizeof(T));
  if (swapped) std::reverse(b, b + sizeof(T));
  T v;
  std::memcpy(&v, b, sizeof(T));
  return v;
}

std::string shown_double(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", x);
  return buf;
}

constexpr std::uint64_t kMaxInflateRatio = 1032; // deflate's largest expansion

// Checks the first `n` bytes of the file (the header, up to 540 bytes) and returns what it
// says; IoError naming the file for anything the library or the reader would trust wrongly.
CheckedHeader check_header(const std::string& path, const unsigned char* h, std::size_t n,
                           std::uint64_t file_size, bool gz) {
  auto fail = [&](const std::string& what) -> void { throw IoError(path + ": " + what); };
  if (n < 348) {
    fail("not a NIfTI-1/2 file (" + std::to_string(n) +
         " bytes, shorter than a NIfTI-1 header's 348)");
  }
  CheckedHeader c;
  const auto size_native = field<std::int32_t>(h, 0, false);
  const auto size_swapped = field<std::int32_t>(h, 0, true);
  if (size_native == 348 || size_swapped == 348) {
    c.version = 1;
    c.swapped = size_native != 348;
  } else if (size_native == 540 || size_swapped == 540) {
    c.version = 2;
    c.swapped = size_native != 540;
  } else {
    fail("not a NIfTI-1/2 file (sizeof_hdr " + std::to_string(size_native) + ", 348 or 540)");
  }
  const bool v1 = c.version == 1;
  if (v1) {
    if (std::memcmp(h + 344, "ni1\0", 4) == 0)
      fail("the header of a .hdr/.img pair (magic ni1); zdg reads single-file .nii volumes");
    if (std::memcmp(h + 344, "n+1\0", 4) != 0)
      fail("not a single-file NIfTI-1 volume (magic is not n+1: ANALYZE 7.5 or damaged)");
  } else {
    if (n < 540) fail("truncated NIfTI-2 header (" + std::to_string(n) + " of 540 bytes)");
    if (std::memcmp(h + 4, "ni2\0", 4) == 0)
      fail("the header of a .hdr/.img pair (magic ni2); zdg reads single-file .nii volumes");
    // The check bytes \r\n\032\n follow n+2 (zeros in the files libnifti 3.0 writes).
    if (std::memcmp(h + 4, "n+2\0", 4) != 0 ||
        (std::memcmp(h + 8, "\r\n\032\n", 4) != 0 && std::memcmp(h + 8, "\0\0\0\0", 4) != 0))
      fail("not a single-file NIfTI-2 volume (magic is not n+2 with its \\r\\n\\032\\n check "
           "bytes: damaged, or transferred as text)");
  }
  const bool sw = c.swapped;
  for (int k = 0; k < 8; ++k) {
    c.dim[k] = v1 ? field<std::int16_t>(h, 40 + 2 * static_cast<std::size_t>(k), sw)
                  : field<std::int64_t>(h, 16 + 8 * static_cast<std::size_t>(k), sw);
  }
  const std::int64_t ndim = c.dim[0];
  if (ndim < 1 || ndim > 7) fail("NIfTI dim[0] = " + std::to_string(ndim) + " (1..7)");
  for (std::int64_t k = 1; k <= ndim; ++k) {
    if (c.dim[k] < 1)
      fail("NIfTI dim[" + std::to_string(k) + "] = " + std::to_string(c.dim[k]) +
           " is not positive");
  }
  if (ndim < 2) fail("a 1-D NIfTI array is not an image (2D or 3D needed)");
  for (std::int64_t k = 4; k <= ndim; ++k) {
    if (c.dim[k] != 1)
      fail("NIfTI dim[" + std::to_string(k) + "] = " + std::to_string(c.dim[k]) +
           " (a 4-D or larger dataset; zdg reads one 2D or 3D volume)");
  }
  const int d = ndim == 2 ? 2 : 3;
  const int datatype = v1 ? field<std::int16_t>(h, 70, sw) : field<std::int16_t>(h, 12, sw);
  const int bitpix = v1 ? field<std::int16_t>(h, 72, sw) : field<std::int16_t>(h, 14, sw);
  bool known = false;
  for (const auto& t : kTypes) {
    if (t.code == datatype && t.dtype != DType::Bool) {
      c.dtype = t.dtype;
      c.datatype = datatype;
      known = true;
      break;
    }
  }
  if (!known) {
    const char* name = nifti_datatype_string(datatype);
    fail("NIfTI datatype " + std::to_string(datatype) + " (" + (name != nullptr ? name : "?") +
         ") is not supported (uint8/16/32/64, int8/16/32/64, float32, float64)");
  }
  if (bitpix != 8 * static_cast<int>(dtype_size(c.dtype)))
    fail("NIfTI bitpix " + std::to_string(bitpix) + " disagrees with the datatype " +
         dtype_name(c.dtype) + " (" + std::to_string(8 * dtype_size(c.dtype)) + " bits)");
  std::string dims = std::to_string(c.dim[1]);
  for (int k = 2; k <= d; ++k) dims.append("x").append(std::to_string(c.dim[k]));
  std::uint64_t bytes = dtype_size(c.dtype);
  for (int k = 1; k <= d; ++k) {
    if (__builtin_mul_overflow(bytes, static_cast<std::uint64_t>(c.dim[k]), &bytes) ||
        bytes > (std::uint64_t{1} << 62))
      fail("NIfTI dims " + dims + " need more than 2^62 bytes");
  }
  c.data_bytes = bytes;
  // vox_offset: NIfTI-1 stores it as a float; it must be an integer, at least the header and
  // its 4-byte extension flag (352; 544 for NIfTI-2), and the data must fit after it.
  const std::uint64_t least = v1 ? 352 : 544;
  if (v1) {
    const double off = field<float>(h, 108, sw);
    if (!std::isfinite(off) || off != std::floor(off) || off < static_cast<double>(least) ||
        off >= 2147483648.0)
      fail("NIfTI vox_offset " + shown_double(off) + " is not an integer in [352, 2^31)");
    c.vox_offset = static_cast<std::uint64_t>(off);
  } else {
    const auto off = field<std::int64_t>(h, 168, sw);
    if (off < static_cast<std::int64_t>(least) || off > (std::int64_t{1} << 62))
      fail("NIfTI vox_offset " + std::to_string(off) + " is not in [544, 2^62]");
    c.vox_offset = static_cast<std::uint64_t>(off);
  }
  if (!gz) {
    if (c.vox_offset > file_size || file_size - c.vox_offset < bytes) {
      fail("NIfTI header says " + dims + " " + dtype_name(c.dtype) + " (" + std::to_string(bytes) +
           " bytes from offset " + std::to_string(c.vox_offset) + ") but the file has " +
           std::to_string(file_size) + " bytes");
    }
  } else {
    const std::uint64_t most = kMaxInflateRatio * file_size + 1024;
    if (c.vox_offset + bytes > most) {
      fail("NIfTI header says " + std::to_string(bytes) + " bytes of data from offset " +
           std::to_string(c.vox_offset) + " but " + std::to_string(file_size) +
           " compressed bytes can hold at most " + std::to_string(most));
    }
  }
  // The values kept (spacing, scaling, origin) must be numbers.
  for (int k = 1; k <= d; ++k) {
    const double p = v1 ? field<float>(h, 76 + 4 * static_cast<std::size_t>(k), sw)
                        : field<double>(h, 104 + 8 * static_cast<std::size_t>(k), sw);
    if (!std::isfinite(p))
      fail("NIfTI pixdim[" + std::to_string(k) + "] = " + shown_double(p) +
           " is not a finite spacing");
  }
  const double slope = v1 ? field<float>(h, 112, sw) : field<double>(h, 176, sw);
  const double inter = v1 ? field<float>(h, 116, sw) : field<double>(h, 184, sw);
  if (std::isfinite(slope) && slope != 0.0 && !std::isfinite(inter))
    fail("NIfTI scl_inter " + shown_double(inter) + " is not finite (scl_slope " +
         shown_double(slope) + ")");
  const int qform = v1 ? field<std::int16_t>(h, 252, sw) : field<std::int32_t>(h, 344, sw);
  const int sform = v1 ? field<std::int16_t>(h, 254, sw) : field<std::int32_t>(h, 348, sw);
  for (int k = 0; k < d; ++k) {
    const auto q = static_cast<std::size_t>(k);
    double o = 0.0;
    const char* what = "";
    if (qform > 0) {
      o = v1 ? field<float>(h, 268 + 4 * q, sw) : field<double>(h, 376 + 8 * q, sw);
      what = "qoffset";
    } else if (sform > 0) {
      o = v1 ? field<float>(h, 280 + 16 * q + 12, sw) : field<double>(h, 400 + 32 * q + 24, sw);
      what = "srow translation";
    }
    if (!std::isfinite(o))
      fail(std::string("NIfTI ") + what + " " + shown_double(o) + " is not a finite origin");
  }
  return c;
}

} // namespace

ScalarVolume read_nifti(const std::string& path) {
  const std::string lname = lower_case(path);
  const bool gz = ends_with(lname, ".nii.gz");
  if (!gz && !ends_with(lname, ".nii"))
    throw IoError(path + ": a NIfTI file name ends in .nii or .nii.gz");
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw IoError(path + ": no such file");
  const auto file_size = static_cast<std::uint64_t>(std::filesystem::file_size(path, ec));
  if (ec) throw IoError(path + ": cannot read the file size");
  if (file_size == 0) throw IoError(path + ": empty file (not a NIfTI volume)");

  std::lock_guard<std::mutex> lock(nifti_mutex());
  nifti_set_debug_level(0);
  znzFile f = znzopen(path.c_str(), "rb", gz ? 1 : 0);
  if (znz_isnull(f)) throw IoError(path + ": cannot open the file");
  struct Close {
    znzFile& f;
    ~Close() {
      if (!znz_isnull(f)) znzclose(f);
    }
  } closer{f};
  // The header, read by zdg and checked before the library converts it.
  static_assert(sizeof(nifti_1_header) == 348 && sizeof(nifti_2_header) == 540);
  unsigned char raw[540] = {};
  std::size_t n = 0;
  while (n < sizeof raw) {
    const std::size_t got = znzread(raw + n, 1, sizeof raw - n, f);
    if (got == 0 || got > sizeof raw - n) break; // (size_t)-1: gzip data that does not inflate
    n += got;
  }
  const CheckedHeader c = check_header(path, raw, n, file_size, gz);
  const int d = c.dim[0] == 2 ? 2 : 3;
  NimPtr nim;
  {
    StderrCapture cap;
    if (c.version == 1) {
      nifti_1_header h1;
      std::memcpy(&h1, raw, sizeof h1);
      nim.reset(nifti_convert_n1hdr2nim(h1, nullptr));
    } else {
      nifti_2_header h2;
      std::memcpy(&h2, raw, sizeof h2);
      nim.reset(nifti_convert_n2hdr2nim(h2, nullptr));
    }
    if (!nim)
      throw IoError(path + ": " + with_library_message("the NIfTI header is refused", cap.text()));
  }
  // The library read what zdg checked (dims, type, byte order), or the file is refused.
  // The library's byte orders are LSB_FIRST = 1 and MSB_FIRST = 2 (its REVERSE_ORDER is 3 - x,
  // a macro it keeps private).
  const int order = c.swapped ? 3 - nifti_short_order() : nifti_short_order();
  bool agree = nim->dim[0] == c.dim[0] && nim->datatype == c.datatype &&
               nim->nbyper == static_cast<int>(dtype_size(c.dtype)) && nim->byteorder == order;
  for (int k = 1; k <= d; ++k) agree = agree && nim->dim[k] == c.dim[k];
  if (!agree)
    throw IoError(path + ": the NIfTI library reads this header differently from zdg's checks");
  const std::uint64_t bytes = c.data_bytes;
  std::vector<std::int64_t> shape;
  for (int k = d; k >= 1; --k) shape.push_back(c.dim[k]);
  // The payload is read here through libnifti's znz layer rather than nifti_image_load:
  // nifti_image_load replaces every NaN and infinity of a float volume by 0, and a value
  // that reads back different from what was written is a wrong answer. A .nii.gz takes memory
  // as its bytes inflate (ArrivingBytes), not for what its header claims.
  ScalarVolume v;
  v.array.dtype = c.dtype;
  v.array.shape = shape;
  // znzseek returns fseek's 0 or gzseek's new offset on success, -1 on failure.
  const bool at = znzseek(f, static_cast<znz_off_t>(c.vox_offset), SEEK_SET) >= 0;
  std::uint64_t got = 0;
  bool corrupt = false;
  // znzread reads at most 2^31 - 1 bytes a call through gzread: read in chunks. It returns
  // (size_t)-1 when gzread fails (corrupt deflate data, a bad CRC).
  auto read_into = [&](unsigned char* p, std::size_t want) -> std::size_t {
    const std::size_t r = znzread(p, 1, want, f);
    if (r > want) corrupt = true;
    return r > want ? 0 : r;
  };
  if (!gz) {
    v.array.bytes.resize(static_cast<std::size_t>(bytes));
    while (at && got < bytes) {
      const auto want = static_cast<std::size_t>(std::min<std::uint64_t>(bytes - got, 1u << 30));
      const std::size_t r = read_into(v.array.bytes.data() + got, want);
      if (r == 0) break;
      got += r;
    }
  } else {
    ArrivingBytes data(bytes);
    while (at) {
      const auto room = data.room();
      if (room.empty()) break;
      // At most 1 MiB a call: a failing gzread returns -1 and loses the count of its call, so
      // the error's count of good bytes falls short by at most about 1 MiB.
      const std::size_t r = read_into(room.data(), std::min<std::size_t>(room.size(), 1u << 20));
      if (r == 0) break;
      data.arrived(r);
    }
    got = data.size();
    // A .nii.gz is checked to its end: zlib verifies the stream's CRC only when it reads the
    // trailer, so stopping at the last voxel would accept a corrupted payload.
    if (at && got == bytes) {
      char rest[4096];
      while (read_into(reinterpret_cast<unsigned char*>(rest), sizeof rest) != 0) {
      }
    }
    if (at && got == bytes && !corrupt) v.array.bytes = data.take();
  }
  if (!at || got != bytes || corrupt) {
    throw IoError(path + ": truncated or corrupt NIfTI data (" + std::to_string(got) + " of " +
                  std::to_string(bytes) + " bytes" +
                  (corrupt ? ", gzip data that does not inflate or a bad CRC" : "") + ")");
  }
  if (c.swapped && dtype_size(c.dtype) > 1) {
    nifti_swap_Nbytes(static_cast<std::int64_t>(bytes / dtype_size(c.dtype)),
                      static_cast<int>(dtype_size(c.dtype)), v.array.bytes.data());
  }
  v.lower.assign(static_cast<std::size_t>(d), 0);
  const double qoff[3] = {nim->qoffset_x, nim->qoffset_y, nim->qoffset_z};
  for (int k = d; k >= 1; --k) {
    v.spacing.push_back(nim->pixdim[k]);
    double o = 0.0;
    if (nim->qform_code > 0) {
      o = qoff[k - 1];
    } else if (nim->sform_code > 0) {
      o = nim->sto_xyz.m[k - 1][3];
    }
    v.origin.push_back(o);
  }
  if (std::isfinite(nim->scl_slope) && nim->scl_slope != 0.0) {
    v.slope = nim->scl_slope;
    v.inter = nim->scl_inter;
  }
  return v;
}

void write_nifti(const std::string& path, const ScalarVolume& volume) {
  const std::string lname = lower_case(path);
  const bool gz = ends_with(lname, ".nii.gz");
  if (!gz && !ends_with(lname, ".nii"))
    throw IoError(path + ": a NIfTI file name ends in .nii or .nii.gz");
  write_nifti(path, volume, gz);
}

void write_nifti(const std::string& path, const ScalarVolume& volume, bool gz) {
  volume.validate();
  const int d = volume.dim();
  int code = DT_UINT8;
  for (const auto& t : kTypes) {
    if (t.dtype == volume.array.dtype) code = t.code;
  }
  std::int64_t dims[8] = {d, 1, 1, 1, 1, 1, 1, 1};
  bool fits_nifti1 = true;
  for (int k = 1; k <= d; ++k) {
    dims[k] = volume.array.shape[static_cast<std::size_t>(d - k)];
    fits_nifti1 = fits_nifti1 && dims[k] <= 32767;
  }
  for (int k = 0; k < d; ++k) {
    const double s = volume.spacing[static_cast<std::size_t>(k)];
    if (!std::isfinite(s) || s <= 0.0)
      throw InvalidArgument(path + ": spacing " + std::to_string(s) +
                            " cannot be written (positive and finite needed)");
  }
  OutputSet out(Existing::replace);
  const auto staging = out.add(path);
  {
    std::lock_guard<std::mutex> lock(nifti_mutex());
    nifti_set_debug_level(0);
    StderrCapture cap;
    NimPtr nim(nifti_make_new_nim(dims, code, 0));
    if (!nim)
      throw IoError(path + ": " + with_library_message("cannot make a NIfTI header", cap.text()));
    nim->nifti_type = fits_nifti1 ? NIFTI_FTYPE_NIFTI1_1 : NIFTI_FTYPE_NIFTI2_1;
    double* spacing[3] = {&nim->dx, &nim->dy, &nim->dz};
    double* qoffset[3] = {&nim->qoffset_x, &nim->qoffset_y, &nim->qoffset_z};
    for (int k = 1; k <= d; ++k) {
      const auto a = static_cast<std::size_t>(d - k);
      *spacing[k - 1] = volume.spacing[a];
      nim->pixdim[k] = volume.spacing[a];
      *qoffset[k - 1] = volume.origin[a];
    }
    nim->qform_code = NIFTI_XFORM_SCANNER_ANAT;
    nim->sform_code = 0;
    nim->quatern_b = nim->quatern_c = nim->quatern_d = 0.0;
    nim->qfac = 1.0;
    nim->scl_slope = volume.slope;
    nim->scl_inter = volume.inter;
    std::free(nim->fname);
    std::free(nim->iname);
    nim->fname = nifti_strdup(gz ? "zdg.nii.gz" : "zdg.nii");
    nim->iname = nifti_strdup(gz ? "zdg.nii.gz" : "zdg.nii");
    // The library writes through the open staging file; it never opens a file by name here.
    znzFile fp = znzopen(staging.c_str(), "wb", gz ? 1 : 0);
    if (znz_isnull(fp)) throw IoError(path + ": cannot write (" + std::strerror(errno) + ")");
    nim->data = const_cast<unsigned char*>(volume.array.bytes.data());
    fp = nifti_image_write_hdr_img2(nim.get(), 3, "wb", fp, nullptr);
    nim->data = nullptr; // the bytes belong to `volume`
    const bool opened = !znz_isnull(fp);
    const int closed = opened ? znzclose(fp) : -1;
    const std::string library = cap.text();
    if (!opened || closed != 0 || !library.empty())
      throw IoError(path + ": " + with_library_message("NIfTI write failed", library));
  }
  if (!gz) {
    std::error_code ec;
    const auto size = std::filesystem::file_size(staging, ec);
    if (ec || size < volume.array.bytes.size() + 348)
      throw IoError(path + ": NIfTI write failed (disk full?)");
  }
  out.commit();
}

} // namespace zdg
