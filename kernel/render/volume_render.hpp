// Direct volume rendering of a scalar volume: front-to-back compositing through a transfer
// function, and maximum intensity projection (MIP) over exact digital rays.
//
// Transfer function: piecewise-linear points value -> (r, g, b, alpha) in [0, 1], values
// strictly increasing, clamped outside them; alpha is the opacity of one voxel length, a step
// of length s composites 1 - (1 - alpha)^s (Max 1995, "Optical models for direct volume
// rendering", IEEE TVCG 1(2)). Forms: "value r g b alpha" lines ('#' comments), or
// {"points": [[value, r, g, b, alpha], ...]}.
//
// Digital ray: kernel/images/digital_ray.hpp (the voxels a rational line crosses over a
// positive length, exact). O(visited voxels).
//
// Camera: orthographic, render_mesh.hpp's view convention (azimuth around +z, elevation, +z
// up), the box's projection framed; each pixel's ray rounded to den = 2^20.
//   compositing  trilinear samples (boundary values extended) at equal steps <= `step`, Lambert
//                shading by the interpolant's gradient (30% ambient, headlight; none where the
//                gradient vanishes), over black; a ray stops at opacity `early_termination`
//   MIP          the exact maximum over the pixel's digital ray, coloured by the function
// Cost: O(pixels x samples) or O(pixels x visited voxels) on `threads` threads (0: all
// cores); the result does not depend on the thread count. The volume is read in place.
// 2D volumes are volumes of one slice.
#pragma once

#include <zdg/kernel/images/digital_ray.hpp>
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
/// The preset of that name over the values [lo, hi] of the volume ("grey": transparent black
/// at lo to opaque white at hi; "ct-bone", "ct-soft-tissue": Hounsfield units);
/// InvalidArgument listing the names for another.
TransferFunction transfer_function_preset(const std::string& name, double lo, double hi);
/// "grey", "ct-bone", "ct-soft-tissue".
std::vector<std::string> transfer_function_presets();

struct VolumeRenderOptions {
  int width = 800, height = 800;
  double azimuth = -60.0, elevation = 30.0; ///< degrees
  bool mip = false;                         ///< maximum intensity projection
  double step = 0.5;                        ///< compositing step, voxel lengths (0.01..8)
  double early_termination = 0.99;          ///< in (0, 1]
  bool shading = true;
  unsigned threads = 0;

  /// InvalidArgument for a picture size check_picture_size refuses, an angle that is not
  /// finite, a step outside [0.01, 8] or an early termination outside (0, 1].
  void validate() const;
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

/// Renders the volume (the volume, the function and the options validated first).
VolumeRendering render_volume(const ScalarVolume& volume, const TransferFunction& tf,
                              const VolumeRenderOptions& options = {});

} // namespace zdg
