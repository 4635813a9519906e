#include <zdg/kernel/io/volume_io.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/io/nifti_io.hpp>
#include <zdg/kernel/io/pgm_io.hpp>
#include <zdg/kernel/io/raw_io.hpp>
#include <zdg/kernel/io/vdb_io.hpp>
#include <zdg/kernel/io/vol_io.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace zdg {

namespace {

std::string lower_case(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// The physical values as integers in [0, max]; InvalidArgument naming the first that is not.
template <class T>
std::vector<T> integer_values(const ScalarVolume& v, std::uint64_t max, const std::string& path,
                              const char* format) {
  std::vector<T> out(static_cast<std::size_t>(v.count()));
  if (!v.scaled() && (v.array.dtype == DType::U8 || v.array.dtype == DType::Bool)) {
    std::copy(v.array.bytes.begin(), v.array.bytes.end(), out.begin()); // always fits
    return out;
  }
  const bool exact_ints = !v.scaled() && !dtype_is_float(v.array.dtype);
  for (std::int64_t i = 0; i < v.count(); ++i) {
    bool ok = false;
    std::uint64_t u = 0;
    std::string shown;
    if (exact_ints && v.array.dtype == DType::U64) {
      std::memcpy(&u, v.array.bytes.data() + 8 * i, 8);
      ok = u <= max;
      shown = std::to_string(u);
    } else if (exact_ints) {
      const std::int64_t s = v.array.get(i);
      ok = s >= 0 && static_cast<std::uint64_t>(s) <= max;
      u = static_cast<std::uint64_t>(s);
      shown = std::to_string(s);
    } else {
      const double x = v.value(i);
      ok = std::isfinite(x) && x >= 0 && x <= static_cast<double>(max) && x == std::floor(x);
      u = ok ? static_cast<std::uint64_t>(x) : 0;
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.17g", x);
      shown = buf;
    }
    if (!ok) {
      throw InvalidArgument(path + ": value " + shown + " (voxel " + std::to_string(i) +
                            ") does not fit a " + format + " (integers 0.." + std::to_string(max) +
                            "); write .npy or .nii");
    }
    out[static_cast<std::size_t>(i)] = static_cast<T>(u);
  }
  return out;
}

// The physical values of a float or scaled volume as int64, each checked to be an integer.
Image<std::int64_t> read_integer_image_of(const std::string& path, const ScalarVolume& v) {
  Image<std::int64_t> img(Domain(v.array.shape, v.lower), std::int64_t{0});
  for (std::int64_t i = 0; i < img.size(); ++i) {
    const double x = v.value(i);
    // 2^63 is exactly representable; every double below it in magnitude converts exactly.
    if (!(std::nearbyint(x) == x && x >= -9223372036854775808.0 && x < 9223372036854775808.0)) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.17g", x);
      throw IoError(path + ": value " + buf + " at voxel " + std::to_string(i) +
                    " (C order) is not an integer (" + describe_volume(v) +
                    "; integer values are needed)");
    }
    img[i] = static_cast<std::int64_t>(x);
  }
  return img;
}

} // namespace

std::string volume_format_name(VolumeFormat f) {
  switch (f) {
  case VolumeFormat::vol:
    return "vol";
  case VolumeFormat::nifti:
    return "nifti";
  case VolumeFormat::nifti_gz:
    return "nifti.gz";
  case VolumeFormat::npy:
    return "npy";
  case VolumeFormat::pgm:
    return "pgm";
  case VolumeFormat::raw:
    return "raw";
  case VolumeFormat::vdb:
    return "vdb";
  }
  return "?";
}

VolumeFormat volume_format_of(const std::string& path) {
  const std::string p = lower_case(std::filesystem::path(path).filename().string());
  if (ends_with(p, ".vol")) return VolumeFormat::vol;
  if (ends_with(p, ".nii")) return VolumeFormat::nifti;
  if (ends_with(p, ".nii.gz")) return VolumeFormat::nifti_gz;
  if (ends_with(p, ".npy")) return VolumeFormat::npy;
  if (ends_with(p, ".pgm")) return VolumeFormat::pgm;
  if (ends_with(p, ".raw")) return VolumeFormat::raw;
  if (ends_with(p, ".vdb")) return VolumeFormat::vdb;
  throw IoError(path + ": unknown volume format (.vol, .nii, .nii.gz, .npy, .pgm, .raw, .vdb)");
}

ScalarVolume read_volume(const std::string& path, const RawLayout& raw) {
  if (raw.given()) {
    if (raw.shape.empty() || !raw.dtype)
      throw InvalidArgument("a raw file needs both --raw-shape and --raw-dtype");
    return read_raw(path, raw.shape, *raw.dtype);
  }
  const VolumeFormat f = volume_format_of(path);
  if (f == VolumeFormat::raw)
    throw InvalidArgument(path + ": a raw file needs --raw-shape Z,Y,X and --raw-dtype");
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw IoError(path + ": no such file");
  switch (f) {
  case VolumeFormat::vol:
    return make_scalar_volume(read_vol(path));
  case VolumeFormat::nifti:
  case VolumeFormat::nifti_gz:
    return read_nifti(path);
  case VolumeFormat::npy: {
    NpyArray a = read_npy(path);
    if (a.shape.size() != 2 && a.shape.size() != 3) {
      throw IoError(path + ": a " + std::to_string(a.shape.size()) +
                    "-D array is not a volume (2D or 3D needed)");
    }
    for (auto s : a.shape) {
      if (s < 1) throw IoError(path + ": empty array (an extent is 0)");
    }
    return make_scalar_volume(std::move(a));
  }
  case VolumeFormat::pgm: {
    const auto img = read_pgm(path);
    NpyArray a;
    a.shape = img.domain().extents();
    bool wide = false;
    for (auto v : img.values()) wide = wide || v > 255;
    a.dtype = wide ? DType::U16 : DType::U8;
    a.bytes.resize(img.values().size() * (wide ? 2 : 1));
    for (std::size_t i = 0; i < img.values().size(); ++i) {
      if (wide) {
        std::memcpy(a.bytes.data() + 2 * i, &img.values()[i], 2);
      } else {
        a.bytes[i] = static_cast<unsigned char>(img.values()[i]);
      }
    }
    return make_scalar_volume(std::move(a));
  }
  case VolumeFormat::vdb:
    return read_vdb(path);
  case VolumeFormat::raw:
    break;
  }
  throw IoError(path + ": unknown volume format");
}

Image<std::int64_t> read_integer_image(const std::string& path, const RawLayout& raw) {
  if (!raw.given() && volume_format_of(path) == VolumeFormat::npy) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw IoError(path + ": no such file");
    const NpyArray a = read_npy(path);
    if (!dtype_is_float(a.dtype)) return npy_to_int64(a, {}, path);
    return read_integer_image_of(path, make_scalar_volume(a));
  }
  const ScalarVolume v = read_volume(path, raw);
  if (!v.scaled() && !dtype_is_float(v.array.dtype)) return npy_to_int64(v.array, v.lower, path);
  return read_integer_image_of(path, v);
}

NpyArray physical_array(const ScalarVolume& volume) {
  if (!volume.scaled()) return volume.array;
  NpyArray a;
  a.dtype = DType::F64;
  a.shape = volume.array.shape;
  a.bytes.resize(static_cast<std::size_t>(volume.count()) * 8);
  for (std::int64_t i = 0; i < volume.count(); ++i) {
    const double x = volume.value(i);
    std::memcpy(a.bytes.data() + 8 * i, &x, 8);
  }
  return a;
}

void write_volume(const std::string& path, const ScalarVolume& volume,
                  const VolumeWriteOptions& options) {
  volume.validate();
  const VolumeFormat f = options.format ? *options.format : volume_format_of(path);
  switch (f) {
  case VolumeFormat::vol: {
    if (volume.dim() != 3)
      throw InvalidArgument(path + ": .vol holds 3D volumes, this one is " +
                            describe_volume(volume));
    auto values = integer_values<std::uint8_t>(volume, 255, path, ".vol voxel");
    write_vol(path, Image<std::uint8_t>(volume.domain(), std::move(values)), options.vol_version);
    return;
  }
  case VolumeFormat::nifti:
  case VolumeFormat::nifti_gz:
    write_nifti(path, volume, f == VolumeFormat::nifti_gz);
    return;
  case VolumeFormat::npy:
    write_npy(path, physical_array(volume));
    return;
  case VolumeFormat::pgm: {
    if (volume.dim() != 2)
      throw InvalidArgument(path + ": .pgm holds 2D images, this volume is " +
                            describe_volume(volume));
    auto values = integer_values<std::uint64_t>(volume, 65535, path, "PGM pixel");
    write_pgm(path, Image<std::uint64_t>(Domain(volume.array.shape), std::move(values)));
    return;
  }
  case VolumeFormat::vdb:
    write_vdb(path, volume);
    return;
  case VolumeFormat::raw: {
    if (!volume.scaled()) {
      write_raw(path, volume);
    } else {
      ScalarVolume v = make_scalar_volume(physical_array(volume));
      write_raw(path, v);
    }
    return;
  }
  }
}

} // namespace zdg
