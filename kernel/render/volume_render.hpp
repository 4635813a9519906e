// Direct volume rendering of a scalar volume: front-to-back compositing through a transfer
// function, and maximum intensity projection (MIP) over exact digital rays.
//
// Transfer function: piecewise-linear control points value -> (r, g, b, alpha), r, g, b and
// alpha in [0, 1], values strictly increasing; clamped to the first and last point outside
// their range. alpha is the opacity of one voxel length of material (voxel coordinates);
// a step of length s composites 1 - (1 - alpha)^s (opacity correction, Max 1995, "Optical
// models for direct volume rendering", IEEE TVCG 1(2)), so the picture does not depend on
// the step for a constant material. Text form: one "value r g b alpha" per line ('#' starts
// a comment); JSON form: {"points": [[value, r, g, b, alpha], ...]}. Presets: "grey" (a
// ramp from transparent black at the volume's minimum to opaque white at its maximum),
// "ct-bone" and "ct-soft-tissue" (Hounsfield units).
//
// Digital rays (kernel of the MIP): the line (O + t D) / den with integer O, D and den > 0 in
// voxel coordinates (voxel (x, y, z) is the cube of side 1 centred on it), clipped to the
// volume's box. The voxels visited are those the line crosses over a positive length, in the
// order of t (a plane of voxel faces containing the line belongs to the voxel above it:
// half-open cubes); consecutive voxels differ by one step on each axis whose face plane is
// crossed at that parameter (two or three at once through an edge or a corner). Computed
// incrementally (Amanatides & Woo 1987, "A fast voxel traversal algorithm for ray tracing")
// with every comparison of crossing parameters exact in 128-bit integers: |O|, |D| and den
// at most 2^40, extents at most 2^20 (InvalidArgument otherwise). O(visited voxels).
//
// Camera: orthographic, looking at the centre of the volume's physical box from the direction
// (cos e cos a, cos e sin a, sin e) (azimuth a around +z, elevation e; x, y, z the volume's
// axes, spacing applied), +z up in the picture, the box's projection framed in the picture.
// Each pixel's ray is the rational ray nearest the exact one with den = 2^20 (within 2^-21
// voxel in each coordinate of its origin and direction).
//   compositing  trilinear samples (the volume extended by its boundary values) at equal
//                steps of at most `step` voxel lengths over the ray's chord, shaded by
//                Lambert's cosine of the trilinear interpolant's gradient (physical
//                coordinates, two-sided, 30% ambient, a headlight; no shading where the
//                gradient vanishes), composited front to back over a black background; the
//                ray stops once its opacity reaches `early_termination` (1 = never)
//   MIP          the maximum physical value over the voxels of the pixel's digital ray, exact
//                (the voxel values as read), coloured by the transfer function's colour
// Cost: O(pixels x samples) (compositing) or O(pixels x visited voxels) (MIP), on `threads`
// threads (0: all cores), bands of rows; the result does not depend on the thread count.
// Memory: the picture and the values image; the volume is read in place (any dtype).
// 2D volumes are rendered as volumes of one slice.
#pragma once

#include <zdg/kernel/images/scalar_volume.hpp>
#include <zdg/kernel/render/picture.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace zdg {

struct TransferPoint {
  double value = 0, r = 0, g = 0, b = 0, alpha = 0;
  friend bool operator==(const TransferPoint&, const TransferPoint&) = default;
};

struct Rgba {
  double r = 0, g = 0, b = 0, a = 0;
};

struct TransferFunction {
  std::vector<TransferPoint> points; ///< values strictly increasing, components in [0, 1]

  /// The interpolated colour and opacity at v (clamped outside the points; NaN: transparent).
  Rgba operator()(double v) const;
  /// InvalidArgument naming `where` and the first bad point (none, a value not finite or not
  /// increasing, a component outside [0, 1]).
  void validate(const std::string& where) const;
};

/// The transfer function of a text or JSON form (see above); `where` (a file name) starts
/// every error: "tf.txt:3: expected 'value r g b alpha'" (IoError, one line).
TransferFunction parse_transfer_function(std::string_view text, const std::string& where);
/// Reads a file (IoError naming it; at most 1 MiB) and parses it.
TransferFunction read_transfer_function(const std::string& path);
/// The preset of that name over the values [lo, hi] of the volume (used by "grey");
/// InvalidArgument listing the names for another.
TransferFunction transfer_function_preset(const std::string& name, double lo, double hi);
/// "grey", "ct-bone", "ct-soft-tissue".
std::vector<std::string> transfer_function_presets();

struct DigitalRay {
  std::array<std::int64_t, 3> origin{};    ///< numerators, voxel coordinates (x, y, z)
  std::array<std::int64_t, 3> direction{}; ///< not all zero
  std::int64_t denominator = 1;
};

/// The voxels (x, y, z) of a box of `extent` (x, y, z) that the ray crosses over a positive
/// length, in the order of the ray (see above); empty when it misses the box.
std::vector<std::array<std::int64_t, 3>>
digital_ray_voxels(const DigitalRay& ray, const std::array<std::int64_t, 3>& extent);

struct VolumeRenderOptions {
  int width = 800, height = 800;
  double azimuth = -60.0, elevation = 30.0; ///< degrees
  bool mip = false;                         ///< maximum intensity projection
  double step = 0.5;                        ///< compositing step, voxel lengths (0.01..8)
  double early_termination = 0.99;          ///< in (0, 1]
  bool shading = true;
  unsigned threads = 0;
};

struct VolumeRendering {
  RgbImage picture;
  /// Per pixel (row-major, row 0 at the top): the MIP value, or the composited opacity; NaN
  /// where the ray misses the volume.
  std::vector<double> values;
  std::int64_t rays = 0;    ///< pixels whose ray meets the volume
  std::int64_t samples = 0; ///< trilinear samples (compositing) or voxels visited (MIP)
};

/// The camera ray of pixel (px, py) (centre of the pixel) for a volume of `extent` (x, y, z)
/// and `spacing` (x, y, z): the ray the renderer uses.
DigitalRay volume_camera_ray(const std::array<std::int64_t, 3>& extent,
                             const std::array<double, 3>& spacing,
                             const VolumeRenderOptions& options, int px, int py);

/// Renders the volume (validated; picture size as check_picture_size; step and
/// early_termination in range: InvalidArgument otherwise).
VolumeRendering render_volume(const ScalarVolume& volume, const TransferFunction& tf,
                              const VolumeRenderOptions& options = {});

} // namespace zdg
