#include <zdg/estimators/moments.hpp>

#include <zdg/arith/escalate.hpp>

namespace zdg {

namespace {

template <TowerInt I>
std::array<I, 6> sums(const std::vector<DigitalContour>& contours) {
  std::array<I, 6> s{I(0), I(0), I(0), I(0), I(0), I(0)};
  for (const auto& c : contours) {
    Pixel p = c.start;
    for (auto code : c.codes) {
      if (code == 1 || code == 3) {
        // Up (1): ends the interval at x = p.x - 1 in row p.y; down (3): starts the
        // interval at x = p.x in row p.y - 1.
        I x = I(p.x);
        I y = code == 1 ? I(p.y) : I(p.y) - 1;
        I f0 = x, f1 = x * (x - 1) / 2, f2 = (x - 1) * x * (2 * x - 1) / 6;
        if (code == 3) {
          f0 = -f0;
          f1 = -f1;
          f2 = -f2;
        }
        s[0] += f0;
        s[1] += f1;
        s[2] += f0 * y;
        s[3] += f2;
        s[4] += f1 * y;
        s[5] += f0 * y * y;
      }
      Pixel d = freeman_step(code);
      p = Pixel{p.x + d.x, p.y + d.y};
    }
  }
  return s;
}

} // namespace

template <TowerInt I>
std::array<I, 6> digital_moments(const std::vector<DigitalContour>& contours) {
  return sums<I>(contours);
}

template std::array<Int64, 6> digital_moments<Int64>(const std::vector<DigitalContour>&);
template std::array<Int128, 6> digital_moments<Int128>(const std::vector<DigitalContour>&);
template std::array<BigInt, 6> digital_moments<BigInt>(const std::vector<DigitalContour>&);

Escalated<std::array<BigInt, 6>>
digital_moments_exact(const std::vector<DigitalContour>& contours) {
  return escalate([&]<class I>(std::type_identity<I>) {
    auto s = sums<I>(contours);
    std::array<BigInt, 6> out;
    for (std::size_t i = 0; i < 6; ++i) out[i] = to_bigint(s[i]);
    return out;
  });
}

std::array<double, 6> moments_estimate(const std::vector<DigitalContour>& contours, double h) {
  auto s = digital_moments_exact(contours).value;
  constexpr int order[6] = {0, 1, 1, 2, 2, 2};
  std::array<double, 6> m{};
  for (std::size_t i = 0; i < 6; ++i) {
    double scale = h * h;
    for (int k = 0; k < order[i]; ++k) scale *= h;
    m[i] = to_double(s[i]) * scale;
  }
  return m;
}

} // namespace zdg
