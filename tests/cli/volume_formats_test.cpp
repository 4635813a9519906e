// Every command that reads an image reads every volume format (issue #34): one object written
// as .npy (C and Fortran order), .vol (Versions 2 and 3), .nii, .nii.gz, .pgm (2D) and raw, and
// each command run on each file must give the same result (the JSON without the input block and
// the times; the output files byte for byte). The files are written by zdg's writers, except the
// Fortran-order .npy (written here byte by byte, as numpy writes a transposed array).
#include <zdg/kernel/io/npy_io.hpp>
#include <zdg/kernel/io/volume_io.hpp>

#include "tests/support/cli.hpp"
#include <zdg/kernel/io/vdb_io.hpp>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace zdg {
namespace {

namespace fs = std::filesystem;

// A 3D object (two blocks joined by a bar, with a tunnel) or a 2D one (a ring and a dot), with
// values 0 and 200, C order.
NpyArray object_array(int dim) {
  NpyArray a;
  a.dtype = DType::U8;
  if (dim == 3) {
    a.shape = {6, 7, 9};
    a.bytes.assign(6 * 7 * 9, 0);
    for (int z = 1; z < 5; ++z)
      for (int y = 1; y < 6; ++y)
        for (int x = 1; x < 8; ++x) {
          const bool tunnel = y == 3 && x >= 3 && x <= 5;
          if (!tunnel && !(z == 2 && x == 4))
            a.bytes[static_cast<std::size_t>((z * 7 + y) * 9 + x)] = 200;
        }
  } else {
    a.shape = {9, 11};
    a.bytes.assign(9 * 11, 0);
    for (int y = 1; y < 8; ++y)
      for (int x = 1; x < 8; ++x)
        if (y == 1 || y == 7 || x == 1 || x == 7)
          a.bytes[static_cast<std::size_t>(y * 11 + x)] = 200;
    a.bytes[4 * 11 + 9] = 200;
  }
  return a;
}

// The bytes numpy writes for np.save(path, np.asfortranarray(a)).
std::string fortran_npy_bytes(const NpyArray& a) {
  std::string dict = "{'descr': '|u1', 'fortran_order': True, 'shape': (";
  for (auto e : a.shape) dict += std::to_string(e) + ", ";
  dict += "), }";
  const std::size_t total = 10 + dict.size() + 1;
  dict.append((64 - total % 64) % 64, ' ');
  dict.push_back('\n');
  std::string out = "\x93NUMPY";
  out += '\x01';
  out += '\0';
  out += static_cast<char>(dict.size() & 0xff);
  out += static_cast<char>(dict.size() >> 8);
  out += dict;
  const std::size_t d = a.shape.size();
  std::vector<std::int64_t> idx(d, 0); // Fortran order: first axis fastest
  for (std::size_t i = 0; i < a.bytes.size(); ++i) {
    std::int64_t c = 0;
    for (std::size_t k = 0; k < d; ++k) c = c * a.shape[k] + idx[k];
    out += static_cast<char>(a.bytes[static_cast<std::size_t>(c)]);
    for (std::size_t k = 0; k < d; ++k) {
      if (++idx[k] < a.shape[k]) break;
      idx[k] = 0;
    }
  }
  return out;
}

// The files of one object: format name -> the arguments that name the input.
std::map<std::string, std::string> write_formats(const fs::path& dir, int dim) {
  const NpyArray a = object_array(dim);
  const ScalarVolume v = make_scalar_volume(a);
  std::map<std::string, std::string> in;
  auto put = [&](const std::string& name, const std::string& file, VolumeWriteOptions o = {}) {
    write_volume((dir / file).string(), v, o);
    in[name] = (dir / file).string();
  };
  put("npy", "c.npy");
  std::ofstream((dir / "f.npy").string(), std::ios::binary) << fortran_npy_bytes(a);
  in["npy-fortran"] = (dir / "f.npy").string();
  put("nii", "n.nii");
  put("nii.gz", "n.nii.gz");
  if (dim == 3) {
    put("vol-v3", "v3.vol");
    VolumeWriteOptions v2;
    v2.vol_version = 2;
    put("vol-v2", "v2.vol", v2);
    if (vdb_supported()) put("vdb", "v.vdb");
  } else {
    put("pgm", "p.pgm");
  }
  put("raw", "r.raw");
  in["raw"] +=
      dim == 3 ? " --raw-shape 6,7,9 --raw-dtype uint8" : " --raw-shape 9,11 --raw-dtype uint8";
  return in;
}

// The JSON of a run without what depends on the input file or the clock.
nlohmann::json scrub(nlohmann::json j) {
  if (j.is_object()) {
    nlohmann::json out = nlohmann::json::object();
    for (auto& [k, v] : j.items()) {
      if (k == "input" || k == "output" || k == "path" || k == "format" || k == "stages" ||
          k.find("seconds") != std::string::npos)
        continue;
      out[k] = scrub(v);
    }
    return out;
  }
  if (j.is_array()) {
    for (auto& e : j) e = scrub(e);
  }
  return j;
}

struct Command {
  std::string args;   // {in} the input arguments, {out} an output file
  std::string output; // the output's name ("" when the command writes none)
};

void check_commands(int dim, const std::vector<Command>& commands) {
  const auto dir = test::scratch_dir("formats");
  const auto inputs = write_formats(dir, dim);
  for (const auto& c : commands) {
    std::string ref_json, ref_file, ref_format;
    for (const auto& [format, in] : inputs) {
      std::string args = c.args;
      args.replace(args.find("{in}"), 4, in);
      const fs::path out = dir / (format + "-" + c.output);
      if (!c.output.empty()) {
        fs::remove(out);
        args.replace(args.find("{out}"), 5, out.string());
      }
      const auto r = test::run_zdg(args + " --json");
      ASSERT_EQ(r.status, 0) << "zdg " << args << " (" << format << "): " << r.err;
      const std::string j = scrub(nlohmann::json::parse(r.out)).dump();
      const std::string file = c.output.empty() ? "" : test::read_file(out);
      if (ref_format.empty()) {
        ref_json = j;
        ref_file = file;
        ref_format = format;
        continue;
      }
      EXPECT_EQ(j, ref_json) << "zdg " << c.args << ": " << format << " differs from "
                             << ref_format;
      EXPECT_TRUE(file == ref_file)
          << "zdg " << c.args << ": the output of " << format << " differs from " << ref_format;
    }
  }
  fs::remove_all(dir);
}

TEST(VolumeFormats, EveryCommandReadsEvery3dFormat) {
  check_commands(3, {{"surface {in}", ""},
                     {"convert {in} {out}", "conv.npy"},
                     {"transform dt {in} -o {out}", "dt.npy"},
                     {"transform dt {in} --threshold 100 -o {out}", "dt-t.npy"},
                     {"transform voronoi {in} -o {out}", "vor.npy"},
                     {"transform rma {in} -o {out}", "rma.npy"},
                     {"transform rdt {in} -o {out}", "rdt.npy"},
                     {"transform power {in} -o {out}", "pow.npy"},
                     {"topology betti {in}", ""},
                     {"topology components {in} -o {out}", "cc.npy"},
                     {"topology simple {in} --invert -o {out}", "simple.npy"}});
}

TEST(VolumeFormats, EveryCommandReadsEvery2dFormat) {
  check_commands(2, {{"contour {in}", ""},
                     {"convert {in} {out}", "conv.npy"},
                     {"transform dt {in} -o {out}", "dt.npy"},
                     {"transform voronoi {in} --label 200 -o {out}", "vor.npy"},
                     {"topology betti {in}", ""},
                     {"topology skeleton {in} -o {out}", "sk.npy"}});
}

// The Fortran-order file is the transposed layout of the same array: read_volume returns the
// C-order bytes of the C file.
TEST(VolumeFormats, FortranOrderNpyIsTheSameArray) {
  const auto dir = test::scratch_dir("formats");
  const auto inputs = write_formats(dir, 3);
  EXPECT_EQ(read_volume(inputs.at("npy-fortran")).array.bytes, object_array(3).bytes);
  EXPECT_EQ(read_integer_image(inputs.at("npy-fortran")).values(),
            read_integer_image(inputs.at("vol-v3")).values());
  fs::remove_all(dir);
}

} // namespace
} // namespace zdg
