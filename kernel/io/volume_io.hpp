// Reading and writing scalar volumes in any of zdg's formats, chosen by the file name:
//
//   .vol            DGtal volume, 3D uint8, Version 2 or 3       (kernel/io/vol_io.hpp)
//   .nii, .nii.gz   NIfTI-1/2, 2D or 3D, typed, spacing, scaling (kernel/io/nifti_io.hpp)
//   .npy            NumPy array, 2D or 3D, bool/int/float         (kernel/io/npy_io.hpp)
//   .pgm            2D Netpbm grey image (uint8, or uint16 when a value exceeds 255)
//   .raw            bare little-endian values; the shape and dtype are given
//                   (RawLayout), and any file name is read as raw when they are
//   .vdb            OpenVDB sparse grid (bool, float, double, int32, int64), spacing and
//                   origin, the active voxels' box (kernel/io/vdb_io.hpp)
//
// Writing keeps the stored dtype and bytes wherever the format can hold them, so that a
// round trip through one format is bit-identical. Where it cannot, the physical values
// (slope * stored + inter) are written: .npy and .raw get float64 when the volume is scaled;
// .vol needs integer values in 0..255 (3D), .pgm integer values in 0..65535 (2D); a value
// that does not fit is an InvalidArgument naming it. Spacing and origin are kept by NIfTI and
// .vdb, the scaling by NIfTI only (.vdb gets the physical values), the lattice lower bounds by
// .vol (its Center keys) and .vdb.
#pragma once

#include <zdg/kernel/images/scalar_volume.hpp>

#include <optional>
#include <string>
#include <vector>

namespace zdg {

enum class VolumeFormat { vol, nifti, nifti_gz, npy, pgm, raw, vdb };

/// "vol", "nifti", "nifti.gz", "npy", "pgm", "raw", "vdb".
std::string volume_format_name(VolumeFormat f);
/// The format of a file name by its extension (case-insensitive; IoError for another one).
VolumeFormat volume_format_of(const std::string& path);

/// The layout of a raw file (both or neither given).
struct RawLayout {
  std::vector<std::int64_t> shape; // (Z, Y, X) or (Y, X)
  std::optional<DType> dtype;
  bool given() const { return !shape.empty() || dtype.has_value(); }
};

/// Reads a volume; a raw layout, when given, makes the file raw whatever its name.
ScalarVolume read_volume(const std::string& path, const RawLayout& raw = {});

struct VolumeWriteOptions {
  int vol_version = 3;                ///< .vol Version: 2 (raw) or 3 (zlib)
  std::optional<VolumeFormat> format; ///< the format; default: by the file name (writing to
                                      ///< an OutputSet's staging file needs it given)
};

/// The values of an image file as exact integers, for the commands that work on integer images
/// (the transforms, topology): an .npy of any dimension (C or Fortran order) on the origin of
/// the lattice, or any volume read_volume reads (2D or 3D, with a .vol's lower bounds). The
/// physical values (slope * stored + inter) must be integers in int64: otherwise an IoError
/// naming the file, the first voxel that is not and its value. O(voxels).
Image<std::int64_t> read_integer_image(const std::string& path, const RawLayout& raw = {});

/// Writes a volume in the format of the options or of the file name (atomically).
void write_volume(const std::string& path, const ScalarVolume& volume,
                  const VolumeWriteOptions& options = {});

/// The physical values as an array: the stored array when not scaled, else float64.
NpyArray physical_array(const ScalarVolume& volume);

} // namespace zdg
