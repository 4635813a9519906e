#include <zdg/kernel/images/rigid_motion.hpp>

#include <zdg/arith/error.hpp>

#include <algorithm>
#include <cmath>

namespace zdg {

namespace {

std::string str(const BigInt& v) {
  return to_string(v);
}

int128_t to_i128(const BigInt& v) {
  return int_cast<Int128>(v).value();
}

BigInt abs_big(const BigInt& v) {
  return v < 0 ? BigInt(-v) : v;
}

// floor(a / b) for b > 0 on raw 128-bit integers.
int128_t floor_div128(int128_t a, int128_t b) {
  int128_t q = a / b;
  if (a % b != 0 && a < 0) --q;
  return q;
}

// The motion as integers: D(p)_k = floor((sum_j coef[k][j] p_j + cst[k]) / q), q > 0, with
// coef = 2 vd m, cst = 2 n vn + n vd, q = 2 n vd (vd the common denominator of v).
struct Affine {
  int dim = 2;
  std::array<std::array<BigInt, 3>, 3> coef{};
  std::array<BigInt, 3> cst{};
  BigInt q;
};

Affine affine_of(const RigidMotion& m) {
  Affine a;
  a.dim = m.dim;
  BigInt vd = 1;
  for (int k = 0; k < m.dim; ++k) {
    const BigInt& d = m.v[static_cast<std::size_t>(k)].den();
    vd = vd / gcd(vd, d) * d;
  }
  for (int k = 0; k < m.dim; ++k) {
    const auto ku = static_cast<std::size_t>(k);
    for (int j = 0; j < m.dim; ++j) {
      const auto ju = static_cast<std::size_t>(j);
      a.coef[ku][ju] = 2 * vd * m.m[ku][ju];
    }
    const BigInt vn = m.v[ku].num() * (vd / m.v[ku].den());
    a.cst[ku] = 2 * m.n * vn + m.n * vd;
  }
  a.q = 2 * m.n * vd;
  return a;
}

const BigInt& limit126() {
  static const BigInt v = BigInt(1) << 126;
  return v;
}

// The affine form on raw 128-bit integers, valid for |p_j| <= bound[j] (checked here).
struct Affine128 {
  int dim = 2;
  int128_t coef[3][3]{};
  int128_t cst[3]{};
  int128_t q = 1;
};

Affine128 compile(const Affine& a, const std::array<BigInt, 3>& bound, const std::string& what) {
  Affine128 r;
  r.dim = a.dim;
  if (a.q >= limit126()) {
    throw OverflowError(what + ": the motion's denominators (2 n lcm(v)) = " + str(a.q) +
                        " do not fit 126 bits");
  }
  r.q = to_i128(a.q);
  for (int k = 0; k < a.dim; ++k) {
    const auto ku = static_cast<std::size_t>(k);
    BigInt s = abs_big(a.cst[ku]);
    for (int j = 0; j < a.dim; ++j) {
      const auto ju = static_cast<std::size_t>(j);
      s += abs_big(a.coef[ku][ju]) * bound[ju];
    }
    // The numerator and the image (|D| <= |num| / q + 1) must fit.
    if (s >= limit126() || s / a.q + 2 >= (BigInt(1) << 62)) {
      throw OverflowError(what + ": the images of the coordinates up to " + str(bound[0]) +
                          " do not fit 62 bits");
    }
    for (int j = 0; j < a.dim; ++j) {
      r.coef[k][j] = to_i128(a.coef[ku][static_cast<std::size_t>(j)]);
    }
    r.cst[k] = to_i128(a.cst[ku]);
  }
  return r;
}

void check_vector(const std::vector<Rational<BigInt>>& v, int dim, const char* what) {
  if (static_cast<int>(v.size()) != dim) {
    throw InvalidArgument(std::string(what) + ": " + std::to_string(v.size()) +
                          " coordinates for a motion of dimension " + std::to_string(dim));
  }
}

BigInt mod_big(const BigInt& a, const BigInt& c) {
  BigInt r = a % c;
  if (r < 0) r += c;
  return r;
}

} // namespace

RigidMotion rotation_2d(const BigInt& a, const BigInt& b, const BigInt& c) {
  if (c <= 0)
    throw InvalidArgument("rotation " + str(a) + "," + str(b) + "," + str(c) +
                          ": C must be positive");
  if (a * a + b * b != c * c) {
    throw InvalidArgument("rotation " + str(a) + "," + str(b) + "," + str(c) +
                          ": not a Pythagorean triple (A^2 + B^2 = " + str(a * a + b * b) +
                          ", C^2 = " + str(c * c) + ")");
  }
  const BigInt g = gcd(gcd(a, b), c);
  RigidMotion m;
  m.dim = 2;
  m.m[0] = {a / g, -b / g, 0};
  m.m[1] = {b / g, a / g, 0};
  m.n = c / g;
  return m;
}

RigidMotion rotation_3d(const BigInt& w, const BigInt& x, const BigInt& y, const BigInt& z) {
  const BigInt n = w * w + x * x + y * y + z * z;
  if (n == 0) throw InvalidArgument("quaternion 0,0,0,0: the zero quaternion is no rotation");
  RigidMotion m;
  m.dim = 3;
  m.m[0] = {w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)};
  m.m[1] = {2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)};
  m.m[2] = {2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z};
  BigInt g = n;
  for (const auto& row : m.m)
    for (const auto& e : row) g = gcd(g, e);
  for (auto& row : m.m)
    for (auto& e : row) e /= g;
  m.n = n / g;
  return m;
}

RigidMotion motion_about(const RigidMotion& rotation, const std::vector<Rational<BigInt>>& center,
                         const std::vector<Rational<BigInt>>& translation) {
  check_vector(center, rotation.dim, "center");
  check_vector(translation, rotation.dim, "translation");
  RigidMotion m = rotation;
  for (int k = 0; k < m.dim; ++k) {
    const auto ku = static_cast<std::size_t>(k);
    Rational<BigInt> rc(0);
    for (int j = 0; j < m.dim; ++j) {
      const auto ju = static_cast<std::size_t>(j);
      rc = rc + Rational<BigInt>(m.m[ku][ju], m.n) * center[ju];
    }
    m.v[ku] = center[ku] + translation[ku] - rc;
  }
  return m;
}

std::vector<BigInt> digitized_image(const RigidMotion& motion, const std::vector<BigInt>& p) {
  if (static_cast<int>(p.size()) != motion.dim) {
    throw InvalidArgument("digitized_image: a point of dimension " + std::to_string(p.size()) +
                          " for a motion of dimension " + std::to_string(motion.dim));
  }
  const Affine a = affine_of(motion);
  std::vector<BigInt> r(p.size());
  for (int k = 0; k < a.dim; ++k) {
    const auto ku = static_cast<std::size_t>(k);
    BigInt s = a.cst[ku];
    for (std::size_t j = 0; j < p.size(); ++j) s += a.coef[ku][j] * p[j];
    r[ku] = floor_div(s, a.q);
  }
  return r;
}

namespace {

// The state of D((i, 0)) along i: for each output coordinate the remainder of the floor
// division (0 <= r < q), advanced by additions only.
struct RowWalk {
  int128_t q = 1;
  int128_t r[2]{};
  int128_t step_r[2]{}; // coef mod q
};

// The image of the geometric point g under the compiled motion.
void image_of(const Affine128& f, const std::int64_t* g, std::int64_t* out) {
  for (int k = 0; k < f.dim; ++k) {
    int128_t s = f.cst[k];
    for (int j = 0; j < f.dim; ++j) s += f.coef[k][j] * g[j];
    out[k] = static_cast<std::int64_t>(floor_div128(s, f.q));
  }
}

// Past the period's range: a witness among the points near the origin. Two points with one
// image are 8-neighbours (|R p - R p'| < sqrt 2), so the pairs (p, p + e) are tried for the
// four directions e over the square rings |p|_inf = 0, 1, ..., 512; a hole is a point q of the
// rings up to 128 none of whose candidate preimages (within 1 of R^-1 (q - v)) maps to it.
void search_witness(const RigidMotion& motion, const Affine128& f, LatticeBijectivity& out) {
  const std::int64_t far = 512, far_hole = 128;
  auto ring = [](std::int64_t r, auto&& visit) {
    if (r == 0) return visit(0, 0);
    for (std::int64_t t = -r; t < r; ++t) {
      if (visit(t, -r) || visit(r, t) || visit(-t, r) || visit(-r, -t)) return true;
    }
    return false;
  };
  const std::int64_t dirs[4][2] = {{1, 0}, {0, 1}, {1, 1}, {1, -1}};
  for (std::int64_t r = 0; r <= far && !out.collision; ++r) {
    ring(r, [&](std::int64_t x, std::int64_t y) {
      std::int64_t g[3] = {x, y, 0}, q[3] = {0, 0, 0};
      image_of(f, g, q);
      for (const auto& e : dirs) {
        std::int64_t h[3] = {x + e[0], y + e[1], 0}, qh[3] = {0, 0, 0};
        image_of(f, h, qh);
        if (q[0] == qh[0] && q[1] == qh[1]) {
          out.collision = std::array<std::array<BigInt, 2>, 2>{
              std::array<BigInt, 2>{BigInt(x), BigInt(y)},
              std::array<BigInt, 2>{BigInt(h[0]), BigInt(h[1])}};
          out.collision_image = std::array<BigInt, 2>{BigInt(q[0]), BigInt(q[1])};
          return true;
        }
      }
      return false;
    });
  }
  const double n = to_double(motion.n), a = to_double(motion.m[0][0]) / n,
               b = to_double(motion.m[1][0]) / n;
  const double vx = to_double(motion.v[0].num()), vy = to_double(motion.v[1].num());
  for (std::int64_t r = 0; r <= far_hole && !out.hole; ++r) {
    ring(r, [&](std::int64_t x, std::int64_t y) {
      // R^-1 (q - v) = (a u + b w, -b u + a w) for (u, w) = q - v.
      const double u = static_cast<double>(x) - vx, w = static_cast<double>(y) - vy;
      const auto px = static_cast<std::int64_t>(std::floor(a * u + b * w)) - 2;
      const auto py = static_cast<std::int64_t>(std::floor(-b * u + a * w)) - 2;
      for (std::int64_t i = 0; i < 25; ++i) {
        std::int64_t g[3] = {px + i % 5, py + i / 5, 0}, q[3] = {0, 0, 0};
        image_of(f, g, q);
        if (q[0] == x && q[1] == y) return false;
      }
      out.hole = std::array<BigInt, 2>{BigInt(x), BigInt(y)};
      return true;
    });
  }
}

} // namespace

LatticeBijectivity lattice_bijectivity(const RigidMotion& motion) {
  if (motion.dim != 2) {
    throw InvalidArgument("lattice bijectivity: a motion of dimension " +
                          std::to_string(motion.dim) + "; the certificate is for Z^2");
  }
  const BigInt& a = motion.m[0][0];
  const BigInt& b = motion.m[1][0];
  const BigInt& c = motion.n;
  LatticeBijectivity out;
  out.period = c;
  if (c == 1) { // a quarter turn: D is an integer matrix plus a constant shift
    out.bijective = true;
    out.method = "period";
    return out;
  }
  // L = {(x, y) : x = s y mod c}, R L = {q : q_x = t q_y mod c} with t = a b^-1 mod c; the
  // class of q in Z^2 / R L is key(q) = q_x - t q_y mod c.
  const auto bz = ext_gcd(mod_big(b, c), c);
  if (bz.g != 1) {
    throw InvalidArgument("lattice bijectivity: gcd(b, c) = " + str(bz.g) +
                          " (the rotation is not reduced)");
  }
  const BigInt t = mod_big(a * bz.x, c);
  const Affine af = affine_of(motion);
  const bool integral_v = motion.v[0].den() == 1 && motion.v[1].den() == 1;
  const BigInt period_limit = BigInt(1) << 28;
  const bool by_theorem = c > period_limit;
  if (by_theorem && !integral_v) {
    throw InvalidArgument("lattice bijectivity: the period c = " + str(c) +
                          " exceeds 2^28 and the offset is not integral (the theorem covers "
                          "rotations about a lattice point)");
  }
  if (by_theorem) {
    out.method = "theorem";
    out.bijective = abs_big(a) == c - 1 || abs_big(b) == c - 1;
    if (!out.bijective) {
      try {
        search_witness(motion, compile(af, {1024, 1024, 0}, "lattice bijectivity"), out);
      } catch (const OverflowError&) {
        // Coefficients past 126 bits: the theorem's answer stands without a witness.
      }
    }
    return out;
  }
  const BigInt& count = c;
  // Keys and remainders along i = 0, 1, ..., count - 1.
  const Affine128 f = compile(af, {count, 0, 0}, "lattice bijectivity");
  RowWalk w;
  w.q = f.q;
  int128_t fl[2], da[2];
  for (int k = 0; k < 2; ++k) {
    fl[k] = floor_div128(f.cst[k], f.q);
    w.r[k] = f.cst[k] - fl[k] * f.q;
    da[k] = floor_div128(f.coef[k][0], f.q);
    w.step_r[k] = f.coef[k][0] - da[k] * f.q;
  }
  const BigInt key0 = mod_big(to_bigint(Int128(fl[0])) - t * to_bigint(Int128(fl[1])), c);
  // The key increments mod c: dx = da_x (+1 on a carry), dy = da_y (+1 on a carry).
  const int128_t c128 = to_i128(c);
  const int128_t kx128 = to_i128(mod_big(to_bigint(Int128(da[0])), c));
  const int128_t ky128 = to_i128(mod_big(t * to_bigint(Int128(da[1])), c));
  const int128_t t128 = to_i128(t);
  auto advance = [&](RowWalk& s, int128_t key) {
    int128_t dk = kx128 - ky128;
    s.r[0] += s.step_r[0];
    if (s.r[0] >= s.q) {
      s.r[0] -= s.q;
      dk += 1;
    }
    s.r[1] += s.step_r[1];
    if (s.r[1] >= s.q) {
      s.r[1] -= s.q;
      dk -= t128;
    }
    key += dk; // dk in (-2c, c + 1)
    while (key < 0) key += c128;
    while (key >= c128) key -= c128;
    return key;
  };
  const int128_t start_key = to_i128(key0);
  std::optional<std::pair<std::int64_t, int128_t>> dup; // (i2, key)
  const auto n = static_cast<std::int64_t>(to_i128(count));
  {
    std::vector<std::uint64_t> seen((static_cast<std::size_t>(n) + 63) / 64, 0);
    RowWalk s = w;
    int128_t key = start_key;
    for (std::int64_t i = 0; i < n; ++i) {
      if (i > 0) key = advance(s, key);
      const auto ku = static_cast<std::size_t>(key);
      const std::uint64_t bit = std::uint64_t{1} << (ku & 63);
      if ((seen[ku >> 6] & bit) != 0) {
        if (!dup) dup = std::make_pair(i, key);
      } else {
        seen[ku >> 6] |= bit;
      }
    }
    out.method = "period";
    out.bijective = !dup;
    if (dup) {
      for (std::size_t word = 0; word < seen.size() && !out.hole; ++word) {
        if (seen[word] == ~std::uint64_t{0}) continue;
        for (std::size_t bitpos = 0; bitpos < 64; ++bitpos) {
          const std::size_t k = word * 64 + bitpos;
          if (k >= static_cast<std::size_t>(n)) break;
          if ((seen[word] >> bitpos & 1) == 0) {
            // (k, 0) has key k; (k - c, 0) is in the same class.
            BigInt hx = BigInt(static_cast<std::int64_t>(k));
            if (2 * hx > c) hx -= c;
            out.hole = std::array<BigInt, 2>{hx, BigInt(0)};
            break;
          }
        }
      }
    }
  }
  if (dup) {
    // The first i1 with the duplicate key.
    RowWalk s = w;
    int128_t key = start_key;
    std::int64_t i1 = 0;
    for (;; ++i1) {
      if (i1 > 0) key = advance(s, key);
      if (key == dup->second) break;
    }
    const std::int64_t i2 = dup->first;
    const auto q1 = digitized_image(motion, {BigInt(i1), BigInt(0)});
    const auto q2 = digitized_image(motion, {BigInt(i2), BigInt(0)});
    // q1 - q2 = R l with l in L: (i2, 0) + l has the image q1.
    const BigInt dx = q1[0] - q2[0], dy = q1[1] - q2[1];
    const BigInt lx = a * dx + b * dy, ly = a * dy - b * dx;
    if (lx % c != 0 || ly % c != 0) {
      throw std::logic_error("lattice_bijectivity: the collision is not in R L");
    }
    out.collision =
        std::array<std::array<BigInt, 2>, 2>{std::array<BigInt, 2>{BigInt(i1), BigInt(0)},
                                             std::array<BigInt, 2>{BigInt(i2) + lx / c, ly / c}};
    out.collision_image = std::array<BigInt, 2>{q1[0], q1[1]};
  }
  return out;
}

namespace {

std::string point_text(const std::int64_t* g, int dim) {
  std::string s = "(";
  for (int k = 0; k < dim; ++k) {
    if (k > 0) s += ", ";
    s += std::to_string(g[k]);
  }
  return s + ")";
}

// Calls visit(g, image) for every object point (geometric coordinates), row by row with the
// floor divisions advanced by additions along x.
template <class Visit>
void for_each_image(const Image<std::uint8_t>& image, const Affine128& f, Visit&& visit) {
  const Domain& d = image.domain();
  const int dim = d.dim();
  const auto& ext = d.extents();
  const auto& low = d.lowers();
  const std::int64_t nx = ext[static_cast<std::size_t>(dim - 1)];
  const std::int64_t rows = d.size() / nx;
  const std::uint8_t* v = image.values().data();
  std::int64_t g[3] = {0, 0, 0}, q[3] = {0, 0, 0};
  int128_t r[3], step_q[3], step_r[3];
  for (int k = 0; k < dim; ++k) {
    step_q[k] = floor_div128(f.coef[k][0], f.q);
    step_r[k] = f.coef[k][0] - step_q[k] * f.q;
  }
  for (std::int64_t row = 0; row < rows; ++row) {
    const std::uint8_t* line = v + row * nx;
    // Geometric coordinates of the row's first point: y = axis dim-2, z = axis 0 (3D).
    std::int64_t rest = row;
    for (int axis = dim - 2; axis >= 0; --axis) {
      const auto au = static_cast<std::size_t>(axis);
      g[dim - 1 - axis] = low[au] + rest % ext[au];
      rest /= ext[au];
    }
    g[0] = low[static_cast<std::size_t>(dim - 1)];
    bool started = false;
    for (std::int64_t x = 0; x < nx; ++x) {
      if (!started) {
        if (line[x] == 0) continue;
        g[0] = low[static_cast<std::size_t>(dim - 1)] + x;
        for (int k = 0; k < dim; ++k) {
          int128_t s = f.cst[k];
          for (int j = 0; j < dim; ++j) s += f.coef[k][j] * g[j];
          const int128_t fl = floor_div128(s, f.q);
          q[k] = static_cast<std::int64_t>(fl);
          r[k] = s - fl * f.q;
        }
        started = true;
      } else {
        ++g[0];
        for (int k = 0; k < dim; ++k) {
          q[k] += static_cast<std::int64_t>(step_q[k]);
          r[k] += step_r[k];
          if (r[k] >= f.q) {
            r[k] -= f.q;
            ++q[k];
          }
        }
      }
      if (line[x] != 0)
        visit(static_cast<const std::int64_t*>(g), static_cast<const std::int64_t*>(q));
    }
  }
}

} // namespace

MotionOnImage apply_motion(const Image<std::uint8_t>& image, const RigidMotion& motion,
                           bool expand) {
  const Domain& d = image.domain();
  const int dim = d.dim();
  if (dim != motion.dim) {
    throw InvalidArgument("motion: a " + std::to_string(motion.dim) + "D motion for a " +
                          std::to_string(dim) + "D image");
  }
  std::array<BigInt, 3> bound{0, 0, 0};
  for (int k = 0; k < dim; ++k) {
    const auto axis = static_cast<std::size_t>(dim - 1 - k);
    const std::int64_t lo = d.lowers()[axis], hi = lo + d.extents()[axis] - 1;
    bound[static_cast<std::size_t>(k)] = std::max(abs_big(BigInt(lo)), abs_big(BigInt(hi)));
  }
  const Affine128 f = compile(affine_of(motion), bound, "motion");
  // Geometric bounds of the result's domain.
  std::int64_t lo[3], hi[3];
  for (int k = 0; k < dim; ++k) {
    const auto axis = static_cast<std::size_t>(dim - 1 - k);
    lo[k] = d.lowers()[axis];
    hi[k] = lo[k] + d.extents()[axis] - 1;
  }
  if (expand) {
    for_each_image(image, f, [&](const std::int64_t*, const std::int64_t* q) {
      for (int k = 0; k < dim; ++k) {
        lo[k] = std::min(lo[k], q[k]);
        hi[k] = std::max(hi[k], q[k]);
      }
    });
  }
  std::vector<std::int64_t> ext(static_cast<std::size_t>(dim)), low(static_cast<std::size_t>(dim));
  for (int k = 0; k < dim; ++k) {
    const auto axis = static_cast<std::size_t>(dim - 1 - k);
    low[axis] = lo[k];
    ext[axis] = hi[k] - lo[k] + 1;
  }
  MotionOnImage out;
  out.image = Image<std::uint8_t>(Domain(ext, low), 0);
  const Domain& od = out.image.domain();
  std::uint8_t* ov = out.image.values().data();
  std::optional<std::array<std::int64_t, 3>> second; // the point of the first collision
  std::array<std::int64_t, 3> second_image{};
  for_each_image(image, f, [&](const std::int64_t* g, const std::int64_t* q) {
    ++out.points;
    std::int64_t index = 0;
    for (int k = 0; k < dim; ++k) {
      if (q[k] < lo[k] || q[k] > hi[k]) {
        throw InvalidArgument("motion: the object point " + point_text(g, dim) + " goes to " +
                              point_text(q, dim) + ", outside the domain (--expand grows it)");
      }
      const auto axis = static_cast<std::size_t>(dim - 1 - k);
      index += (q[k] - lo[k]) * od.stride(static_cast<int>(axis));
    }
    if (ov[index] != 0) {
      if (!second) {
        second = std::array<std::int64_t, 3>{g[0], dim > 1 ? g[1] : 0, dim > 2 ? g[2] : 0};
        second_image = {q[0], q[1], dim > 2 ? q[2] : 0};
      }
    } else {
      ov[index] = 1;
      ++out.images;
    }
  });
  if (second) {
    // The other preimage: within distance sqrt(dim)/2 < 1 of R^-1 (q - v), in the input's object.
    double y[3] = {0, 0, 0};
    const double n = to_double(motion.n);
    for (int j = 0; j < dim; ++j) {
      for (int k = 0; k < dim; ++k) {
        const auto ku = static_cast<std::size_t>(k);
        const double vk = to_double(motion.v[ku].num()) / to_double(motion.v[ku].den());
        y[j] += to_double(motion.m[ku][static_cast<std::size_t>(j)]) / n *
                (static_cast<double>(second_image[ku]) - vk);
      }
    }
    std::int64_t base[3], p[3] = {0, 0, 0}, img[3];
    for (int j = 0; j < dim; ++j) base[j] = static_cast<std::int64_t>(std::floor(y[j])) - 2;
    const int span = 5, total = dim == 2 ? span * span : span * span * span;
    for (int c = 0; c < total && out.collision_image.empty(); ++c) {
      int rest = c;
      for (int j = 0; j < dim; ++j) {
        p[j] = base[j] + rest % span;
        rest /= span;
      }
      bool same = true, inside = true;
      std::vector<std::int64_t> idx(static_cast<std::size_t>(dim));
      for (int j = 0; j < dim; ++j) {
        same = same && p[j] == (*second)[static_cast<std::size_t>(j)];
        const auto axis = static_cast<std::size_t>(dim - 1 - j);
        idx[axis] = p[j];
        inside = inside && p[j] >= d.lowers()[axis] && p[j] < d.lowers()[axis] + d.extents()[axis];
      }
      if (same || !inside || image.at(idx) == 0) continue;
      image_of(f, p, img);
      bool hit = true;
      for (int k = 0; k < dim; ++k)
        hit = hit && img[k] == second_image[static_cast<std::size_t>(k)];
      if (!hit) continue;
      std::vector<std::int64_t> first(p, p + dim), other(second->begin(), second->begin() + dim);
      out.collision = std::array<std::vector<std::int64_t>, 2>{first, other};
      out.collision_image.assign(second_image.begin(), second_image.begin() + dim);
    }
    if (out.collision_image.empty()) {
      throw std::logic_error("apply_motion: the first preimage of a collision was not found");
    }
  }
  return out;
}

} // namespace zdg
