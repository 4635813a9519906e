// Shared helpers of the two translation units of the Python module: Python ints <-> BigInt
// (exact, any size, through base 16, which Python's int/str digit limit does not cover), and
// numpy arrays that own a C++ buffer (a capsule frees it: no copy on the way out).
#pragma once
#include <zdg/arith/error.hpp>
#include <zdg/arith/integer.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace zdg::python {

namespace py = pybind11;

void bind_arrays(py::module_& m);

/// A Python integer (or anything with __index__: numpy integers) as a BigInt; TypeError else.
inline BigInt py_to_bigint(py::handle h, const char* what) {
  if (PyBool_Check(h.ptr())) {
    throw py::type_error(std::string(what) + ": expected an integer, got a bool");
  }
  PyObject* index = PyNumber_Index(h.ptr());
  if (index == nullptr) {
    PyErr_Clear();
    throw py::type_error(std::string(what) + ": expected an integer, got " +
                         std::string(py::str(py::type::of(h))));
  }
  py::object n = py::reinterpret_steal<py::object>(index);
  int overflow = 0;
  long long v = PyLong_AsLongLongAndOverflow(n.ptr(), &overflow);
  if (overflow == 0) return BigInt(v);
  py::object hex = py::reinterpret_steal<py::object>(PyNumber_ToBase(n.ptr(), 16));
  if (!hex) throw py::error_already_set();
  std::string text = py::str(hex);
  bool negative = !text.empty() && text[0] == '-';
  std::string digits = text.substr(negative ? 3 : 2); // drop "0x" or "-0x"
  BigInt r;
  mpz_set_str(r.backend().data(), digits.c_str(), 16);
  return negative ? BigInt(-r) : r;
}

/// A file path argument (str, bytes or os.PathLike) as the file system's bytes (os.fsencode:
/// names that are not UTF-8 round-trip). Every function of the module that takes a path reads
/// it here. A NUL byte, which the system would take as the end of the name (opening another
/// file), is refused: InvalidArgument (ValueError) naming `what`. TypeError for other types.
inline std::string path_argument(const py::handle& path, const char* what) {
  const py::bytes encoded = py::module_::import("os").attr("fsencode")(path);
  std::string bytes = encoded;
  if (bytes.find('\0') != std::string::npos) {
    throw InvalidArgument(std::string(what) + ": the path " + std::string(py::repr(path)) +
                          " holds a NUL byte");
  }
  return bytes;
}

/// A BigInt as a Python int (exact).
inline py::int_ bigint_to_py(const BigInt& v) {
  if (v >= std::numeric_limits<long long>::min() && v <= std::numeric_limits<long long>::max()) {
    return py::int_(v.convert_to<long long>());
  }
  std::string text(mpz_sizeinbase(v.backend().data(), 16) + 2, '\0');
  mpz_get_str(text.data(), 16, v.backend().data());
  text.resize(std::strlen(text.c_str()));
  bool negative = !text.empty() && text[0] == '-';
  PyObject* r = PyLong_FromString(text.c_str() + (negative ? 1 : 0), nullptr, 16);
  if (r == nullptr) throw py::error_already_set();
  py::int_ out = py::reinterpret_steal<py::int_>(r);
  if (negative) return py::reinterpret_steal<py::int_>(PyNumber_Negative(out.ptr()));
  return out;
}

/// A numpy array of `shape` (C order, or F order when `fortran`) viewing the vector's buffer;
/// the array owns the vector (moved to the heap, freed by a capsule): no copy.
template <class T>
py::array_t<T> owning_array(std::vector<T>&& values, const std::vector<std::int64_t>& shape,
                            bool fortran = false) {
  auto* owned = new std::vector<T>(std::move(values));
  py::capsule free_when_done(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  std::vector<py::ssize_t> dims(shape.begin(), shape.end()), strides(shape.size());
  py::ssize_t s = static_cast<py::ssize_t>(sizeof(T));
  if (fortran) {
    for (std::size_t k = 0; k < shape.size(); ++k) {
      strides[k] = s;
      s *= dims[k];
    }
  } else {
    for (std::size_t k = shape.size(); k-- > 0;) {
      strides[k] = s;
      s *= dims[k];
    }
  }
  return py::array_t<T>(dims, strides, owned->data(), free_when_done);
}

} // namespace zdg::python
