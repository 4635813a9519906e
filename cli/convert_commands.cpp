// zdg convert IN OUT: volumes between .vol (Version 2 or 3), .nii, .nii.gz, .npy, .pgm (2D)
// and raw files (kernel/io/volume_io.hpp says what each format keeps); with --threshold,
// --range, --label or --invert, the object's 0/1 mask (uint8) instead of the values. The
// output is checked before the input is read and written atomically (kernel/io/output_files.hpp).
#include <zdg/arith/error.hpp>
#include <zdg/cli/commands.hpp>
#include <zdg/cli/volume_input.hpp>
#include <zdg/kernel/io/output_files.hpp>
#include <zdg/kernel/io/volume_io.hpp>

#include <fmt/core.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <string>

namespace zdg::cli {

namespace {

struct ConvertArgs {
  VolumeInputArgs in;
  std::string output;
  int vol_version = 3;
  unsigned threads = 0;
  bool force = false, json = false, quiet = false;
};

void run_convert(const ConvertArgs& a) {
  namespace fs = std::filesystem;
  using clock = std::chrono::steady_clock;
  check_not_input(a.in.path, a.output);
  std::error_code ec;
  const VolumeFormat out_format = volume_format_of(a.output);
  OutputSet out(a.force ? Existing::replace : Existing::refuse);
  const fs::path staging = out.add(a.output); // checked before the input is read
  const bool mask = has_selection(a.in);
  // PGM holds 2D images: a 3D volume of one slice is read as the 2D image it is.
  const int dim = out_format == VolumeFormat::pgm ? 2 : 0;
  ScalarVolume v;
  nlohmann::json input;
  double read_s = 0, select_s = 0;
  if (mask) {
    LoadedObject obj = load_object(a.in, dim, a.threads, !a.quiet);
    v = make_scalar_volume(obj.mask);
    v.spacing = obj.volume.spacing;
    v.origin = obj.volume.origin;
    input = std::move(obj.json);
    read_s = obj.read_seconds;
    select_s = obj.select_seconds;
  } else {
    LoadedVolume lv = load_volume(a.in, dim, !a.quiet);
    v = std::move(lv.volume);
    input = std::move(lv.json);
    read_s = lv.read_seconds;
  }
  const auto t1 = clock::now();
  VolumeWriteOptions opt;
  opt.vol_version = a.vol_version;
  opt.format = out_format;
  try {
    write_volume(staging.string(), v, opt);
  } catch (const Error& e) {
    // Messages name the staging file; the user knows the output by its own name.
    std::string what = e.what();
    const std::string s = staging.string();
    for (auto p = what.find(s); p != std::string::npos; p = what.find(s))
      what.replace(p, s.size(), a.output);
    throw IoError(what);
  }
  out.commit();
  const double write_s = std::chrono::duration<double>(clock::now() - t1).count();
  const auto bytes = fs::file_size(a.output, ec);
  if (a.json) {
    nlohmann::json j = {{"input", input},
                        {"output",
                         {{"path", a.output},
                          {"format", volume_format_name(out_format)},
                          {"content", mask ? "mask" : "values"},
                          {"bytes", std::to_string(bytes)}}},
                        {"seconds", {{"read", read_s}, {"select", select_s}, {"write", write_s}}}};
    if (out_format == VolumeFormat::vol) j["output"]["vol_version"] = a.vol_version;
    print_json(j);
  } else {
    fmt::print("{} -> {} ({}{}, {} bytes)\n", a.in.path, a.output, volume_format_name(out_format),
               mask ? ", object mask" : "", bytes);
  }
}

} // namespace

void add_convert_commands(CLI::App& app, Context& /*ctx*/) {
  auto args = std::make_shared<ConvertArgs>();
  auto* cmd = app.add_subcommand(
      "convert", "convert a volume between .vol (v2/v3), .nii, .nii.gz, .npy, .pgm and raw; "
                 "with a selection option, write the object's 0/1 mask instead of the values");
  add_volume_input_options(*cmd, args->in);
  cmd->add_option("OUT", args->output,
                  "output volume: .vol, .nii, .nii.gz, .npy, .pgm (2D) or .raw")
      ->required();
  cmd->add_option("--vol-version", args->vol_version,
                  "Version of a .vol output: 3 (zlib, DGtal's default) or 2 (uncompressed)")
      ->check(CLI::IsMember({2, 3}));
  cmd->add_option("--threads", args->threads, "threads for the selection (0 = all cores)");
  cmd->add_flag("--force", args->force, "replace an existing output");
  cmd->add_flag("--json", args->json, "print a JSON summary");
  cmd->add_flag("--quiet", args->quiet, "no progress on stderr");
  cmd->callback([args] { run_convert(*args); });
}

} // namespace zdg::cli
