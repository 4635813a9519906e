// NIfTI-1 and NIfTI-2 volumes (.nii, .nii.gz) through the NIfTI reference C library
// (nifti_clib, Debian's libnifti2-dev) for the header's conversion and the writing.
//
// Reading: zdg reads the raw header (348 or 540 bytes, through zlib for .nii.gz) and checks
// every field that the library or the reader trusts BEFORE the library sees it (the library
// uses dim[0] as a loop bound and takes vox_offset as it is); then nifti_convert_n1hdr2nim /
// n2hdr2nim converts it (no extension is read: zdg does not use them), and zdg reads the
// voxels itself (nifti_image_load would replace NaN and infinities by 0). The checks:
//   - sizeof_hdr 348 (NIfTI-1) or 540 (NIfTI-2), in either byte order (that order is the
//     file's); magic n+1, or n+2 followed by its check bytes \r\n\032\n or by zeros (as
//     libnifti 3.0 writes it); single-file only: a .hdr/.img pair, ANALYZE 7.5 or a damaged
//     magic is refused;
//   - dim[0] in 1..7, dim[1..dim[0]] >= 1, dims 4..7 equal to 1 (2D when dim[0] = 2, else 3D);
//   - datatype uint8, int8, uint16, int16, uint32, int32, uint64, int64, float32 or float64,
//     and bitpix its width in bits; nx * ny * nz * bytes per voxel <= 2^62 (overflow-checked);
//   - vox_offset an integer >= 352 (NIfTI-1, a float below 2^31) or >= 544 (NIfTI-2): the
//     header and its 4-byte extension flag; .nii: vox_offset + data <= the file size;
//     .nii.gz: vox_offset + data <= 1032 x the file size + 1024 (deflate's largest expansion);
//   - the kept values are numbers: pixdim[1..d] finite, scl_inter finite when scaling,
//     the origin used (qoffset, or the sform translation) finite.
// Kept: shape (nz, ny, nx) in C order (x fastest, as stored); spacing (pixdim[3], pixdim[2],
// pixdim[1]), where a 0 reads as 1 (the library's rule); origin the qoffset (qform_code > 0),
// else the sform translation (sform_code > 0), else 0 (the rotation part of the affine is not
// kept); scl_slope / scl_inter when the slope is finite and nonzero (NIfTI's rule; otherwise
// no scaling). Data is byte-swapped to the machine's order. A .nii.gz takes memory as its
// bytes inflate (kernel/io/input_file.hpp's ArrivingBytes), not for what the header claims,
// and is read to its end (the gzip CRC). Every failure is one IoError naming the file; the
// library's own diagnostics (it prints them on stderr) are captured and put in that line.
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
