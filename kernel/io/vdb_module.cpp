// The OpenVDB half of kernel/io/vdb_io.hpp, built as a module of its own (libzdg_vdb.so) that
// vdb_io.cpp loads at the first .vdb file: linked into every program, libopenvdb's 69,000
// symbol relocations cost each process about 45 ms at start (issue #40 item 3: `zdg --help`
// 56 ms, a program linking nothing but libopenvdb 52 ms, perf: the dynamic loader). The module
// links OpenVDB only; the few zdg functions this code calls are the host's, handed over when
// it is loaded (VdbHost), so that it holds no second copy of the library.
#include <zdg/kernel/io/vdb_module.hpp>

#include <zdg/arith/error.hpp>

#include <openvdb/io/File.h>
#include <openvdb/io/Stream.h>
#include <openvdb/openvdb.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <iostream>
#include <limits>
#include <mutex>
#include <sstream>
#include <vector>

namespace zdg {

namespace {
const VdbHost* g_host = nullptr;
} // namespace

// The host's functions that this code calls (declared in the zdg headers it includes).
std::string dtype_name(DType t) {
  return g_host->dtype_name(t);
}
bool dtype_is_float(DType t) {
  return g_host->dtype_is_float(t);
}
DType dtype_from_name(const std::string& name) {
  return g_host->dtype_from_name(name);
}
NpyArray make_npy(DType t, std::vector<std::int64_t> shape, const std::vector<std::int64_t>& v) {
  return g_host->make_npy(t, std::move(shape), v);
}
std::int64_t NpyArray::count() const {
  return g_host->npy_count(*this);
}
double ScalarVolume::value(std::int64_t i) const {
  return g_host->volume_value(*this, i);
}
void ScalarVolume::validate() const {
  g_host->volume_validate(*this);
}

namespace {

void init_openvdb() {
  static std::once_flag once;
  std::call_once(once, [] { openvdb::initialize(); });
}

template <class GridT, class T>
ScalarVolume dense_of(const std::string& path, const GridT& grid, DType dtype) {
  openvdb::CoordBBox box = grid.evalActiveVoxelBoundingBox();
  // zdg's own files name their dense box (metadata), which holds the active voxels.
  const auto lo = grid.template getMetadata<openvdb::Vec3IMetadata>("zdg_box_min");
  const auto hi = grid.template getMetadata<openvdb::Vec3IMetadata>("zdg_box_max");
  if (lo && hi) {
    const openvdb::CoordBBox named(openvdb::Coord(lo->value()), openvdb::Coord(hi->value()));
    if (!named.empty() && (box.empty() || named.isInside(box))) box = named;
  }
  if (box.empty()) throw IoError(path + ": grid '" + grid.getName() + "' has no active voxel");
  const openvdb::Coord dim = box.dim();
  const std::int64_t nx = dim.x(), ny = dim.y(), nz = dim.z();
  if (nx * ny > (std::int64_t{1} << 32) / nz) {
    throw IoError(path + ": the active voxels of grid '" + grid.getName() + "' span " +
                  std::to_string(nz) + " x " + std::to_string(ny) + " x " + std::to_string(nx) +
                  " voxels, past 2^32 as a dense volume");
  }
  const openvdb::math::Transform& xf = grid.transform();
  bool diagonal = xf.isLinear();
  if (diagonal) {
    const openvdb::Mat4d m = xf.baseMap()->getAffineMap()->getMat4();
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) diagonal = diagonal && (r == c || m(r, c) == 0.0);
  }
  if (!diagonal) {
    throw IoError(path + ": grid '" + grid.getName() +
                  "' has a transform that is not an axis-aligned scale and translation");
  }
  const openvdb::Vec3d size = xf.voxelSize();
  const openvdb::Vec3d first = xf.indexToWorld(box.min());
  ScalarVolume v;
  v.array.dtype = dtype;
  v.array.shape = {nz, ny, nx};
  v.array.bytes.resize(static_cast<std::size_t>(nx * ny * nz) * sizeof(T));
  v.lower = {box.min().z(), box.min().y(), box.min().x()};
  v.spacing = {size.z(), size.y(), size.x()};
  v.origin = {first.z(), first.y(), first.x()};
  auto acc = grid.getConstUnsafeAccessor(); // not registered with the tree: no TBB hash map
  std::size_t i = 0;
  for (std::int32_t z = box.min().z(); z <= box.max().z(); ++z) {
    for (std::int32_t y = box.min().y(); y <= box.max().y(); ++y) {
      for (std::int32_t x = box.min().x(); x <= box.max().x(); ++x, ++i) {
        const T value = static_cast<T>(acc.getValue(openvdb::Coord(x, y, z)));
        std::memcpy(v.array.bytes.data() + i * sizeof(T), &value, sizeof(T));
      }
    }
  }
  v.validate();
  return v;
}

template <class GridT>
typename GridT::Ptr filled_grid(const ScalarVolume& v, auto&& value_of) {
  auto grid = GridT::create(typename GridT::ValueType(0));
  auto acc = grid->getUnsafeAccessor(); // not registered with the tree
  const bool two = v.dim() == 2;
  const std::int64_t nz = two ? 1 : v.array.shape[0], ny = v.array.shape[two ? 0 : 1],
                     nx = v.array.shape[two ? 1 : 2];
  const std::int64_t lz = two ? 0 : v.lower[0], ly = v.lower[two ? 0 : 1],
                     lx = v.lower[two ? 1 : 2];
  std::int64_t i = 0;
  for (std::int64_t z = 0; z < nz; ++z) {
    for (std::int64_t y = 0; y < ny; ++y) {
      for (std::int64_t x = 0; x < nx; ++x, ++i) {
        const auto value = value_of(i);
        if (value != typename GridT::ValueType(0)) {
          acc.setValue(openvdb::Coord(static_cast<std::int32_t>(lx + x),
                                      static_cast<std::int32_t>(ly + y),
                                      static_cast<std::int32_t>(lz + z)),
                       value);
        }
      }
    }
  }
  return grid;
}

template <class T>
T stored(const ScalarVolume& v, std::int64_t i) {
  T x;
  std::memcpy(&x, v.array.bytes.data() + static_cast<std::size_t>(i) * sizeof(T), sizeof(T));
  return x;
}

// The stored value of voxel i as int64 (integer dtypes; uint64 past 2^63 refused).
std::int64_t integer_at(const std::string& path, const ScalarVolume& v, std::int64_t i) {
  switch (v.array.dtype) {
  case DType::Bool:
  case DType::U8:
    return stored<std::uint8_t>(v, i);
  case DType::U16:
    return stored<std::uint16_t>(v, i);
  case DType::U32:
    return stored<std::uint32_t>(v, i);
  case DType::U64: {
    const std::uint64_t x = stored<std::uint64_t>(v, i);
    if (x > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
      throw InvalidArgument(path + ": voxel " + std::to_string(i) + " holds " + std::to_string(x) +
                            ", past the int64 grids of OpenVDB");
    }
    return static_cast<std::int64_t>(x);
  }
  case DType::I8:
    return stored<std::int8_t>(v, i);
  case DType::I16:
    return stored<std::int16_t>(v, i);
  case DType::I32:
    return stored<std::int32_t>(v, i);
  case DType::I64:
    return stored<std::int64_t>(v, i);
  case DType::F32:
  case DType::F64:
    break;
  }
  throw std::logic_error("vdb: integer_at on a float volume");
}

} // namespace

ScalarVolume module_read(const std::string& path) {
  init_openvdb();
  openvdb::GridPtrVecPtr grids;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(path + ": cannot open");
  // The library's inline code warns on std::cerr (OPENVDB_LOG_WARN without log4cplus): the
  // warnings of a damaged file are held back, the error is one line.
  struct QuietCerr {
    std::ostringstream held;
    std::streambuf* old = std::cerr.rdbuf(held.rdbuf());
    ~QuietCerr() { std::cerr.rdbuf(old); }
  } quiet;
  // A stream that throws at the first read past the end: io::File reads a truncated file
  // without a word (the missing voxels as background), and the library would otherwise go on
  // with the lengths it failed to read (allocations of any size).
  in.exceptions(std::ios::failbit | std::ios::badbit);
  try {
    openvdb::io::Stream stream(in, false);
    grids = stream.getGrids();
  } catch (const openvdb::Exception& e) {
    throw IoError(path + ": not a readable OpenVDB file (" + e.what() + ")");
  } catch (const std::ios_base::failure&) {
    throw IoError(path + ": not a readable OpenVDB file (truncated or damaged: the data ends "
                         "early)");
  }
  if (in.fail() || !grids) {
    throw IoError(path + ": not a readable OpenVDB file (truncated or damaged: the data ends "
                         "early)");
  }
  std::string types;
  // zdg's own files name the integer dtype they were written from ("zdg_dtype").
  auto restore = [&](ScalarVolume v, const openvdb::GridBase& base) {
    const auto meta = base.getMetadata<openvdb::StringMetadata>("zdg_dtype");
    if (!meta) return v;
    DType t;
    try {
      t = dtype_from_name(meta->value());
    } catch (const Error&) {
      return v;
    }
    if (dtype_is_float(t) || t == v.array.dtype) return v;
    std::vector<std::int64_t> values(static_cast<std::size_t>(v.count()));
    for (std::int64_t i = 0; i < v.count(); ++i) {
      values[static_cast<std::size_t>(i)] = integer_at(path, v, i);
    }
    try {
      NpyArray a = make_npy(t, v.array.shape, values);
      v.array = std::move(a);
    } catch (const Error&) {
      // A value that does not fit the named dtype: the grid's type stands.
    }
    return v;
  };
  for (const auto& base : *grids) {
    if (auto g = openvdb::gridConstPtrCast<openvdb::BoolGrid>(base)) {
      return restore(dense_of<openvdb::BoolGrid, std::uint8_t>(path, *g, DType::Bool), *base);
    }
    if (auto g = openvdb::gridConstPtrCast<openvdb::FloatGrid>(base)) {
      return dense_of<openvdb::FloatGrid, float>(path, *g, DType::F32);
    }
    if (auto g = openvdb::gridConstPtrCast<openvdb::DoubleGrid>(base)) {
      return dense_of<openvdb::DoubleGrid, double>(path, *g, DType::F64);
    }
    if (auto g = openvdb::gridConstPtrCast<openvdb::Int32Grid>(base)) {
      return restore(dense_of<openvdb::Int32Grid, std::int32_t>(path, *g, DType::I32), *base);
    }
    if (auto g = openvdb::gridConstPtrCast<openvdb::Int64Grid>(base)) {
      return restore(dense_of<openvdb::Int64Grid, std::int64_t>(path, *g, DType::I64), *base);
    }
    types += (types.empty() ? "" : ", ") + base->valueType();
  }
  throw IoError(path + ": no bool, float, double, int32 or int64 grid (found: " +
                (types.empty() ? std::string("no grid") : types) + ")");
}

void module_write(const std::string& path, const ScalarVolume& v) {
  v.validate();
  init_openvdb();
  for (std::size_t k = 0; k < v.lower.size(); ++k) {
    const std::int64_t hi = v.lower[k] + v.array.shape[k] - 1;
    if (v.lower[k] < std::numeric_limits<std::int32_t>::min() ||
        hi > std::numeric_limits<std::int32_t>::max()) {
      throw InvalidArgument(path + ": the voxels' lattice coordinates leave int32 (OpenVDB's "
                                   "index space)");
    }
  }
  openvdb::GridBase::Ptr grid;
  const DType t = v.array.dtype;
  if (v.scaled() || t == DType::F64) {
    grid = filled_grid<openvdb::DoubleGrid>(v, [&](std::int64_t i) { return v.value(i); });
  } else if (t == DType::F32) {
    grid = filled_grid<openvdb::FloatGrid>(v, [&](std::int64_t i) { return stored<float>(v, i); });
  } else {
    bool binary = true, narrow = true;
    for (std::int64_t i = 0; i < v.count() && (binary || narrow); ++i) {
      const std::int64_t x = integer_at(path, v, i);
      binary = binary && (x == 0 || x == 1);
      narrow = narrow && x >= std::numeric_limits<std::int32_t>::min() &&
               x <= std::numeric_limits<std::int32_t>::max();
    }
    if (binary) {
      grid = filled_grid<openvdb::BoolGrid>(
          v, [&](std::int64_t i) { return integer_at(path, v, i) != 0; });
    } else if (narrow) {
      grid = filled_grid<openvdb::Int32Grid>(
          v, [&](std::int64_t i) { return static_cast<std::int32_t>(integer_at(path, v, i)); });
    } else {
      grid = filled_grid<openvdb::Int64Grid>(
          v, [&](std::int64_t i) { return integer_at(path, v, i); });
    }
  }
  // Voxel p at origin + spacing (p - lower): a scale by the spacing, then the translation.
  const bool two = v.dim() == 2;
  const double sx = v.spacing[two ? 1 : 2], sy = v.spacing[two ? 0 : 1],
               sz = two ? 1.0 : v.spacing[0];
  const double ox = v.origin[two ? 1 : 2] - sx * static_cast<double>(v.lower[two ? 1 : 2]);
  const double oy = v.origin[two ? 0 : 1] - sy * static_cast<double>(v.lower[two ? 0 : 1]);
  const double oz = two ? 0.0 : v.origin[0] - sz * static_cast<double>(v.lower[0]);
  auto xf = openvdb::math::Transform::createLinearTransform(1.0);
  xf->preScale(openvdb::Vec3d(sx, sy, sz));
  xf->postTranslate(openvdb::Vec3d(ox, oy, oz));
  grid->setTransform(xf);
  grid->setName("density");
  // The dense box, so that the zeros around the active voxels come back on reading.
  const std::int64_t lz = two ? 0 : v.lower[0], ly = v.lower[two ? 0 : 1],
                     lx = v.lower[two ? 1 : 2];
  const std::int64_t nz = two ? 1 : v.array.shape[0], ny = v.array.shape[two ? 0 : 1],
                     nx = v.array.shape[two ? 1 : 2];
  if (!v.scaled() && !dtype_is_float(t)) {
    grid->insertMeta("zdg_dtype", openvdb::StringMetadata(dtype_name(t)));
  }
  grid->insertMeta("zdg_box_min",
                   openvdb::Vec3IMetadata(openvdb::Vec3i(static_cast<int>(lx), static_cast<int>(ly),
                                                         static_cast<int>(lz))));
  grid->insertMeta("zdg_box_max", openvdb::Vec3IMetadata(openvdb::Vec3i(
                                      static_cast<int>(lx + nx - 1), static_cast<int>(ly + ny - 1),
                                      static_cast<int>(lz + nz - 1))));
  try {
    openvdb::io::File file(path);
    openvdb::GridPtrVec out{grid};
    file.write(out);
    file.close();
  } catch (const openvdb::Exception& e) {
    throw IoError(path + ": cannot write the OpenVDB file (" + e.what() + ")");
  }
}

} // namespace zdg

extern "C" __attribute__((visibility("default"))) const zdg::VdbModule*
zdg_vdb_module(const zdg::VdbHost* host) {
  static const zdg::VdbModule module{zdg::kVdbModuleVersion, &zdg::module_read, &zdg::module_write};
  zdg::g_host = host;
  return &module;
}
