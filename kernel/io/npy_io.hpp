// NumPy .npy files (format versions 1.0, 2.0 and 3.0): read and write n-D arrays.
//
// Accepted dtypes: bool, uint8, uint16, uint32, uint64, int8, int16, int32, int64, float32,
// float64 (little-endian or byte-sized), in C or Fortran order (a Fortran-order file, as numpy
// writes for a transposed array, is read into C order: the same array as np.load gives). The
// header dict is parsed as the Python literal numpy writes (keys 'descr', 'fortran_order',
// 'shape', each once; shape entries decimal integers); big-endian or other dtypes (float16,
// complex, structured), malformed headers,
// truncated data and trailing bytes are IoError naming the file and the problem. The data size
// implied by the header (a product checked against overflow) must equal what the file holds, and it
// is checked before anything is allocated: a short file cannot ask for a huge array. Writing:
// version 1.0 while the header fits its 2-byte length (65535 bytes), else 2.0 (4-byte length;
// headers are ASCII, so 3.0 is never needed), padded to 64 bytes as numpy does; the file is written
// atomically (kernel/io/output_files.hpp).
//
// parse_npy works on the bytes of a whole file (the fuzz target); read_npy reads a file without
// holding it twice (header first, then the data straight into the array).
#pragma once

#include <zdg/kernel/images/image.hpp>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace zdg {

enum class DType { Bool, U8, U16, U32, U64, I8, I16, I32, I64, F32, F64 };

/// "bool", "uint8", ..., "int64", "float32", "float64".
std::string dtype_name(DType t);
/// Size of one element in bytes.
std::size_t dtype_size(DType t);

/// An array as stored: dtype, shape (C order) and the raw little-endian bytes.
struct NpyArray {
  DType dtype = DType::U8;
  std::vector<std::int64_t> shape;
  std::vector<unsigned char> bytes;

  std::int64_t count() const;
  /// Element i as an int64 (IoError for a uint64 value > 2^63 - 1 and for a float dtype).
  std::int64_t get(std::int64_t i) const;
  /// Element i as a double (exact for every dtype but 64-bit integers past 2^53).
  double get_double(std::int64_t i) const;
};

/// True for float32 and float64.
bool dtype_is_float(DType t);
/// The dtype named "bool", "uint8", ..., "float64" (InvalidArgument for another name).
DType dtype_from_name(const std::string& name);

/// The array stored in the bytes of an npy file (source names it in errors).
NpyArray parse_npy(std::string_view bytes, const std::string& source);
NpyArray read_npy(const std::string& path);
/// The bytes of the npy file of a (version 1.0, or 2.0 for a header past 65535 bytes).
std::string npy_file_bytes(const NpyArray& a);
/// The prefix of such a file (magic, version, header dict, padding to 64 bytes): the array's
/// bytes follow it. For writers that stream or map the data (kernel/io/mapped_file.hpp).
std::string npy_header_bytes(DType t, const std::vector<std::int64_t>& shape);

/// Where an npy file's array is: its dtype, shape, and the offset and size of the data, from
/// the header alone, with every check of read_npy (the data size equals what the file holds).
/// For readers that map the file instead of reading it (no size limit but the file's).
/// A Fortran-order file's data are in file order (first axis fastest): a reader that maps the
/// data must reorder them or refuse.
struct NpyLayout {
  DType dtype = DType::U8;
  std::vector<std::int64_t> shape;
  std::uint64_t data_offset = 0, data_bytes = 0;
  bool fortran_order = false;
};
NpyLayout read_npy_layout(const std::string& path);
/// Writes atomically (temporary file + rename). IoError on failure.
void write_npy(const std::string& path, const NpyArray& a);

/// Builds an array of dtype t from int64 values (InvalidArgument when a value does not fit).
NpyArray make_npy(DType t, std::vector<std::int64_t> shape, const std::vector<std::int64_t>& v);
/// Same from a typed buffer (T an unsigned or signed machine integer, float or double).
template <class T>
NpyArray make_npy(std::vector<std::int64_t> shape, const std::vector<T>& v);

/// The array as a binary image (nonzero = 1; for floats, value != 0, so -0.0 is 0 and NaN is 1) on
/// the domain with these lower bounds (empty = all 0). A 0-D array is an IoError.
Image<std::uint8_t> npy_to_mask(const NpyArray& a, const std::vector<std::int64_t>& lower = {});
/// The array as int64 values (IoError for a float dtype).
Image<std::int64_t> npy_to_int64(const NpyArray& a, const std::vector<std::int64_t>& lower = {});

} // namespace zdg
