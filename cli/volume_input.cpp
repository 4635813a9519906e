// The shared input options of the image commands (see volume_input.hpp).
#include <zdg/cli/volume_input.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/cli/commands.hpp>
#include <zdg/kernel/io/raw_io.hpp>

#include <fmt/core.h>

#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <unistd.h>

namespace zdg::cli {

namespace {

std::string number_text(double x) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x); // shortest text that reads back to x
  return std::string(buf, r.ptr);
}

// The option that chose the rule, as the user wrote it (for messages).
std::string selection_words(const VolumeInputArgs& a) {
  std::string s;
  if (!a.threshold.empty()) s = "--threshold " + a.threshold;
  if (!a.range.empty()) s = "--range " + a.range;
  if (!a.label.empty()) s = "--label " + a.label;
  if (s.empty()) s = "the default selection (value != 0)";
  if (a.invert) s += " --invert";
  return s;
}

bool show_progress(bool progress) {
  return progress && ::isatty(2) == 1;
}

// A 3D volume of one slice, as the 2D image it is.
void drop_leading_axis(ScalarVolume& v) {
  v.array.shape.erase(v.array.shape.begin());
  v.lower.erase(v.lower.begin());
  v.spacing.erase(v.spacing.begin());
  v.origin.erase(v.origin.begin());
}

} // namespace

void add_volume_input_options(CLI::App& cmd, VolumeInputArgs& args, VolumeOptionSet which) {
  cmd.add_option("INPUT", args.path,
                 "input image: .vol (Version 2 or 3), .nii, .nii.gz, .npy (C or Fortran order), "
                 ".pgm, or raw (with --raw-shape and --raw-dtype)")
      ->required();
  cmd.add_option("--raw-shape", args.raw_shape,
                 "shape of a raw input, Z,Y,X (3D) or Y,X (2D), x fastest");
  cmd.add_option("--raw-dtype", args.raw_dtype,
                 "value type of a raw input (little-endian): bool, uint8, int8, uint16, int16, "
                 "uint32, int32, uint64, int64, float32, float64");
  if (which.selection) {
    auto* t = cmd.add_option("--threshold", args.threshold, "object = voxels with value >= T");
    auto* r = cmd.add_option("--range", args.range, "object = voxels with LO <= value <= HI");
    auto* l = cmd.add_option("--label", args.label, "object = voxels with value == L");
    t->excludes(r)->excludes(l);
    r->excludes(l);
    cmd.add_flag("--invert", args.invert, "object = the complement of the selection");
  }
  args.physical = which.spacing;
  if (which.spacing) {
    cmd.add_option("--spacing", args.spacing,
                   "physical voxel size SZ,SY,SX (2D: SY,SX), overriding the file's (NIfTI "
                   "pixdim; 1 for the other formats)");
  }
}

RawLayout raw_layout(const VolumeInputArgs& a) {
  RawLayout raw;
  if (a.raw_shape.empty() && a.raw_dtype.empty()) return raw;
  if (a.raw_shape.empty() || a.raw_dtype.empty())
    throw InvalidArgument("a raw input needs both --raw-shape and --raw-dtype");
  raw.shape = parse_raw_shape(a.raw_shape);
  try {
    raw.dtype = dtype_from_name(a.raw_dtype);
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(std::string("--raw-dtype: ") + e.what());
  }
  return raw;
}

ObjectSelection object_selection(const VolumeInputArgs& a) {
  ObjectSelection s;
  s.invert = a.invert;
  if (!a.threshold.empty()) {
    s.rule = ObjectSelection::Rule::at_least;
    s.low = parse_number(a.threshold, "--threshold");
  } else if (!a.label.empty()) {
    s.rule = ObjectSelection::Rule::equal;
    s.low = parse_number(a.label, "--label");
  } else if (!a.range.empty()) {
    // The separator is the first ':' (numbers never contain one).
    const auto colon = a.range.find(':');
    if (colon == std::string::npos) throw InvalidArgument("--range '" + a.range + "' is not LO:HI");
    s.rule = ObjectSelection::Rule::range;
    s.low = parse_number(a.range.substr(0, colon), "--range LO");
    s.high = parse_number(a.range.substr(colon + 1), "--range HI");
    if (s.low > s.high) throw InvalidArgument("--range '" + a.range + "' is empty (LO > HI)");
  }
  return s;
}

std::vector<double> parse_spacing(const std::string& text, int dim) {
  std::vector<double> out;
  std::size_t pos = 0;
  while (true) {
    const auto comma = text.find(',', pos);
    const std::string part =
        text.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos);
    const double v = parse_number(part, "--spacing");
    if (v <= 0.0) throw InvalidArgument("--spacing '" + text + "': " + part + " is not positive");
    out.push_back(v);
    if (comma == std::string::npos) break;
    pos = comma + 1;
  }
  if (static_cast<int>(out.size()) != dim)
    throw InvalidArgument("--spacing '" + text + "' has " + std::to_string(out.size()) +
                          " entries for a " + std::to_string(dim) + "D image (" +
                          (dim == 3 ? "SZ,SY,SX" : "SY,SX") + ")");
  return out;
}

bool has_selection(const VolumeInputArgs& a) {
  return !a.threshold.empty() || !a.range.empty() || !a.label.empty() || a.invert;
}

LoadedVolume load_volume(const VolumeInputArgs& args, int dim, bool progress) {
  using clock = std::chrono::steady_clock;
  if (dim != 0 && dim != 2 && dim != 3) throw InvalidArgument("load_volume: dimension 2 or 3");
  LoadedVolume lv;
  const RawLayout raw = raw_layout(args);
  if (show_progress(progress)) fmt::print(stderr, "zdg: reading {} ...\n", args.path);
  const auto t0 = clock::now();
  lv.format = raw.given() ? VolumeFormat::raw : volume_format_of(args.path);
  lv.volume = read_volume(args.path, raw);
  lv.read_seconds = std::chrono::duration<double>(clock::now() - t0).count();
  ScalarVolume& v = lv.volume;
  if (dim == 2 && v.dim() == 3 && v.array.shape[0] == 1) drop_leading_axis(v);
  if (dim != 0 && v.dim() != dim) {
    throw InvalidArgument(args.path + ": a " + std::to_string(v.dim()) + "D image " +
                          describe_volume(v) + " where a " + std::to_string(dim) +
                          "D one is needed");
  }
  if (!args.spacing.empty()) {
    v.spacing = parse_spacing(args.spacing, v.dim());
  } else if (args.physical) {
    for (int k = 0; k < v.dim(); ++k) {
      const double s = v.spacing[static_cast<std::size_t>(k)];
      if (!std::isfinite(s) || s <= 0.0)
        throw InvalidArgument(args.path + ": spacing " + number_text(s) + " along axis " +
                              std::to_string(k) + " in the file is not positive; give --spacing");
    }
  }
  if (show_progress(progress))
    fmt::print(stderr, "zdg: {} read in {:.2f} s\n", describe_volume(v), lv.read_seconds);
  std::vector<std::string> shape, lower;
  for (auto s : v.array.shape) shape.push_back(std::to_string(s));
  for (auto s : v.lower) lower.push_back(std::to_string(s));
  lv.json = {{"path", args.path},  {"format", volume_format_name(lv.format)},
             {"shape", shape},     {"dtype", dtype_name(v.array.dtype)},
             {"lower", lower},     {"spacing", v.spacing},
             {"origin", v.origin}, {"scaling", {{"slope", v.slope}, {"inter", v.inter}}}};
  return lv;
}

LoadedObject load_object(const VolumeInputArgs& args, int dim, unsigned threads, bool progress) {
  using clock = std::chrono::steady_clock;
  const ObjectSelection selection = object_selection(args); // option errors before reading
  LoadedVolume lv = load_volume(args, dim, progress);
  LoadedObject obj;
  obj.volume = std::move(lv.volume);
  obj.format = lv.format;
  obj.read_seconds = lv.read_seconds;
  if (show_progress(progress)) fmt::print(stderr, "zdg: selecting {} ...\n", selection.describe());
  const auto t1 = clock::now();
  SelectedObject sel = select_object(obj.volume, selection, threads);
  obj.select_seconds = std::chrono::duration<double>(clock::now() - t1).count();
  obj.selection = selection;
  obj.mask = std::move(sel.mask);
  obj.voxels = sel.voxels;
  obj.min_value = sel.min_value;
  obj.max_value = sel.max_value;
  if (obj.voxels == 0) {
    std::string values = "all NaN";
    if (!std::isnan(sel.min_value)) {
      values = "from ";
      values += number_text(sel.min_value);
      values += " to ";
      values += number_text(sel.max_value);
    }
    throw InvalidArgument(args.path + ": " + selection_words(args) + " selects no voxel (values " +
                          values + ")");
  }
  if (show_progress(progress))
    fmt::print(stderr, "zdg: object of {} voxels ({:.2f} s)\n", obj.voxels, obj.select_seconds);
  obj.json = std::move(lv.json);
  obj.json["selection"] = selection.describe();
  obj.json["voxels"] = std::to_string(obj.voxels);
  obj.json["values"] = {obj.min_value, obj.max_value};
  return obj;
}

} // namespace zdg::cli
