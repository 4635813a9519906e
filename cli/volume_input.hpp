// The input of the commands that work on a user's image (zdg surface, zdg contour,
// zdg topology): one file read as a scalar volume, its object selected as a binary mask.
//
//   VolumeInputArgs in;
//   add_volume_input_options(*cmd, in);               // INPUT + the options below
//   ...
//   LoadedObject obj = load_object(in, 3, threads, !quiet);   // in the command's callback
//                                                 // (load_volume: the values, no selection)
//   obj.mask        Image<uint8_t>, 1 = object (the volume's lattice domain)
//   obj.volume      the values as read (spacing/origin for the physical embedding; the
//                   grey values for marching cubes at obj.selection.low)
//   obj.json        the "input" block of --json
//
// Options added to the subcommand (all optional but INPUT):
//   INPUT                  .vol (v2/v3), .nii, .nii.gz, .npy, .pgm (2D), or raw with:
//   --raw-shape Z,Y,X      (or Y,X) and --raw-dtype uint8|int8|uint16|...|float32|float64
//   --threshold T          object = value >= T
//   --range LO:HI          object = LO <= value <= HI
//   --label L              object = value == L            (default: value != 0)
//   --invert               object = the complement
//   --spacing SZ,SY,SX     physical voxel size (2D: SY,SX), overriding the file's
//
// Errors (zdg::Error, so one line and exit 2): every message names the file: unreadable or
// malformed file, a dimension other than the command's (a 3D volume with one slice is taken
// as 2D), a spacing that is not positive and finite, and a selection of no voxel ("INPUT:
// --threshold 300 selects no voxel (values from 0 to 255)").
#pragma once

#include <zdg/kernel/images/image.hpp>
#include <zdg/kernel/images/object_selection.hpp>
#include <zdg/kernel/images/scalar_volume.hpp>
#include <zdg/kernel/io/volume_io.hpp>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>

namespace zdg::cli {

struct VolumeInputArgs {
  std::string path;
  std::string raw_shape, raw_dtype;
  std::string threshold, range, label;
  bool invert = false;
  std::string spacing;
  bool physical = true; ///< the command uses the spacing (false: a file's spacing is not checked)
};

/// Which options besides INPUT and the raw layout (--raw-shape, --raw-dtype) a command takes.
struct VolumeOptionSet {
  bool selection = true; ///< --threshold, --range, --label, --invert
  bool spacing = true;   ///< --spacing
};

/// Adds INPUT (a required positional), the raw options and those of `which` to `cmd`; they are
/// stored into `args` (which must outlive the parse). Every command that reads an image calls
/// it, so that every command reads every format with the same options and errors.
void add_volume_input_options(CLI::App& cmd, VolumeInputArgs& args, VolumeOptionSet which = {});

/// The raw layout of the arguments (empty when neither --raw-shape nor --raw-dtype is given).
RawLayout raw_layout(const VolumeInputArgs& args);

/// The selection rule of the arguments (nonzero when no option is given).
ObjectSelection object_selection(const VolumeInputArgs& args);

/// Parses "--spacing" text: `dim` positive finite numbers separated by commas.
std::vector<double> parse_spacing(const std::string& text, int dim);

/// True when --threshold, --range, --label or --invert is given.
bool has_selection(const VolumeInputArgs& args);

struct LoadedVolume {
  ScalarVolume volume; ///< as read; spacing from --spacing when given
  VolumeFormat format = VolumeFormat::vol;
  double read_seconds = 0;
  nlohmann::json json; ///< {"path","format","shape","dtype","lower","spacing","origin",
                       ///<  "scaling":{"slope","inter"}} (integers as strings)
};

/// Reads args.path and checks it is `dim`-dimensional (2 or 3; 0 accepts both; a 3D volume
/// of one slice is taken as 2D when dim = 2), applies --spacing (and checks the file's
/// spacing is positive when it is not given). With `progress`, says so on stderr when stderr
/// is a terminal.
LoadedVolume load_volume(const VolumeInputArgs& args, int dim, bool progress = false);

struct LoadedObject {
  ScalarVolume volume; ///< as read; spacing from --spacing when given
  VolumeFormat format = VolumeFormat::vol;
  ObjectSelection selection;           ///< the rule applied
  Image<std::uint8_t> mask;            ///< 1 on the object
  std::int64_t voxels = 0;             ///< object voxels
  double min_value = 0, max_value = 0; ///< range of the physical values
  double read_seconds = 0, select_seconds = 0;
  nlohmann::json json; ///< load_volume's block plus "selection" (text), "voxels" (string) and
                       ///< "values": [min, max]
};

/// load_volume, then the object under the selection options (on `threads` threads, 0 = all).
/// A selection of no voxel is an InvalidArgument naming the file, the option and the range of
/// the values.
LoadedObject load_object(const VolumeInputArgs& args, int dim, unsigned threads = 0,
                         bool progress = false);

} // namespace zdg::cli
