// NIfTI-1 and NIfTI-2 volumes (.nii, .nii.gz) through the NIfTI reference C library
// (nifti_clib, Debian's libnifti2-dev): zdg does not parse the header itself.
//
// Reading: nifti_image_read (header), zdg's checks, then nifti_image_load (data, byte-swapped
// to the host order by the library). Kept: 2D (dim[0] = 2) or 3D volumes (dims 4..7 must be
// 1) of uint8, int8, uint16, int16, uint32, int32, uint64, int64, float32 or float64; shape
// (nz, ny, nx) in C order (x fastest, as stored); spacing (pixdim[3], pixdim[2], pixdim[1]);
// origin the qoffset (qform_code > 0), else the sform translation (sform_code > 0), else 0
// (the rotation part of the affine is not kept); scl_slope / scl_inter when the slope is
// finite and nonzero (NIfTI's rule; otherwise no scaling). The sizes of the header are
// checked before the data is allocated: nx * ny * nz * bytes per voxel with overflow checks,
// against the file size (.nii: vox_offset + data <= size; .nii.gz: data <= 1032 x size, the
// largest expansion of deflate). Every failure is one IoError naming the file; the library's
// own diagnostics (it prints them on stderr) are captured and put in that line.
//
// Writing: nifti_make_new_nim + nifti_image_write_hdr_img2 into the staging file of an
// OutputSet (atomic), NIfTI-1 when every extent fits its 16-bit dims, NIfTI-2 otherwise;
// gzip-compressed when the name ends in .gz; qform_code 1 with identity rotation, qoffset =
// origin, pixdim = spacing, scl_slope / scl_inter = slope / inter (1 / 0 when unscaled);
// bool is stored as uint8. Writing a volume read from a zdg-written file gives the same bytes.
//
// The library keeps global state: calls are serialized by a mutex.
#pragma once

#include <zdg/kernel/images/scalar_volume.hpp>

#include <string>

namespace zdg {

/// Reads a .nii or .nii.gz file (by its name).
ScalarVolume read_nifti(const std::string& path);
/// Writes a .nii or .nii.gz file (by its name).
void write_nifti(const std::string& path, const ScalarVolume& volume);
/// Writes a NIfTI file, gzip-compressed or not, whatever its name (an OutputSet staging file).
void write_nifti(const std::string& path, const ScalarVolume& volume, bool gzip);

} // namespace zdg
