// Digitized rigid motions of Z^2 and Z^3 with rational rotations, and their certificates.
//
// A motion is x -> R x + v with R = M / n a rational rotation (M an integer matrix, n > 0,
// gcd of M's entries and n equal to 1) and v a rational vector. In 2D, R comes from a
// Pythagorean triple a^2 + b^2 = c^2 (cos = a/c, sin = b/c: every rational rotation of the
// plane is one); in 3D from a quaternion q = (w, x, y, z) with integer entries (R = M / |q|^2,
// M the quaternion's integer rotation matrix; every rational rotation of space is one, up to
// the reduction by the gcd). Coordinates are geometric, (x, y) or (x, y, z): x is the last
// array axis (ARCHITECTURE.md, arrays in C order).
//
// The digitized motion is D(p) = floor(R p + v + 1/2) componentwise (half-integers round up),
// computed exactly (BigInt set-up, then 128-bit integers whose bounds are checked on the domain).
//
// Certificates:
// - lattice_bijectivity (2D): whether D is a bijection of Z^2, with a witness when it is not
//   (two points with one image, and a point with no preimage). For a primitive triple the
//   points l with R l in Z^2 form a lattice L of index c (Roussillon, Coeurjolly,
//   "Characterization of bijective discretized rotations by Gaussian integers", 2016: L is
//   the ideal of a Gaussian integer of norm c), and D(p + l) = D(p) + R l. So D is a bijection
//   iff the c points (i, 0), 0 <= i < c, which represent Z^2 / L, have images in distinct
//   classes of Z^2 / R L; injectivity and surjectivity fail together (c classes on each side).
//   O(c) time, c / 8 bytes; "method": "period". Past c = 2^28 and for an integral v (a
//   rotation about a lattice point), the answer is the theorem of Nouvel and Remila
//   ("Characterization of bijective discretized rotations", IWCIA 2004; Roussillon and
//   Coeurjolly 2016): D is a bijection iff max(|a|, |b|) = c - 1, i.e. the triple is
//   (2k+1, 2k^2+2k, 2k^2+2k+1) up to order and signs; the witness is then searched near
//   the origin (two points with one image are 8-neighbours: the pairs (p, p + e) with
//   |p|_inf <= 512, and holes with |q|_inf <= 128) and may be absent; "method": "theorem".
//   Past 2^28 with a non-integral v: InvalidArgument.
// - apply_motion: D on the object of a binary image (2D or 3D), with the injectivity of D on
//   that finite set (Pluta, Romon, Kenmochi, Passat, "Bijective digitized rigid motions on
//   subsets of the plane", JMIV 59, 2017: the images of the set are distinct) and a witness
//   pair when it is not. O(N) for N points in the domain. Topology preservation (Betti
//   numbers, well-composedness: kernel/topology/well_composed.hpp) is compared by the callers.
//
// Errors: InvalidArgument (not a triple, c <= 0, the zero quaternion, wrong dimensions, an
// object point leaving the domain without `expand`, a period past the certificate's range),
// OverflowError (a coordinate bound that does not fit 128 bits).
#pragma once

#include <zdg/arith/integer.hpp>
#include <zdg/arith/rational.hpp>
#include <zdg/kernel/images/image.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace zdg {

struct RigidMotion {
  int dim = 2;
  /// R = m / n; row k gives geometric coordinate k (only the dim x dim block is used).
  std::array<std::array<BigInt, 3>, 3> m{};
  BigInt n = 1;
  /// v, geometric order.
  std::array<Rational<BigInt>, 3> v{};
};

/// The rotation of the plane with cos = a/c, sin = b/c. InvalidArgument unless c > 0 and
/// a^2 + b^2 = c^2. The triple is reduced by gcd(a, b, c).
RigidMotion rotation_2d(const BigInt& a, const BigInt& b, const BigInt& c);

/// The rotation of space of the quaternion w + x i + y j + z k (not zero): R = M / (w^2 + x^2 +
/// y^2 + z^2), reduced by the gcd of M's entries and the norm.
RigidMotion rotation_3d(const BigInt& w, const BigInt& x, const BigInt& y, const BigInt& z);

/// The motion p -> R (p - center) + center + translation of a rotation (its v is replaced).
/// Both vectors have the rotation's dimension (InvalidArgument otherwise).
RigidMotion motion_about(const RigidMotion& rotation, const std::vector<Rational<BigInt>>& center,
                         const std::vector<Rational<BigInt>>& translation);

/// D(p) for a point of Z^dim (geometric order).
std::vector<BigInt> digitized_image(const RigidMotion& motion, const std::vector<BigInt>& p);

struct LatticeBijectivity {
  bool bijective = false;
  std::string method; ///< "period" or "theorem"
  BigInt period;      ///< c: the index of the period lattice L in Z^2
  /// Two points of Z^2 with the same image, and that image (when not bijective; absent only
  /// when the theorem answered and the search found none).
  std::optional<std::array<std::array<BigInt, 2>, 2>> collision;
  std::optional<std::array<BigInt, 2>> collision_image;
  /// A point of Z^2 with no preimage (when not bijective; absent only when the theorem answered
  /// and the search found none).
  std::optional<std::array<BigInt, 2>> hole;
};

/// Whether D is a bijection of Z^2 (motion.dim must be 2).
LatticeBijectivity lattice_bijectivity(const RigidMotion& motion);

struct MotionOnImage {
  /// D(X) for the object X (nonzero points) of the input, 0/1.
  Image<std::uint8_t> image;
  std::int64_t points = 0; ///< |X|
  std::int64_t images = 0; ///< |D(X)|; D is injective on X iff images == points
  /// Two points of X with one image (geometric order), and the image, when not injective.
  std::optional<std::array<std::vector<std::int64_t>, 2>> collision;
  std::vector<std::int64_t> collision_image;
};

/// D applied to the object of a 2D or 3D binary image (the image's dimension must be the
/// motion's). The result's domain is the input's, or with `expand` the smallest box that
/// contains the input's domain and D(X) (its lower bounds may be negative). Without `expand`,
/// an object point whose image leaves the domain is an InvalidArgument naming it.
MotionOnImage apply_motion(const Image<std::uint8_t>& image, const RigidMotion& motion,
                           bool expand = false);

} // namespace zdg
