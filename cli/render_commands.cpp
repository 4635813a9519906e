// zdg render volume: a picture of a scalar volume by direct volume rendering
// (kernel/render/volume_render.hpp): front-to-back compositing through a transfer function,
// or the maximum intensity projection over exact digital rays.
//
//   zdg render volume INPUT -o OUT.png [--tf TF] [--view AZ,EL] [--mip] [--png-size WxH]
//                     [--step S] [--early-termination A] [--no-shading] [--threads T]
//                     [--raw-shape ...] [--spacing ...] [--downsample F] [--force] [--json]
//
// TF: a preset (grey, the default: transparent black at the volume's minimum to opaque white
// at its maximum; ct-bone, ct-soft-tissue in Hounsfield units) or a file of control points
// ("value r g b alpha" per line, or {"points": [[value, r, g, b, alpha], ...]}). Bad input
// (a TF file that does not parse, a step or an opacity out of range, a view that is not two
// numbers, an existing output without --force): one line, exit 2, nothing written.
#include <zdg/arith/error.hpp>
#include <zdg/cli/commands.hpp>
#include <zdg/cli/volume_input.hpp>
#include <zdg/kernel/io/output_files.hpp>
#include <zdg/kernel/render/volume_render.hpp>

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <tuple>

namespace zdg::cli {

namespace {

struct RenderVolumeArgs {
  VolumeInputArgs in;
  std::string output, tf = "grey", view, size;
  double step = 0.5, early = 0.99;
  bool mip = false, no_shading = false, force = false, json = false;
  unsigned threads = 0;
};

void run_render_volume(const RenderVolumeArgs& a) {
  const auto t0 = std::chrono::steady_clock::now();
  // Options and names first: nothing is read when one is wrong.
  VolumeRenderOptions o;
  o.mip = a.mip;
  o.step = a.step;
  o.early_termination = a.early;
  o.shading = !a.no_shading;
  o.threads = a.threads;
  if (!a.view.empty()) std::tie(o.azimuth, o.elevation) = parse_view(a.view);
  if (!a.size.empty()) std::tie(o.width, o.height) = parse_picture_size(a.size);
  o.validate();
  const auto presets = transfer_function_presets();
  const bool preset = std::find(presets.begin(), presets.end(), a.tf) != presets.end();
  TransferFunction tf;
  if (!preset) {
    std::error_code ec;
    if (!std::filesystem::exists(a.tf, ec)) {
      std::string names;
      for (const auto& n : presets) names += (names.empty() ? "" : ", ") + n;
      throw InvalidArgument("--tf '" + a.tf + "': neither a file nor a preset (" + names + ")");
    }
    tf = read_transfer_function(a.tf);
  }
  if (lower_extension(a.output) != ".png")
    throw IoError(a.output + ": the picture is a .png file (got '" + lower_extension(a.output) +
                  "')");
  check_not_input(a.in.path, a.output);
  OutputSet out(a.force ? Existing::replace : Existing::refuse);
  const auto staging = out.add(a.output); // checked before the input is read

  const LoadedVolume in = load_volume(a.in, 0, !a.json);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::int64_t i = 0; i < in.volume.count(); ++i) {
    const double v = in.volume.value(i);
    if (std::isnan(v)) continue;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  if (preset) {
    if (!(lo <= hi)) throw InvalidArgument(a.in.path + ": no value that is a number");
    tf = transfer_function_preset(a.tf, lo, hi);
  }
  const auto t1 = std::chrono::steady_clock::now();
  const VolumeRendering r = render_volume(in.volume, tf, o);
  const double render_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  write_png(staging.string(), r.picture);
  out.commit();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (a.json) {
    nlohmann::json tfj = nlohmann::json::array();
    for (const auto& p : tf.points) tfj.push_back({p.value, p.r, p.g, p.b, p.alpha});
    print_json(
        {{"input", in.json},
         {"output", a.output},
         {"mode", o.mip ? "mip" : "composite"},
         {"view", {o.azimuth, o.elevation}},
         {"size", {o.width, o.height}},
         {"transfer_function", {{"name", a.tf}, {"points", tfj}}},
         {"values", {lo, hi}},
         {"rays", r.rays},
         {"samples", r.samples},
         {"seconds", {{"read", in.read_seconds}, {"render", render_seconds}, {"total", seconds}}}});
  } else {
    fmt::print("{} -> {}: {} of {} ({} x {} pixels, view {},{}), {} rays, {} {}\n", a.in.path,
               a.output, o.mip ? "maximum intensity projection" : "volume rendering",
               describe_volume(in.volume), o.width, o.height, o.azimuth, o.elevation, r.rays,
               r.samples, o.mip ? "voxels visited" : "samples");
  }
}

} // namespace

void add_render_commands(CLI::App& app, Context& /*ctx*/) {
  auto* render = app.add_subcommand("render", "pictures of volumes (direct volume rendering)");
  render->require_subcommand(1);
  auto a = std::make_shared<RenderVolumeArgs>();
  auto* cmd = render->add_subcommand(
      "volume", "direct volume rendering of a scalar volume (front-to-back compositing through a "
                "transfer function, or maximum intensity projection over exact digital rays)");
  add_volume_input_options(*cmd, a->in, VolumeOptionSet{false, true});
  cmd->add_option("-o,--output", a->output, "the picture (.png)")->required();
  cmd->add_option("--tf", a->tf,
                  "transfer function: a preset (grey, the default; ct-bone; ct-soft-tissue) or a "
                  "file of 'value r g b alpha' lines or {\"points\": [[v, r, g, b, a], ...]}");
  cmd->add_option("--view", a->view, "azimuth,elevation in degrees (default -60,30)");
  cmd->add_flag("--mip", a->mip, "maximum intensity projection instead of compositing");
  cmd->add_option("--png-size", a->size, "picture size WIDTHxHEIGHT (default 800x800)");
  cmd->add_option("--step", a->step, "compositing step in voxel lengths (default 0.5)");
  cmd->add_option("--early-termination", a->early,
                  "stop a ray once its opacity reaches this (default 0.99; 1 = never)");
  cmd->add_flag("--no-shading", a->no_shading, "no gradient shading");
  cmd->add_option("--threads", a->threads, "threads (default: all cores)");
  cmd->add_flag("--force", a->force, "replace an existing output");
  cmd->add_flag("--json", a->json, "print a JSON summary");
  cmd->callback([a] { run_render_volume(*a); });
}

} // namespace zdg::cli
