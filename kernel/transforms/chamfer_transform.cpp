#include <zdg/kernel/transforms/chamfer_transform.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/transforms/distance_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace zdg {

namespace {

// The moves of {-2..2}^d with at most `k` classes: class 1..d = number of nonzero coordinates in
// {-1, 0, 1}^d; class 3 in 2D = the knight moves.
int move_class(int dim, const std::vector<std::int64_t>& s) {
  int nonzero = 0, twos = 0;
  for (auto c : s) {
    if (c != 0) ++nonzero;
    if (c == 2 || c == -2) ++twos;
  }
  if (twos == 0) return nonzero;
  if (dim == 2 && twos == 1 && nonzero == 2) return 3; // (+-1, +-2), (+-2, +-1)
  return 0;
}

} // namespace

ChamferMask::ChamferMask(int dim, std::vector<std::int64_t> weights)
    : dim_(dim), weights_(std::move(weights)) {
  if (dim_ != 2 && dim_ != 3) {
    throw InvalidArgument("chamfer mask: dimension " + std::to_string(dim_) +
                          " (masks are 2D or 3D)");
  }
  if (weights_.empty() || weights_.size() > 3) {
    throw InvalidArgument(
        "chamfer mask: " + std::to_string(weights_.size()) + " weights (1 to 3: " +
        (dim_ == 2 ? std::string("axis, diagonal, knight") : std::string("face, edge, vertex")) +
        ")");
  }
  for (auto w : weights_) {
    if (w <= 0) {
      throw InvalidArgument("chamfer mask " + name() + ": the weights are positive integers");
    }
  }
  const auto classes = static_cast<int>(weights_.size());
  // Every step of {-2..2}^d in C order, kept when its class is one of the mask's.
  std::vector<std::int64_t> s(static_cast<std::size_t>(dim_), -2);
  for (;;) {
    const int c = move_class(dim_, s);
    if (c >= 1 && c <= classes) {
      moves_.push_back({s, weights_[static_cast<std::size_t>(c - 1)]});
    }
    int k = dim_ - 1;
    while (k >= 0 && s[static_cast<std::size_t>(k)] == 2) s[static_cast<std::size_t>(k--)] = -2;
    if (k < 0) break;
    ++s[static_cast<std::size_t>(k)];
  }
  std::stable_sort(moves_.begin(), moves_.end(), [&](const ChamferMove& a, const ChamferMove& b) {
    return move_class(dim_, a.step) < move_class(dim_, b.step);
  });
}

ChamferMask ChamferMask::parse(int dim, std::string_view text) {
  std::vector<std::int64_t> w;
  std::string_view rest = text;
  for (;;) {
    const auto comma = rest.find(',');
    const std::string_view item = rest.substr(0, comma);
    try {
      w.push_back(parse_integer<std::int64_t>(item));
    } catch (const Error& e) {
      throw InvalidArgument("chamfer mask '" + std::string(text) + "': " + e.what() +
                            " (weights as a comma list such as 3,4,5)");
    }
    if (comma == std::string_view::npos) break;
    rest.remove_prefix(comma + 1);
  }
  return ChamferMask(dim, std::move(w));
}

ChamferMask ChamferMask::borgefors(int dim) {
  if (dim == 2) return ChamferMask(2, {3, 4});
  return ChamferMask(dim, {3, 4, 5});
}

std::int64_t ChamferMask::max_weight() const {
  return *std::max_element(weights_.begin(), weights_.end());
}

std::string ChamferMask::name() const {
  std::string s = "<";
  for (std::size_t i = 0; i < weights_.size(); ++i) {
    if (i) s += ",";
    s += std::to_string(weights_[i]);
  }
  return s + ">";
}

ChamferErrorBound chamfer_error_bound(const ChamferMask& mask) {
  using Q = Rational<BigInt>;
  const auto& moves = mask.moves();
  const int d = mask.dim();
  auto norm2 = [](const std::vector<std::int64_t>& v) {
    BigInt s = 0;
    for (auto c : v) s += BigInt(c) * c;
    return s;
  };
  ChamferErrorBound r;
  // rho_min^2 = min w^2 / |m|^2 over the moves (the farthest vertex of the unit ball).
  bool first = true;
  for (const auto& m : moves) {
    const Q q(BigInt(m.weight) * m.weight, norm2(m.step));
    if (first || q < r.rho_min_squared) r.rho_min_squared = q;
    first = false;
  }
  // rho_max^2 = max |c|^2 over the facets <c, v> = 1 of the hull of the points m / w: c solves
  // <c, m_j> = w_j for d independent moves and <c, m_k> <= w_k for every move. Cramer's rule:
  // c = adj(M) w / det(M), M the matrix of rows m_j.
  const auto n = moves.size();
  first = true;
  auto consider = [&](const std::vector<std::size_t>& rows) {
    BigInt M[3][3];
    BigInt w[3];
    for (int i = 0; i < d; ++i) {
      for (int j = 0; j < d; ++j) {
        M[i][j] = moves[rows[static_cast<std::size_t>(i)]].step[static_cast<std::size_t>(j)];
      }
      w[i] = moves[rows[static_cast<std::size_t>(i)]].weight;
    }
    BigInt det;
    BigInt num[3]; // det * c
    if (d == 2) {
      det = M[0][0] * M[1][1] - M[0][1] * M[1][0];
      if (det == 0) return;
      num[0] = M[1][1] * w[0] - M[0][1] * w[1];
      num[1] = M[0][0] * w[1] - M[1][0] * w[0];
    } else {
      BigInt adj[3][3];
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
          // adj[i][j] = cofactor(j, i)
          const int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
          adj[i][j] = M[r0][c0] * M[r1][c1] - M[r0][c1] * M[r1][c0];
        }
      }
      det = M[0][0] * adj[0][0] + M[0][1] * adj[1][0] + M[0][2] * adj[2][0];
      if (det == 0) return;
      for (int i = 0; i < 3; ++i) num[i] = adj[i][0] * w[0] + adj[i][1] * w[1] + adj[i][2] * w[2];
    }
    if (det < 0) {
      det = -det;
      for (int i = 0; i < d; ++i) num[i] = -num[i];
    }
    for (const auto& m : moves) {
      BigInt dot = 0;
      for (int i = 0; i < d; ++i) dot += num[i] * m.step[static_cast<std::size_t>(i)];
      if (dot > det * m.weight) return; // m / w beyond the plane: not a facet
    }
    BigInt c2 = 0;
    for (int i = 0; i < d; ++i) c2 += num[i] * num[i];
    const Q q(c2, det * det);
    if (first || q > r.rho_max_squared) r.rho_max_squared = q;
    first = false;
  };
  std::vector<std::size_t> rows(static_cast<std::size_t>(d));
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a + 1; b < n; ++b) {
      rows[0] = a;
      rows[1] = b;
      if (d == 2) {
        consider(rows);
        continue;
      }
      for (std::size_t c = b + 1; c < n; ++c) {
        rows[2] = c;
        consider(rows);
      }
    }
  }
  r.rho_min = std::sqrt(r.rho_min_squared.to_double());
  r.rho_max = std::sqrt(r.rho_max_squared.to_double());
  const auto s = static_cast<double>(mask.axis_weight());
  r.error_below = r.rho_min / s - 1;
  r.error_above = r.rho_max / s - 1;
  r.optimal_scale = (r.rho_min + r.rho_max) / 2;
  r.optimal_error = (r.rho_max - r.rho_min) / (r.rho_max + r.rho_min);
  return r;
}

BigInt chamfer_transform_max_value(const Domain& domain, const ChamferMask& mask) {
  BigInt steps = 0;
  for (auto e : domain.extents()) steps += BigInt(e) - 1;
  return steps * mask.axis_weight();
}

namespace {

// The largest value of T (BigInt: none).
template <class T>
bool fits(const BigInt& v) {
  if constexpr (std::is_same_v<T, BigInt>) {
    return true;
  } else if constexpr (std::is_same_v<T, Int64>) {
    return v <= BigInt(std::numeric_limits<std::int64_t>::max());
  } else if constexpr (std::is_same_v<T, Int128>) {
    return v <= to_bigint(Int128(std::numeric_limits<int128_t>::max()));
  } else {
    return v <= BigInt(std::numeric_limits<T>::max());
  }
}

template <class T>
T from_int64(std::int64_t v) {
  if constexpr (std::is_same_v<T, BigInt>) {
    return BigInt(v);
  } else if constexpr (std::is_same_v<T, Int64> || std::is_same_v<T, Int128>) {
    return T(v);
  } else {
    return static_cast<T>(v);
  }
}

template <class T>
T from_bigint(const BigInt& v) {
  if constexpr (std::is_same_v<T, BigInt>) {
    return v;
  } else if constexpr (std::is_same_v<T, Int64> || std::is_same_v<T, Int128>) {
    return int_cast<T>(v);
  } else {
    return v.convert_to<T>();
  }
}

// One move of a scan: its linear offset (the neighbour read is i - offset), its step and weight.
template <class T>
struct ScanMove {
  std::int64_t offset;
  std::vector<std::int64_t> step;
  T weight;
};

// One raster scan (forward: C order, moves whose neighbour comes earlier; backward: the reverse)
// over rows along the last axis. The moves from other rows first (every neighbour final for this
// scan), then the moves within the row, sequentially in the scan's direction. Returns whether a
// value decreased.
template <class T>
bool scan(const Domain& dom, std::vector<T>& v, const std::vector<ScanMove<T>>& other_rows,
          const std::vector<ScanMove<T>>& in_row, bool forward) {
  const int d = dom.dim();
  const std::int64_t nx = dom.extent(d - 1);
  const std::int64_t rows = dom.size() / nx;
  std::vector<std::int64_t> p(static_cast<std::size_t>(d));
  bool changed = false;
  for (std::int64_t rr = 0; rr < rows; ++rr) {
    const std::int64_t r = forward ? rr : rows - 1 - rr;
    const std::int64_t base = r * nx;
    dom.point(base, p);
    for (const auto& m : other_rows) {
      bool inside = true;
      for (int k = 0; k + 1 < d && inside; ++k) {
        const auto q = p[static_cast<std::size_t>(k)] - m.step[static_cast<std::size_t>(k)];
        inside = q >= 0 && q < dom.extent(k);
      }
      if (!inside) continue;
      const std::int64_t sx = m.step.back();
      const std::int64_t x0 = std::max<std::int64_t>(0, sx), x1 = std::min(nx, nx + sx);
      if (x0 >= x1) continue;
      // The neighbour of base + x is base - offset + x, inside for x in [x0, x1).
      T* out = v.data() + base;
      const T* in = v.data() + (base - m.offset + x0);
      for (std::int64_t x = x0; x < x1; ++x) {
        if (out[x] == 0) continue;
        T c = in[x - x0] + m.weight;
        if (c < out[x]) {
          out[x] = std::move(c);
          changed = true;
        }
      }
    }
    if (in_row.empty()) continue;
    T* row = v.data() + base;
    for (std::int64_t xx = 0; xx < nx; ++xx) {
      const std::int64_t x = forward ? xx : nx - 1 - xx;
      if (row[x] == 0) continue;
      for (const auto& m : in_row) {
        const std::int64_t q = x - m.step.back();
        if (q < 0 || q >= nx) continue;
        T c = row[q] + m.weight;
        if (c < row[x]) {
          row[x] = std::move(c);
          changed = true;
        }
      }
    }
  }
  return changed;
}

} // namespace

template <class T>
Image<T> chamfer_transform(const Image<std::uint8_t>& shape, const ChamferMask& mask) {
  const Domain& dom = shape.domain();
  if (dom.dim() != mask.dim()) {
    throw InvalidArgument("chamfer transform: a " + std::to_string(mask.dim()) + "-D mask " +
                          mask.name() + " on a " + std::to_string(dom.dim()) + "-D image");
  }
  require_background(shape, TransformOptions{});
  const BigInt bound = chamfer_transform_max_value(dom, mask);
  if (!fits<T>(bound + mask.max_weight())) {
    throw OverflowError("chamfer transform: values up to " + bound.str() + " (mask " + mask.name() +
                        ") do not fit the value type");
  }
  // Foreground starts at B, an upper bound of every value (a path along the axes), so that a
  // candidate is at most B + the largest weight; a value 0 is background and stays.
  const T top = from_bigint<T>(bound);
  std::vector<T> v(static_cast<std::size_t>(dom.size()));
  for (std::int64_t i = 0; i < dom.size(); ++i) {
    v[static_cast<std::size_t>(i)] = shape[i] != 0 ? top : T(0);
  }
  // A foreground point of an image whose B is 0 cannot exist (one point with a background point).
  std::vector<ScanMove<T>> fwd_other, fwd_row, bwd_other, bwd_row;
  for (const auto& m : mask.moves()) {
    std::int64_t offset = 0;
    bool earlier = false, decided = false;
    for (int k = 0; k < dom.dim(); ++k) {
      const auto s = m.step[static_cast<std::size_t>(k)];
      offset += s * dom.stride(k);
      if (!decided && s != 0) {
        earlier = s > 0; // the neighbour x - s comes before x in C order
        decided = true;
      }
    }
    bool same_row = true;
    for (int k = 0; k + 1 < dom.dim(); ++k) same_row = same_row && m.step[k] == 0;
    ScanMove<T> sm{offset, m.step, from_int64<T>(m.weight)};
    auto& list = earlier ? (same_row ? fwd_row : fwd_other) : (same_row ? bwd_row : bwd_other);
    list.push_back(std::move(sm));
  }
  for (;;) {
    const bool a = scan(dom, v, fwd_other, fwd_row, true);
    const bool b = scan(dom, v, bwd_other, bwd_row, false);
    if (!a && !b) break;
  }
  return Image<T>(dom, std::move(v));
}

template Image<std::uint32_t> chamfer_transform(const Image<std::uint8_t>&, const ChamferMask&);
template Image<std::uint64_t> chamfer_transform(const Image<std::uint8_t>&, const ChamferMask&);
template Image<Int64> chamfer_transform(const Image<std::uint8_t>&, const ChamferMask&);
template Image<Int128> chamfer_transform(const Image<std::uint8_t>&, const ChamferMask&);
template Image<BigInt> chamfer_transform(const Image<std::uint8_t>&, const ChamferMask&);

} // namespace zdg
