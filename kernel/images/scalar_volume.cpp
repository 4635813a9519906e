#include <zdg/kernel/images/scalar_volume.hpp>

#include <zdg/arith/error.hpp>

#include <cmath>
#include <cstring>

namespace zdg {

double ScalarVolume::value(std::int64_t i) const {
  const double v = array.get_double(i);
  return scaled() ? slope * v + inter : v;
}

void ScalarVolume::validate() const {
  const auto d = array.shape.size();
  if (d != 2 && d != 3) {
    throw InvalidArgument("volume with " + std::to_string(d) + " axes (2 or 3 needed)");
  }
  std::int64_t n = 1;
  for (auto s : array.shape) {
    if (s < 1) throw InvalidArgument("volume extent " + std::to_string(s) + " is not positive");
    if (__builtin_mul_overflow(n, s, &n))
      throw InvalidArgument("volume: the number of voxels does not fit int64");
  }
  std::uint64_t bytes = 0;
  if (__builtin_mul_overflow(static_cast<std::uint64_t>(n),
                             static_cast<std::uint64_t>(dtype_size(array.dtype)), &bytes) ||
      bytes != array.bytes.size()) {
    throw InvalidArgument("volume: " + std::to_string(array.bytes.size()) + " bytes for " +
                          std::to_string(n) + " voxels of " + dtype_name(array.dtype));
  }
  if (lower.size() != d || spacing.size() != d || origin.size() != d)
    throw InvalidArgument("volume: lower, spacing and origin need one entry per axis");
  if (!std::isfinite(slope) || !std::isfinite(inter) || slope == 0.0)
    throw InvalidArgument("volume: value scaling slope " + std::to_string(slope) + ", inter " +
                          std::to_string(inter) + " (finite, slope != 0 needed)");
}

ScalarVolume make_scalar_volume(NpyArray array) {
  ScalarVolume v;
  const auto d = array.shape.size();
  v.array = std::move(array);
  v.lower.assign(d, 0);
  v.spacing.assign(d, 1.0);
  v.origin.assign(d, 0.0);
  return v;
}

ScalarVolume make_scalar_volume(const Image<std::uint8_t>& image) {
  NpyArray a;
  a.dtype = DType::U8;
  a.shape = image.domain().extents();
  a.bytes.resize(image.values().size());
  if (!a.bytes.empty()) std::memcpy(a.bytes.data(), image.values().data(), a.bytes.size());
  ScalarVolume v = make_scalar_volume(std::move(a));
  v.lower = image.domain().lowers();
  return v;
}

std::string describe_volume(const ScalarVolume& v) {
  std::string s = "(";
  for (std::size_t k = 0; k < v.array.shape.size(); ++k) {
    if (k > 0) s += ", ";
    s += std::to_string(v.array.shape[k]);
  }
  return s + ") " + dtype_name(v.array.dtype);
}

} // namespace zdg
