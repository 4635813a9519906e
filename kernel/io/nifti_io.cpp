#include <zdg/kernel/io/nifti_io.hpp>

#include <zdg/arith/error.hpp>
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
  NimPtr nim;
  {
    StderrCapture cap;
    nim.reset(nifti_image_read(path.c_str(), 0));
    if (!nim) throw IoError(path + ": " + with_library_message("not a NIfTI-1/2 file", cap.text()));
  }
  if (nim->nifti_type != NIFTI_FTYPE_NIFTI1_1 && nim->nifti_type != NIFTI_FTYPE_NIFTI2_1)
    throw IoError(path +
                  ": not a single-file NIfTI-1/2 volume (ANALYZE, ASCII or .hdr/.img "
                  "header, type " +
                  std::to_string(nim->nifti_type) + ")");
  const std::int64_t ndim = nim->dim[0];
  if (ndim < 1 || ndim > 7)
    throw IoError(path + ": NIfTI dim[0] = " + std::to_string(ndim) + " (1..7)");
  for (std::int64_t k = 1; k <= ndim; ++k) {
    if (nim->dim[k] < 1)
      throw IoError(path + ": NIfTI dim[" + std::to_string(k) +
                    "] = " + std::to_string(nim->dim[k]) + " is not positive");
  }
  if (ndim < 2) throw IoError(path + ": a 1-D NIfTI array is not an image (2D or 3D needed)");
  for (std::int64_t k = 4; k <= ndim; ++k) {
    if (nim->dim[k] != 1)
      throw IoError(path + ": NIfTI dim[" + std::to_string(k) +
                    "] = " + std::to_string(nim->dim[k]) +
                    " (a 4-D or larger dataset; zdg reads one 2D or 3D volume)");
  }
  const int d = ndim == 2 ? 2 : 3;
  DType dtype = DType::U8;
  bool known = false;
  for (const auto& t : kTypes) {
    if (t.code == nim->datatype && t.dtype != DType::Bool) {
      dtype = t.dtype;
      known = true;
      break;
    }
  }
  if (!known) {
    const char* name = nifti_datatype_string(nim->datatype);
    throw IoError(path + ": NIfTI datatype " + std::to_string(nim->datatype) + " (" +
                  (name != nullptr ? name : "?") +
                  ") is not supported (uint8/16/32/64, int8/16/32/64, float32, float64)");
  }
  if (nim->nbyper != static_cast<int>(dtype_size(dtype)))
    throw IoError(path + ": NIfTI bytes per voxel " + std::to_string(nim->nbyper) +
                  " disagree with the datatype");
  std::vector<std::int64_t> shape;
  for (int k = d; k >= 1; --k) shape.push_back(nim->dim[k]);
  std::uint64_t bytes = dtype_size(dtype);
  for (auto s : shape) {
    if (__builtin_mul_overflow(bytes, static_cast<std::uint64_t>(s), &bytes) ||
        bytes > (std::uint64_t{1} << 62)) {
      throw IoError(path + ": NIfTI dims " + std::to_string(nim->dim[1]) + "x" +
                    std::to_string(nim->dim[2]) + "x" + std::to_string(nim->dim[3]) +
                    " need more than 2^62 bytes");
    }
  }
  if (nim->iname_offset < 0)
    throw IoError(path + ": NIfTI vox_offset " + std::to_string(nim->iname_offset));
  if (!gz) {
    const auto offset = static_cast<std::uint64_t>(nim->iname_offset);
    if (offset > file_size || file_size - offset < bytes) {
      throw IoError(path + ": NIfTI header says " + std::to_string(nim->dim[1]) + "x" +
                    std::to_string(nim->dim[2]) + "x" + std::to_string(d == 3 ? nim->dim[3] : 1) +
                    " " + dtype_name(dtype) + " (" + std::to_string(bytes) + " bytes from offset " +
                    std::to_string(offset) + ") but the file has " + std::to_string(file_size) +
                    " bytes");
    }
  } else if (bytes > 1032 * file_size + 1024) {
    throw IoError(path + ": NIfTI header says " + std::to_string(bytes) + " bytes of data but " +
                  std::to_string(file_size) + " compressed bytes can hold at most " +
                  std::to_string(1032 * file_size + 1024));
  }
  // The payload is read here through libnifti's znz layer rather than nifti_image_load:
  // nifti_image_load replaces every NaN and infinity of a float volume by 0, and a value
  // that reads back different from what was written is a wrong answer. The byte order is
  // the header's (libnifti detected it), swapped to the machine's.
  ScalarVolume v;
  v.array.dtype = dtype;
  v.array.shape = shape;
  v.array.bytes.resize(static_cast<std::size_t>(bytes));
  {
    znzFile f = znzopen(path.c_str(), "rb", gz ? 1 : 0);
    if (znz_isnull(f)) throw IoError(path + ": cannot open the file");
    // znzseek returns fseek's 0 or gzseek's new offset on success, -1 on failure.
    const bool at = znzseek(f, static_cast<znz_off_t>(nim->iname_offset), SEEK_SET) >= 0;
    std::size_t got = 0;
    if (at) {
      // znzread reads at most 2^31 - 1 bytes a call through gzread: read in chunks.
      while (got < v.array.bytes.size()) {
        const std::size_t want = std::min<std::size_t>(v.array.bytes.size() - got, 1u << 30);
        // znzread returns (size_t)-1 when gzread fails (corrupt deflate data, a bad CRC).
        const std::size_t n = znzread(v.array.bytes.data() + got, 1, want, f);
        if (n == 0 || n > want) break;
        got += n;
      }
    }
    // A .nii.gz is checked to its end: zlib verifies the stream's CRC only when it reads the
    // trailer, so stopping at the last voxel would accept a corrupted payload.
    bool crc_ok = true;
    if (gz && at && got == v.array.bytes.size()) {
      char rest[4096];
      for (;;) {
        const std::size_t n = znzread(rest, 1, sizeof rest, f);
        if (n > sizeof rest) crc_ok = false; // (size_t)-1: a bad CRC or corrupt data
        if (n == 0 || n > sizeof rest) break;
      }
    }
    znzclose(f);
    if (!at || got != v.array.bytes.size() || !crc_ok) {
      throw IoError(path + ": truncated or corrupt NIfTI data (" + std::to_string(got) + " of " +
                    std::to_string(bytes) + " bytes" + (crc_ok ? "" : ", bad gzip CRC") + ")");
    }
  }
  if (nim->byteorder != nifti_short_order() && dtype_size(dtype) > 1) {
    nifti_swap_Nbytes(static_cast<std::int64_t>(bytes / dtype_size(dtype)),
                      static_cast<int>(dtype_size(dtype)), v.array.bytes.data());
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
    v.origin.push_back(std::isfinite(o) ? o : 0.0);
  }
  if (std::isfinite(nim->scl_slope) && nim->scl_slope != 0.0) {
    v.slope = nim->scl_slope;
    v.inter = std::isfinite(nim->scl_inter) ? nim->scl_inter : 0.0;
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
