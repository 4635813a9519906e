#include <zdg/kernel/images/object_selection.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/arith/integer.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <vector>

namespace zdg {

namespace {

std::string number(double x) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x); // shortest text that reads back to x
  return std::string(buf, r.ptr);
}

// The sign of v - t for an integer v and a double t that is not NaN, exactly: every int64 and
// uint64 and every integral double in [-2^64, 2^64] is exact in 128 bits.
template <class I>
int compare_exact(I v, double t) {
  constexpr double two64 = 18446744073709551616.0;
  if (t >= two64) return -1;
  if (t < -two64) return 1;
  const double f = std::floor(t);
  const auto fi = static_cast<int128_t>(f);
  const auto vi = static_cast<int128_t>(v);
  if (vi < fi) return -1;
  if (vi > fi) return 1;
  return t == f ? 0 : -1;
}

template <class I>
bool selects_integer(const ObjectSelection& s, I v) {
  bool in = false;
  switch (s.rule) {
  case ObjectSelection::Rule::nonzero:
    in = v != 0;
    break;
  case ObjectSelection::Rule::at_least:
    in = compare_exact(v, s.low) >= 0;
    break;
  case ObjectSelection::Rule::range:
    in = compare_exact(v, s.low) >= 0 && compare_exact(v, s.high) <= 0;
    break;
  case ObjectSelection::Rule::equal:
    in = compare_exact(v, s.low) == 0;
    break;
  }
  return in != s.invert;
}

template <class T>
T load(const unsigned char* p) {
  T v;
  std::memcpy(&v, p, sizeof(T));
  return v;
}

struct Partial {
  std::int64_t voxels = 0;
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
};

template <class T>
SelectedObject select_typed(const ScalarVolume& v, const ObjectSelection& s, unsigned threads) {
  SelectedObject out;
  out.mask = Image<std::uint8_t>(v.domain());
  const std::int64_t n = v.count();
  const unsigned char* bytes = v.array.bytes.data();
  std::uint8_t* mask = out.mask.values().data();
  const bool scaled = v.scaled();
  constexpr bool is_float = std::is_floating_point_v<T>;
  // 8- and 16-bit stored values: the rule as a table over every stored value.
  constexpr bool small = !is_float && sizeof(T) <= 2;
  std::vector<std::uint8_t> table;
  if constexpr (small) {
    table.resize(std::size_t{1} << (8 * sizeof(T)));
    for (std::size_t k = 0; k < table.size(); ++k) {
      using U = std::make_unsigned_t<T>;
      const T t = static_cast<T>(static_cast<U>(k));
      table[k] =
          scaled ? s.selects(v.slope * static_cast<double>(t) + v.inter) : selects_integer(s, t);
    }
  }
  const std::int64_t blocks = std::min<std::int64_t>(n, 256);
  std::vector<Partial> part(static_cast<std::size_t>(blocks));
  parallel_for(blocks, threads, [&](std::int64_t b) {
    const std::int64_t begin = n / blocks * b + std::min(b, n % blocks);
    const std::int64_t end = begin + n / blocks + (b < n % blocks ? 1 : 0);
    Partial p;
    if constexpr (small) {
      using U = std::make_unsigned_t<T>;
      T lo = std::numeric_limits<T>::max(), hi = std::numeric_limits<T>::min();
      for (std::int64_t i = begin; i < end; ++i) {
        const T t = load<T>(bytes + i * static_cast<std::int64_t>(sizeof(T)));
        const std::uint8_t m = table[static_cast<U>(t)];
        mask[i] = m;
        p.voxels += m;
        lo = std::min(lo, t);
        hi = std::max(hi, t);
      }
      p.lo = scaled ? std::min(v.slope * lo + v.inter, v.slope * hi + v.inter) : lo;
      p.hi = scaled ? std::max(v.slope * lo + v.inter, v.slope * hi + v.inter) : hi;
    } else {
      for (std::int64_t i = begin; i < end; ++i) {
        const T t = load<T>(bytes + i * static_cast<std::int64_t>(sizeof(T)));
        bool m = false;
        double x = 0.0;
        if (scaled || is_float) {
          x = scaled ? v.slope * static_cast<double>(t) + v.inter : static_cast<double>(t);
          m = s.selects(x);
        } else {
          m = selects_integer(s, t);
          x = static_cast<double>(t);
        }
        mask[i] = m ? 1 : 0;
        p.voxels += m ? 1 : 0;
        if (x < p.lo) p.lo = x;
        if (x > p.hi) p.hi = x;
      }
    }
    part[static_cast<std::size_t>(b)] = p;
  });
  Partial all;
  for (const auto& p : part) {
    all.voxels += p.voxels;
    all.lo = std::min(all.lo, p.lo);
    all.hi = std::max(all.hi, p.hi);
  }
  out.voxels = all.voxels;
  const bool none = all.lo > all.hi; // every value NaN
  out.min_value = none ? std::numeric_limits<double>::quiet_NaN() : all.lo;
  out.max_value = none ? std::numeric_limits<double>::quiet_NaN() : all.hi;
  return out;
}

} // namespace

std::string ObjectSelection::describe() const {
  std::string s;
  switch (rule) {
  case Rule::nonzero:
    s = "value != 0";
    break;
  case Rule::at_least:
    s = "value >= " + number(low);
    break;
  case Rule::range:
    s = number(low) + " <= value <= " + number(high);
    break;
  case Rule::equal:
    s = "value == " + number(low);
    break;
  }
  return invert ? "not (" + s + ")" : s;
}

bool ObjectSelection::selects(double x) const {
  bool in = false;
  if (!std::isnan(x)) {
    switch (rule) {
    case Rule::nonzero:
      in = x != 0.0;
      break;
    case Rule::at_least:
      in = x >= low;
      break;
    case Rule::range:
      in = low <= x && x <= high;
      break;
    case Rule::equal:
      in = x == low;
      break;
    }
  }
  return in != invert;
}

SelectedObject select_object(const ScalarVolume& volume, const ObjectSelection& selection,
                             unsigned threads) {
  volume.validate();
  if (std::isnan(selection.low) || std::isnan(selection.high))
    throw InvalidArgument("object selection: a bound is NaN");
  if (selection.rule == ObjectSelection::Rule::range && selection.low > selection.high)
    throw InvalidArgument("object selection: range " + number(selection.low) + ":" +
                          number(selection.high) + " is empty (LO > HI)");
  switch (volume.array.dtype) {
  case DType::Bool:
  case DType::U8:
    return select_typed<std::uint8_t>(volume, selection, threads);
  case DType::I8:
    return select_typed<std::int8_t>(volume, selection, threads);
  case DType::U16:
    return select_typed<std::uint16_t>(volume, selection, threads);
  case DType::I16:
    return select_typed<std::int16_t>(volume, selection, threads);
  case DType::U32:
    return select_typed<std::uint32_t>(volume, selection, threads);
  case DType::I32:
    return select_typed<std::int32_t>(volume, selection, threads);
  case DType::U64:
    return select_typed<std::uint64_t>(volume, selection, threads);
  case DType::I64:
    return select_typed<std::int64_t>(volume, selection, threads);
  case DType::F32:
    return select_typed<float>(volume, selection, threads);
  case DType::F64:
    return select_typed<double>(volume, selection, threads);
  }
  throw InvalidArgument("object selection: unknown dtype");
}

} // namespace zdg
