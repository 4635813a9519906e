// The command line's contract with a hostile user (issue #18), table-driven: for every class
// of bad input, `zdg ARGS` exits with status 2, prints exactly one line "zdg: ..." on stderr
// (naming what was wrong), creates no file, and leaves every existing file (outputs included,
// read-only or not) as it was. A second table checks that numbers are decimal (the answers of
// the first reproducer).
//
// Adding a row (every engineer who adds a command or an input format should): append a
// BadInput to bad_inputs() below:
//   {"what is wrong (the class of input)",
//    "the arguments; {dir} is the scratch folder of the row ({rel}: the same, relative to the
//     working folder)",
//    {{"input.txt", "bytes of an input file the row creates first"}, ...},
//    {"out.npy", ...},   // outputs that already exist (content "keep", mode 0444): untouched
//    "a piece of the expected error line"}
// Files may be in sub-folders ("out/results.csv"); a name ending in '/' makes a folder.
#include "tests/support/cli.hpp"
#include "tests/support/corrupt_zlib.hpp"
#include "tests/support/nifti_bytes.hpp"
#include "tests/support/paths.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <fcntl.h>
#include <linux/fs.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;

struct BadInput {
  std::string what;                         // the class of bad input
  std::string args;                         // "{dir}" stands for the scratch folder
  std::map<std::string, std::string> files; // created before the run ("name/" = a folder)
  std::vector<std::string> existing; // pre-existing outputs, mode 0444, must stay as they are
  std::string message;               // must appear in the error line
};

std::string npy(const std::string& dict, const std::string& data) {
  std::string h = dict;
  const std::size_t total = 10 + h.size() + 1;
  h.append((64 - total % 64) % 64, ' ');
  h.push_back('\n');
  std::string out = "\x93NUMPY";
  out += '\x01';
  out += '\0';
  out += static_cast<char>(h.size() & 0xff);
  out += static_cast<char>(h.size() >> 8);
  return out + h + data;
}

// A valid 4x4 uint8 image with background (a transform input).
std::string small_npy() {
  return npy("{'descr': '|u1', 'fortran_order': False, 'shape': (4, 4), }",
             std::string("\0\0\0\0\0\1\1\0\0\1\1\0\0\0\0\0", 16));
}

// A valid 6x6x6 uint8 volume holding a 4x4x4 cube (a surface and topology input).
std::string cube_npy() {
  std::string v(6 * 6 * 6, '\0');
  for (int z = 1; z < 5; ++z) {
    for (int y = 1; y < 5; ++y) {
      for (int x = 1; x < 5; ++x) v[static_cast<std::size_t>((z * 6 + y) * 6 + x)] = '\1';
    }
  }
  return npy("{'descr': '|u1', 'fortran_order': False, 'shape': (6, 6, 6), }", v);
}

// Files whose header promises more than they hold.
const char* const kCutPgm = "P5\n4 4\n255\nab";
// A valid ascii PLY triangle with one face field k (its last line is "3 0 1 2 0.5\n").
const char* const kPlyTriangle =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
    "property float k\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 0.5\n";
// Three triangles on the edge (0, 1): not a manifold.
const char* const kPlyFin =
    "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\n"
    "property float z\nelement face 3\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n";
// A PLY of three vertices and no face.
const char* const kPlyNoFace =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0\n1 0 0\n0 1 0\n";
const char* const kCutVol = "X: 4\nY: 4\nZ: 4\nVersion: 2\n.\nab";

// An ascii PLY mesh with the given vertex and face lines (x y z as double).
std::string ply_mesh(const std::string& vertices, const std::string& faces, int nv, int nf) {
  return "ply\nformat ascii 1.0\nelement vertex " + std::to_string(nv) +
         "\nproperty double x\nproperty double y\nproperty double z\nelement face " +
         std::to_string(nf) + "\nproperty list uchar int vertex_indices\nend_header\n" + vertices +
         faces;
}

std::vector<BadInput> bad_inputs() {
  const std::string converge = "converge --shape ball:5 --estimator gauss-area --h 1:0.5:3 ";
  return {
      // --- 1. numbers: decimal only, one parser -------------------------------------------
      {"hexadecimal fraction", "cf 0x10/3", {}, {}, "'0x10/3'"},
      {"exponent in an integer", "floor-sum 1e3 3 1 0", {}, {}, "N: '1e3' is not an integer"},
      {"zero denominator", "cf 010/000", {}, {}, "zero denominator"},
      {"hexadecimal dss argument", "dss subsegment 3 7 0x1 0 3", {}, {}, "MU = '0x1'"},
      {"hexadecimal hull radius", "hull disc 0 0 0x5", {}, {}, "R: '0x5'"},
      {"jet degree out of range",
       "converge --shape sphere9 --estimator jet-k1:degree=7 --h 1:0.5:2 -o {dir}/o",
       {},
       {},
       "parameter degree = '7' must be in (0, 4]"},
      {"jet degree not an integer",
       "converge --shape sphere9 --estimator jet-k1:degree=2.5 --h 1:0.5:2 -o {dir}/o",
       {},
       {},
       "the degree must be an integer from 1 to 4"},
      {"heat-kernel time exponent outside (0, 1)",
       "converge --shape sphere9 --estimator lb-heat:alpha=1 --h 1:0.5:2 -o {dir}/o",
       {},
       {},
       "parameter alpha = '1' must be in (0, 1)"},
      {"test function that does not parse",
       "converge --shape sphere9 --estimator lb-heat --function x^^2 --h 1:0.5:2 -o {dir}/o",
       {},
       {},
       "function 'x^^2': unexpected '^' at position 3"},
      {"test function not finite on the surface",
       "converge --shape sphere9 --estimator 'lb-cotan:u=log(x)' --h 1 -o {dir}/o --no-plot",
       {},
       {},
       "is not finite at"},
      {"lb-spectrum: unknown Laplacian",
       "converge --shape sphere1 --estimator lb-spectrum:operator=naive --h 0.5 -o {dir}/o",
       {},
       {},
       "unknown Laplacian 'naive' (known: cotan, cotan-mc, heat)"},
      {"lb-spectrum: a shape other than a sphere",
       "converge --shape ellipsoid --estimator lb-spectrum --h 2 -o {dir}/o --no-plot",
       {},
       {},
       "'ellipsoid' is not a sphere"},
      {"converge: grid steps and sample counts together",
       "converge --shape sphere1 --estimator recon-betti --h 1 --samples 100 -o {dir}/o",
       {},
       {},
       "--h and --samples given together"},
      {"converge: a sample count that is not a positive integer",
       "converge --shape sphere1 --estimator recon-betti --samples 100,0 -o {dir}/o",
       {},
       {},
       "--samples = '0' must be in 1.."},
      {"converge: a sampled estimator over grid steps",
       "converge --shape sphere1 --estimator recon-hausdorff --h 0.5 -o {dir}/o",
       {},
       {},
       "samples points: it needs sample counts (--samples)"},
      {"converge: a reconstruction method that does not exist",
       "converge --shape sphere1 --estimator recon-hausdorff:method=cocone --samples 100 -o "
       "{dir}/o",
       {},
       {},
       "parameter method"},
      {"lb-spectrum: n not an integer",
       "converge --shape sphere1 --estimator lb-spectrum:n=2.5 --h 0.5 -o {dir}/o --no-plot",
       {},
       {},
       "n = 2.5 must be a positive integer"},
      {"geodesic source outside the surface",
       "surface {dir}/cube.npy --estimate geodesic --source 40,40,40",
       {{"cube.npy", cube_npy()}},
       {},
       "not on the surface"},
      {"harmonic dimension of a 2D image (closed surfaces need 3D)",
       "surface {dir}/img.npy --harmonic --json",
       {{"img.npy", small_npy()}},
       {},
       "a 2D image"},
      {"Ambrosio-Tortorelli alpha not positive",
       "surface {dir}/cube.npy --estimate at-normal --at-alpha 0",
       {{"cube.npy", cube_npy()}},
       {},
       "--at-alpha '0': a positive number is needed"},
      {"regularization data weight not positive",
       "surface {dir}/cube.npy --regularize --alpha 0 -o {dir}/r.ply",
       {{"cube.npy", cube_npy()}},
       {},
       "--alpha '0': a positive number is needed"},
      {"regularization weight without --regularize",
       "surface {dir}/cube.npy --gamma 0.1 -o {dir}/r.ply",
       {{"cube.npy", cube_npy()}},
       {},
       "--alpha, --beta and --gamma are only read by --regularize"},
      {"regularization of a marching-cubes mesh",
       "surface {dir}/cube.npy --regularize --mesh marching-cubes -o {dir}/r.ply",
       {{"cube.npy", cube_npy()}},
       {},
       "it does not apply to --mesh marching-cubes"},
      {"regularization of a 2D image",
       "surface {dir}/in.npy --regularize -o {dir}/r.ply",
       {{"in.npy", small_npy()}},
       {},
       "a 2D image (4, 4) uint8 where a 3D one is needed"},
      {"plane normal with a zero component",
       "plane probe 0 1 2",
       {},
       {},
       "the normal needs three nonzero components"},
      {"non-primitive plane normal", "plane probe 2 4 6", {}, {}, "is not primitive"},
      {"hexadecimal plane normal", "plane probe 1 2 0x3", {}, {}, "C = '0x3'"},
      {"plane probing past --max-steps",
       "plane probe 1 50 101 --algorithm r --max-steps 3",
       {},
       {},
       "not ended after 3 steps"},
      {"plane points with two coordinates",
       "plane recognize {dir}/p.txt",
       {{"p.txt", "0 0 0\n1 2\n"}},
       {},
       "p.txt:2:"},
      {"octal-looking option out of its set",
       "dss cover {dir}/p.txt --connectivity 010",
       {{"p.txt", "0 0\n1 0\n"}},
       {},
       "--connectivity: 10 not in {4,8}"},
      {"hexadecimal integer option",
       "transform dt {dir}/in.npy -o {dir}/out.npy --threads 0x10",
       {{"in.npy", small_npy()}},
       {},
       "--threads: not a decimal integer: '0x10'"},
      {"integer option beyond 64 bits",
       "transform dt {dir}/in.npy -o {dir}/out.npy --threads 99999999999999999999",
       {{"in.npy", small_npy()}},
       {},
       "out of range"},
      {"memory budget that is not a byte count",
       "transform dt {dir}/in.npy -o {dir}/out.npy --memory 4GB",
       {{"in.npy", small_npy()}},
       {},
       "--memory '4GB': a byte count"},
      {"memory budget below one slice",
       "transform dt {dir}/in.npy -o {dir}/out.npy --out-of-core --memory 3",
       {{"in.npy", small_npy()}},
       {},
       "is below one slice"},
      {"--mpi without an MPI launcher (or in a zdg built without MPI)",
       "transform dt {dir}/in.npy -o {dir}/out.npy --mpi",
       {{"in.npy", small_npy()}},
       {},
       "--mpi: "},
      {"out of core with values past 64 bits (l100: the in-memory transform takes them)",
       "transform dt {dir}/in.npy -o {dir}/out.npy --out-of-core --metric l100",
       {{"in.npy", small_npy()}},
       {},
       "do not fit 64 bits; use the in-memory transform"},
      {"out of core on a .pgm",
       "transform dt {dir}/in.pgm -o {dir}/out.npy --out-of-core",
       {{"in.pgm", "P2\n2 1\n255\n0 1\n"}},
       {},
       "--out-of-core reads and writes .npy files"},
      {"point file with a hexadecimal coordinate",
       "hull points {dir}/p.txt",
       {{"p.txt", "0 0\n0x10 1\n"}},
       {},
       "p.txt:2: '0x10' is not an integer"},
      {"half-plane file with an exponent",
       "hull halfplanes {dir}/h.txt",
       {{"h.txt", "1 0 3\n1e2 0 1\n"}},
       {},
       "h.txt:2:"},
      {"Freeman chain with a bad code",
       "dss cover {dir}/c.txt",
       {{"c.txt", "0 0 0105\n"}},
       {},
       "c.txt:1: Freeman chain: invalid code '5'"},
      {"Freeman chain start beyond int64",
       "dss cover {dir}/c.txt",
       {{"c.txt", "99999999999999999999 0 01\n"}},
       {},
       "is not a 64-bit integer"},
      // --- 2. exceptions of the environment and of malformed files: one line, exit 2 ----------
      {"npy header 'shape': } (std::out_of_range before)",
       "transform dt {dir}/bad.npy -o {dir}/out.npy",
       {{"bad.npy", npy("{'descr': '<i8', 'fortran_order': False, 'shape': }", "")}},
       {},
       "malformed npy header"},
      {"output below a file (filesystem_error before)",
       "transform dt {dir}/in.npy -o {dir}/file.txt/sub.npy",
       {{"in.npy", small_npy()}, {"file.txt", "a file"}},
       {},
       "is not a folder"},
      {"output in a missing folder",
       "transform dt {dir}/in.npy -o {dir}/missing/out.npy",
       {{"in.npy", small_npy()}},
       {},
       "does not exist"},
      {"output is a folder",
       "transform dt {dir}/in.npy -o {dir}/out.npy",
       {{"in.npy", small_npy()}, {"out.npy/", ""}},
       {},
       "is a folder"},
      {"thread count past the limit (thread creation failure before)",
       "transform dt {dir}/in.npy -o {dir}/out.npy --threads 100000",
       {{"in.npy", small_npy()}},
       {},
       "--threads"},
      {"input is a folder", "hull points {dir}/sub", {{"sub/", ""}}, {}, "is a folder"},
      {"input is a device", "hull points /dev/zero", {}, {}, "not a regular file"},
      {"missing input", "dss recognize {dir}/missing.txt", {}, {}, "no such file"},
      // --- 3. converge's outputs are all or nothing ---------------------------------------------
      {"a folder named summary.json in the output folder",
       converge + "-o {dir}/out --force --no-plot",
       {{"out/summary.json/", ""}},
       {"out/results.csv"},
       "summary.json: is a folder"},
      {"existing results without --force",
       converge + "-o {dir}/out --no-plot",
       {},
       {"out/results.csv"},
       "results.csv: exists (use --force to replace it)"},
      // --- 4. an existing output is refused unless --force --------------------------------------
      {"existing transform output",
       "transform dt {dir}/in.npy -o {dir}/out.npy",
       {{"in.npy", small_npy()}},
       {"out.npy"},
       "out.npy: exists (use --force"},
      {"empty npy whose other extents multiply past 2^63",
       "transform dt {dir}/in.npy -o {dir}/out.npy",
       {{"in.npy", npy("{'descr': '|u1', 'fortran_order': False, 'shape': (0, 4294967296, "
                       "4294967296), }",
                       "")}},
       {},
       "past 2^63"},
      {"existing hull output",
       "hull disc 0 0 5 -o {dir}/hull.txt",
       {},
       {"hull.txt"},
       "hull.txt: exists (use --force"},
      {"existing surface mesh",
       "surface {dir}/v.npy -o {dir}/m.obj",
       {{"v.npy", cube_npy()}},
       {"m.obj"},
       "m.obj: exists (use --force"},
      {"existing surface picture",
       "surface {dir}/v.npy -o {dir}/m.ply --png {dir}/pic.png --color ii-mean --radius 1v",
       {{"v.npy", cube_npy()}},
       {"pic.png"},
       "pic.png: exists (use --force"},
      {"existing contour picture",
       "contour {dir}/in.npy --png {dir}/pic.png",
       {{"in.npy", small_npy()}},
       {"pic.png"},
       "pic.png: exists (use --force"},
      {"existing hull points output",
       "hull points {dir}/p.txt --json -o {dir}/hull.json",
       {{"p.txt", "0 0\n1 0\n0 1\n"}},
       {"hull.json"},
       "exists"},
      // issue #35 (the viewer page)
      {"viewer page of another format",
       "surface {dir}/v.npy --html {dir}/v.htm",
       {{"v.npy", cube_npy()}},
       {},
       "the viewer is an .html file"},
      {"viewer page past the face budget (nothing written, the mesh neither)",
       "surface {dir}/v.npy --html {dir}/v.html -o {dir}/m.ply --max-faces 3",
       {{"v.npy", cube_npy()}},
       {},
       "more than 3 (--max-faces)"},
      {"existing viewer page",
       "surface {dir}/v.npy --html {dir}/v.html",
       {{"v.npy", cube_npy()}},
       {"v.html"},
       "exists"},
      {"skeleton viewer page of another format",
       "topology skeleton {dir}/v.npy -o {dir}/s.npy --html {dir}/s.htm",
       {{"v.npy", cube_npy()}},
       {},
       "the viewer is an .html file"},
      {"skeleton viewer page of a 2D result",
       "topology skeleton {dir}/f.pgm -o {dir}/s.npy --html {dir}/s.html",
       {{"f.pgm", "P2\n3 3\n1\n1 1 1\n1 1 1\n1 1 1\n"}},
       {},
       "--html shows 3D results"},
      {"viewer face budget not positive",
       "surface {dir}/v.npy --html {dir}/v.html --max-faces 0",
       {{"v.npy", cube_npy()}},
       {},
       "--max-faces must be at least 1"},
      {"contour viewer page of another format",
       "contour {dir}/in.npy --html {dir}/c.htm",
       {{"in.npy", small_npy()}},
       {},
       "the viewer is an .html file (got '.htm')"},
      {"contour viewer page past the face budget (nothing written, the CSV neither)",
       "contour {dir}/in.npy --html {dir}/c.html --csv {dir}/c.csv --max-faces 2",
       {{"in.npy", small_npy()}},
       {},
       "more than 2 (--max-faces)"},
      {"existing contour viewer page",
       "contour {dir}/in.npy --html {dir}/c.html",
       {{"in.npy", small_npy()}},
       {"c.html"},
       "exists"},
      {"a paper run by its script, without an output folder",
       "paper at-normals",
       {},
       {},
       "zdg paper at-normals needs -o DIR"},
      {"Ambrosio-Tortorelli on a mesh that is not a manifold",
       "mesh at {dir}/m.ply -o {dir}/out.ply",
       {{"m.ply", kPlyFin}},
       {},
       "has 3 faces: not a manifold mesh"},
      {"Ambrosio-Tortorelli on a mesh without faces",
       "mesh at {dir}/m.ply -o {dir}/out.ply",
       {{"m.ply", kPlyNoFace}},
       {},
       "the mesh has no faces"},
      {"Ambrosio-Tortorelli inpainting a field the mesh does not have",
       "mesh at {dir}/m.ply -o {dir}/out.ply --inpaint mask",
       {{"m.ply", kPlyTriangle}},
       {},
       "has no face field 'mask' (k)"},
      {"Ambrosio-Tortorelli inpainting every face",
       "mesh at {dir}/m.ply -o {dir}/out.ply --inpaint k",
       {{"m.ply", kPlyTriangle}},
       {},
       "all inpainted"},
      {"Ambrosio-Tortorelli on a mesh over an existing output",
       "mesh at {dir}/m.ply -o {dir}/out.ply",
       {{"m.ply", kPlyTriangle}},
       {"out.ply"},
       "out.ply: exists (use --force"},
      {"Ambrosio-Tortorelli on a mesh with alpha not positive",
       "mesh at {dir}/m.ply -o {dir}/out.ply --alpha 0",
       {{"m.ply", kPlyTriangle}},
       {},
       "--alpha '0': a positive number is needed"},
      {"Ambrosio-Tortorelli on a mesh with one epsilon",
       "mesh at {dir}/m.ply -o {dir}/out.ply --epsilon 2",
       {{"m.ply", kPlyTriangle}},
       {},
       "--epsilon '2': expected E1,E2"},
      {"Ambrosio-Tortorelli on a mesh with a threshold outside [0, 1]",
       "mesh at {dir}/m.ply -o {dir}/out.ply --threshold 1.5",
       {{"m.ply", kPlyTriangle}},
       {},
       "--threshold '1.5': a number in [0, 1] is needed"},
      {"Ambrosio-Tortorelli on a mesh with an unknown solver",
       "mesh at {dir}/m.ply -o {dir}/out.ply --solver lu",
       {{"m.ply", kPlyTriangle}},
       {},
       "--solver 'lu': expected cg or cholesky"},
      {"Ambrosio-Tortorelli on a mesh that is not a PLY",
       "mesh at {dir}/m.obj -o {dir}/out.ply",
       {{"m.obj", "v 0 0 0\n"}},
       {},
       "zdg mesh at reads a .ply mesh (got '.obj')"},
      {"reconstruct with an unknown method",
       "reconstruct {dir}/p.xyz --method marching --h 0.5 -o {dir}/m.ply",
       {{"p.xyz", "0 0 0 0 0 1\n1 0 0 1 0 0\n0 1 0 0 1 0\n0 0 1 0 0 1\n1 1 0 1 1 0\n1 0 1 1 0 1\n0 "
                  "1 1 0 1 1\n1 1 1 1 1 1\n2 0 0 1 0 0\n0 2 0 0 1 0\n0 0 2 0 0 1\n2 2 2 1 1 1\n"}},
       {},
       "unknown method 'marching' (hoppe, winding, poisson, rbf, imls)"},
      {"reconstruct with a grid step that is not positive",
       "reconstruct {dir}/p.xyz --h 0 -o {dir}/m.ply",
       {{"p.xyz", "0 0 0 0 0 1\n1 0 0 1 0 0\n0 1 0 0 1 0\n0 0 1 0 0 1\n1 1 0 1 1 0\n1 0 1 1 0 1\n0 "
                  "1 1 0 1 1\n1 1 1 1 1 1\n2 0 0 1 0 0\n0 2 0 0 1 0\n0 0 2 0 0 1\n2 2 2 1 1 1\n"}},
       {},
       "--h 0: the grid step must be > 0"},
      {"reconstruct on a grid too large for memory",
       "reconstruct {dir}/p.xyz --h 1e-7 -o {dir}/m.ply",
       {{"p.xyz", "0 0 0 0 0 1\n1 0 0 1 0 0\n0 1 0 0 1 0\n0 0 1 0 0 1\n1 1 0 1 1 0\n1 0 1 1 0 1\n0 "
                  "1 1 0 1 1\n1 1 1 1 1 1\n2 0 0 1 0 0\n0 2 0 0 1 0\n0 0 2 0 0 1\n2 2 2 1 1 1\n"}},
       {},
       "(use a larger h)"},
      {"reconstruct of a point cloud with a point given twice",
       "reconstruct {dir}/p.xyz --h 0.5 -o {dir}/m.ply",
       {{"p.xyz", "0 0 0\n1 0 0\n0 0 0\n"}},
       {},
       "p.xyz: point 2 repeats point 0"},
      {"reconstruct with more neighbours than points",
       "reconstruct {dir}/p.xyz --h 0.5 --k 30 -o {dir}/m.ply",
       {{"p.xyz", "0 0 0 0 0 1\n1 0 0 1 0 0\n0 1 0 0 1 0\n0 0 1 0 0 1\n1 1 0 1 1 0\n1 0 1 1 0 1\n0 "
                  "1 1 0 1 1\n1 1 1 1 1 1\n2 0 0 1 0 0\n0 2 0 0 1 0\n0 0 2 0 0 1\n2 2 2 1 1 1\n"}},
       {},
       "k = 30 neighbours needs at least 31 points (12 given)"},
      {"reconstruct into a mesh of an unknown extension",
       "reconstruct {dir}/p.xyz --h 0.5 -o {dir}/m.stl",
       {{"p.xyz", "0 0 0 0 0 1\n1 0 0 1 0 0\n0 1 0 0 1 0\n0 0 1 0 0 1\n1 1 0 1 1 0\n1 0 1 1 0 1\n0 "
                  "1 1 0 1 1\n1 1 1 1 1 1\n2 0 0 1 0 0\n0 2 0 0 1 0\n0 0 2 0 0 1\n2 2 2 1 1 1\n"}},
       {},
       "m.stl"},
      {"reconstruct into an existing mesh",
       "reconstruct {dir}/p.xyz --h 0.5 -o {dir}/m.ply",
       {{"p.xyz", "0 0 0 0 0 1\n1 0 0 1 0 0\n0 1 0 0 1 0\n0 0 1 0 0 1\n1 1 0 1 1 0\n1 0 1 1 0 1\n0 "
                  "1 1 0 1 1\n1 1 1 1 1 1\n2 0 0 1 0 0\n0 2 0 0 1 0\n0 0 2 0 0 1\n2 2 2 1 1 1\n"}},
       {"m.ply"},
       "m.ply"},
      {"normals of an empty point cloud",
       "normals {dir}/e.xyz -o {dir}/n.ply",
       {{"e.xyz", "# no points\n"}},
       {},
       "e.xyz: no points"},
      {"normals of a point cloud with a NaN coordinate",
       "normals {dir}/p.xyz -o {dir}/n.ply",
       {{"p.xyz", "0 0 0\n1 nan 1\n"}},
       {},
       "p.xyz:2: 'nan' is not finite"},
      {"normals of a point cloud with a NaN in an npy row",
       "normals {dir}/p.npy -o {dir}/n.ply",
       {{"p.npy", npy("{'descr': '<f8', 'fortran_order': False, 'shape': (1, 3), }",
                      std::string("\0\0\0\0\0\0\xf8\x7f", 8) + std::string(16, '\0'))}},
       {},
       "p.npy: row 0, column 0: the value is not finite"},
      {"render volume with a transfer function of four numbers on a line",
       "render volume {dir}/v.pgm --tf {dir}/tf.txt -o {dir}/r.png",
       {{"v.pgm", "P2\n2 2\n255\n0 1 2 3\n"}, {"tf.txt", "0 0 0 0 0\n255 1 1 1\n"}},
       {},
       "tf.txt:2: expected 'value r g b alpha'"},
      {"render volume with transfer function values that do not increase",
       "render volume {dir}/v.pgm --tf {dir}/tf.txt -o {dir}/r.png",
       {{"v.pgm", "P2\n2 2\n255\n0 1 2 3\n"}, {"tf.txt", "5 0 0 0 0\n5 1 1 1 1\n"}},
       {},
       "control point 2: value 5 does not increase"},
      {"render volume with a JSON transfer function that does not parse",
       "render volume {dir}/v.pgm --tf {dir}/tf.json -o {dir}/r.png",
       {{"v.pgm", "P2\n2 2\n255\n0 1 2 3\n"}, {"tf.json", "{\"points\": [[0, 0, 0, 0, 0]"}},
       {},
       "tf.json: not valid JSON"},
      {"render volume with an unknown preset or a missing file",
       "render volume {dir}/v.pgm --tf bone -o {dir}/r.png",
       {{"v.pgm", "P2\n2 2\n255\n0 1 2 3\n"}},
       {},
       "--tf 'bone': neither a file nor a preset (grey, ct-bone, ct-soft-tissue)"},
      {"render volume with a step out of range",
       "render volume {dir}/v.pgm --step 0 -o {dir}/r.png",
       {{"v.pgm", "P2\n2 2\n255\n0 1 2 3\n"}},
       {},
       "render volume: the step must lie in [0.01, 8] voxels (got 0)"},
      {"render volume with a view that is not two numbers",
       "render volume {dir}/v.pgm --view 30 -o {dir}/r.png",
       {{"v.pgm", "P2\n2 2\n255\n0 1 2 3\n"}},
       {},
       "--view '30': expected AZIMUTH,ELEVATION in degrees"},
      {"render volume with an early termination opacity out of range",
       "render volume {dir}/v.pgm --early-termination 1.5 -o {dir}/r.png",
       {{"v.pgm", "P2\n2 2\n255\n0 1 2 3\n"}},
       {},
       "the early termination opacity must lie in (0, 1] (got 1.5)"},
      {"render volume with a picture size that is not WIDTHxHEIGHT",
       "render volume {dir}/v.pgm --png-size 800 -o {dir}/r.png",
       {{"v.pgm", "P2\n2 2\n255\n0 1 2 3\n"}},
       {},
       "--png-size '800': expected WIDTHxHEIGHT"},
      {"render volume into a picture that is not a .png",
       "render volume {dir}/v.pgm -o {dir}/r.jpg",
       {{"v.pgm", "P2\n2 2\n255\n0 1 2 3\n"}},
       {},
       "r.jpg: the picture is a .png file"},
      {"render volume into an existing picture",
       "render volume {dir}/v.pgm -o {dir}/r.png",
       {{"v.pgm", "P2\n2 2\n255\n0 1 2 3\n"}},
       {"r.png"},
       "r.png"},
      {"normals of a point cloud with a point given twice",
       "normals {dir}/p.xyz -o {dir}/n.ply",
       {{"p.xyz", "0 0 0\n1 0 0\n0 0 0\n"}},
       {},
       "p.xyz: point 2 repeats point 0"},
      {"normals with too few neighbours (k > N - 1)",
       "normals {dir}/p.xyz -o {dir}/n.ply",
       {{"p.xyz", "0 0 0\n1 0 0\n0 1 0\n0 0 1\n"}},
       {},
       "too few neighbours: k = 10 needs at least 11 points, the cloud has 4"},
      {"normals with too few neighbours (k < 3)",
       "normals {dir}/p.xyz -o {dir}/n.ply --k 2",
       {{"p.xyz", "0 0 0\n1 0 0\n0 1 0\n0 0 1\n"}},
       {},
       "k = 2 neighbours are too few (at least 3)"},
      {"normals by the jet with k < 5",
       "normals {dir}/p.xyz -o {dir}/n.ply --k 4 --method jet",
       {{"p.xyz", "0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n"}},
       {},
       "the jet needs k >= 5 neighbours"},
      {"normals of a point cloud of an unknown extension",
       "normals {dir}/p.obj -o {dir}/n.ply",
       {{"p.obj", "v 0 0 0\n"}},
       {},
       "p.obj: unknown point cloud format '.obj' (.ply, .xyz, .off or .npy)"},
      {"normals into a file of an unknown extension",
       "normals {dir}/p.xyz -o {dir}/n.stl",
       {{"p.xyz", "0 0 0\n"}},
       {},
       "n.stl: unknown point cloud format '.stl'"},
      {"normals into an OFF file",
       "normals {dir}/p.xyz -o {dir}/n.off",
       {{"p.xyz", "0 0 0\n"}},
       {},
       "n.off: zdg normals writes .ply, .xyz or .npy (not .off)"},
      {"normals over an existing output without --force",
       "normals {dir}/p.xyz -o {dir}/n.ply",
       {{"p.xyz", "0 0 0\n1 0 0\n0 1 0\n0 0 1\n"}},
       {"n.ply"},
       "n.ply: exists (use --force"},
      {"normals by an unknown method",
       "normals {dir}/p.xyz -o {dir}/n.ply --method vcm",
       {{"p.xyz", "0 0 0\n"}},
       {},
       "normal method 'vcm': expected pca or jet"},
      {"normals with an unknown orientation",
       "normals {dir}/p.xyz -o {dir}/n.ply --orient bfs",
       {{"p.xyz", "0 0 0\n"}},
       {},
       "normal orientation 'bfs': expected mst or none"},
      {"Ambrosio-Tortorelli with v on an unknown cell",
       "surface {dir}/cube.npy --estimate at-normal --at-v edge",
       {{"cube.npy", cube_npy()}},
       {},
       "--at-v 'edge': expected linel or pointel"},
      {"view of a mesh that is not a PLY",
       "view {dir}/m.obj -o {dir}/v.html",
       {{"m.obj", "v 0 0 0\n"}},
       {},
       "zdg view reads a .ply mesh (got '.obj')"},
      {"view page of another format",
       "view {dir}/m.ply -o {dir}/v.png",
       {{"m.ply", kPlyTriangle}},
       {},
       "the viewer is an .html file (got '.png')"},
      {"view of a missing mesh", "view {dir}/none.ply -o {dir}/v.html", {}, {}, "none.ply"},
      {"view of a PLY cut short",
       "view {dir}/m.ply -o {dir}/v.html",
       {{"m.ply", std::string(kPlyTriangle).substr(0, std::string(kPlyTriangle).size() - 4)}},
       {},
       "the file ends inside face 0"},
      {"view of a PLY whose header claims more than the file holds",
       "view {dir}/m.ply -o {dir}/v.html",
       {{"m.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 999999999\n"
                  "property float x\nproperty float y\nproperty float z\nelement face 0\n"
                  "property list uchar int vertex_indices\nend_header\n"}},
       {},
       "claims 999999999 records"},
      {"view of a PLY face with a vertex out of range",
       "view {dir}/m.ply -o {dir}/v.html",
       {{"m.ply", std::string(kPlyTriangle).substr(0, std::string(kPlyTriangle).size() - 12) +
                      "3 0 1 3 0.5\n"}},
       {},
       "vertex index 3 out of range (3 vertices)"},
      {"view past the face budget",
       "view {dir}/m.ply -o {dir}/v.html --max-faces 0",
       {{"m.ply", kPlyTriangle}},
       {},
       "--max-faces must be at least 1"},
      {"view of a field the mesh lacks",
       "view {dir}/m.ply -o {dir}/v.html --field ii-mean",
       {{"m.ply", kPlyTriangle}},
       {},
       "the field 'ii-mean' is not on the mesh (k)"},
      {"existing view page",
       "view {dir}/m.ply -o {dir}/v.html",
       {{"m.ply", kPlyTriangle}},
       {"v.html"},
       "exists"},
      {"surface mesh of an unknown format",
       "surface {dir}/v.npy -o {dir}/m.stl",
       {{"v.npy", cube_npy()}},
       {},
       "unknown mesh format '.stl'"},
      {"surface picture of another format",
       "surface {dir}/v.npy --png {dir}/pic.jpg",
       {{"v.npy", cube_npy()}},
       {},
       "the picture is a .png file"},
      {"picture options without a picture",
       "surface {dir}/v.npy -o {dir}/m.ply --color ii-mean",
       {{"v.npy", cube_npy()}},
       {},
       "--color needs --png"},
      {"picture size out of range",
       "contour {dir}/in.npy --png {dir}/pic.png --png-size 100000x10",
       {{"in.npy", small_npy()}},
       {},
       "200x150 .. 8192x8192"},
      // --- 5. sizes announced by headers are checked before allocation ------------------------
      {"PGM claiming width 2^40 in 32 bytes",
       "transform dt {dir}/w.pgm -o {dir}/out.npy",
       {{"w.pgm", "P5\n1099511627776 1\n255\nabcdefghi"}},
       {},
       "truncated pixel data"},
      {"PGM claiming 20000x20000 in 21 bytes",
       "transform dt {dir}/s.pgm -o {dir}/out.npy",
       {{"s.pgm", "P5 20000 20000 255\nab"}},
       {},
       "20000x20000"},
      {"npy claiming 2^40 elements",
       "transform dt {dir}/big.npy -o {dir}/out.npy",
       {{"big.npy",
         npy("{'descr': '<i8', 'fortran_order': False, 'shape': (1099511627776,), }", "12345678")}},
       {},
       "truncated data"},
      {"npy shape product past 2^64",
       "transform dt {dir}/big.npy -o {dir}/out.npy",
       {{"big.npy", npy("{'descr': '|u1', 'fortran_order': False, 'shape': (4294967296, "
                        "4294967296, 4294967296), }",
                        "")}},
       {},
       "shape too large"},
      {"chamfer mask with a weight that is not positive",
       "transform chamfer {dir}/in.npy -o {dir}/out.npy --mask 3,0",
       {{"in.npy", small_npy()}},
       {},
       "the weights are positive integers"},
      {"chamfer mask with too many weights",
       "transform chamfer {dir}/in.npy -o {dir}/out.npy --mask 3,4,5,6",
       {{"in.npy", small_npy()}},
       {},
       "4 weights (1 to 3"},
      {"chamfer mask that is not a list of integers",
       "transform chamfer {dir}/in.npy -o {dir}/out.npy --mask 3,4.5",
       {{"in.npy", small_npy()}},
       {},
       "chamfer mask '3,4.5'"},
      {"chamfer transform of a 1-D image",
       "transform chamfer {dir}/line.npy -o {dir}/out.npy",
       {{"line.npy", npy("{'descr': '|u1', 'fortran_order': False, 'shape': (3,), }",
                         std::string("\1\0\1", 3))}},
       {},
       "is a 1-D image (the masks are 2D or 3D)"},
      {"chamfer mask whose values pass 64 bits",
       "transform chamfer {dir}/row.npy -o {dir}/out.npy --mask 9223372036854775807",
       {{"row.npy", npy("{'descr': '|u1', 'fortran_order': False, 'shape': (1, 7), }",
                        std::string("\0\1\1\1\1\1\0", 7))}},
       {},
       "does not fit uint64"},
      {"csg of two volumes of different shapes",
       "csg union {dir}/in.npy {dir}/row.npy -o {dir}/out.npy",
       {{"in.npy", small_npy()},
        {"row.npy", npy("{'descr': '|u1', 'fortran_order': False, 'shape': (1, 7), }",
                        std::string("\0\1\1\1\1\1\0", 7))}},
       {},
       "the images differ in shape: (4, 4) and (1, 7)"},
      {"csg with an output format that is not a volume",
       "csg complement {dir}/in.npy -o {dir}/out.txt",
       {{"in.npy", small_npy()}},
       {},
       "out.txt"},
      {"sturmian of a perfect square", "sturmian 1 1 9 2", {}, {}, "d is a perfect square"},
      {"sturmian of a rational (B = 0)", "sturmian 1 0 2 3", {}, {}, "b = 0 is a rational"},
      {"sturmian with a zero denominator", "sturmian 1 1 2 0", {}, {}, "zero denominator"},
      {"sturmian with an integer that is not decimal",
       "sturmian 1 0x1 2 3",
       {},
       {},
       "B: '0x1' is not an integer"},
      {"motion check with a rotation that is not a Pythagorean triple",
       "motion check --rotation 3,4,6",
       {},
       {},
       "not a Pythagorean triple"},
      {"motion check with a rotation of two numbers",
       "motion check --rotation 3,4",
       {},
       {},
       "expected 3 integers"},
      {"motion check with both a rotation and a quaternion",
       "motion check --rotation 3,4,5 --quaternion 1,0,0,0",
       {},
       {},
       "exactly one of --rotation"},
      {"motion check of the zero quaternion on a volume",
       "motion check {dir}/cube.npy --quaternion 0,0,0,0",
       {{"cube.npy", cube_npy()}},
       {},
       "the zero quaternion"},
      {"motion apply of a 2D rotation to a 3D volume",
       "motion apply {dir}/cube.npy --rotation 3,4,5 -o {dir}/out.npy",
       {{"cube.npy", cube_npy()}},
       {},
       "a 2D motion for a 3D input"},
      {"motion apply that sends the object out of the domain",
       "motion apply {dir}/in.npy --rotation 3,4,5 --center 0,0 -o {dir}/out.npy",
       {{"in.npy", small_npy()}},
       {},
       "outside the domain (--expand grows it)"},
      {"a .vdb input that is not an OpenVDB file",
       "topology betti {dir}/junk.vdb",
       {{"junk.vdb", "not a vdb file"}},
       {},
       "junk.vdb: not a readable OpenVDB file"},
      {"hull delaunay of points past 2^53",
       "hull delaunay {dir}/pts.txt",
       {{"pts.txt", "0 0\n9007199254740993 1\n"}},
       {},
       "pts.txt:2: coordinate 9007199254740993 is past 2^53"},
      {"motion check with a translation that is not a number",
       "motion check --rotation 3,4,5 --translation 1,x",
       {},
       {},
       "'x'"},
      {"surface --labels with another value than all",
       "surface {dir}/cube.npy --labels 1,2",
       {{"cube.npy", cube_npy()}},
       {},
       "--labels '1,2': expected all"},
      {"surface --labels all with a selection option",
       "surface {dir}/cube.npy --labels all --label 1",
       {{"cube.npy", cube_npy()}},
       {},
       "--labels all reads every value as a label"},
      // --- 7. bounded work from small inputs ----------------------------------------------------
      {"sturmian word past 10^8 letters",
       "sturmian 1 1 5 2 --length 100000001",
       {},
       {},
       "past the 10^8 letters"},
      {"l_p with a huge p",
       "transform dt {dir}/in.npy -o {dir}/out.npy --metric l1000000",
       {{"in.npy", small_npy()}},
       {},
       "l1000000 is beyond the supported l1 .. l1000"},
      {"l_p whose exact powers pass 4096 bits",
       "transform dt {dir}/in.npy -o {dir}/out.npy --metric l1000",
       {{"in.npy", npy("{'descr': '|u1', 'fortran_order': False, 'shape': (2, 64), }",
                       std::string(127, '\1') + std::string(1, '\0'))}},
       {},
       "zdg supports l_p while L^p < 2^4096 (here p <= 681"},
      {"disc hull with 10^12 radius",
       "hull disc 0 0 1000000000000",
       {},
       {},
       "could have up to 653509645 vertices (about 3.45e+08 expected"},
      {"disc hull with radius 2^63 - 1",
       "hull disc 0 0 9223372036854775807 --json",
       {},
       {},
       "more than the vertex bound 100000000"},
      {"disc hull over a lowered --max-vertices",
       "hull disc 0 0 1000 --max-vertices 10",
       {},
       {},
       "more than the vertex bound 10 "},
      {"exponent in a hull argument", "hull ellipse 0 0 1e12 1", {}, {}, "'1e12'"},
      {"ellipse hull with huge axes",
       "hull ellipse 0 0 1000000000000 1000000000000",
       {},
       {},
       "more than the vertex bound"},
      // --- 8. digital topology (issue #13) ------------------------------------------------------
      {"topology: a selection of no point",
       "topology thin {dir}/in.npy -o {dir}/out.npy --threshold 2",
       {{"in.npy", small_npy()}},
       {},
       "selects no voxel"},
      {"topology: a pair of another dimension",
       "topology betti {dir}/in.npy --adjacency 26,6",
       {{"in.npy", small_npy()}},
       {},
       "not admissible"},
      {"topology: an unknown pair",
       "topology components {dir}/in.npy --adjacency 8,8",
       {{"in.npy", small_npy()}},
       {},
       "not admissible"},
      {"topology: a priority image of another size",
       "topology skeleton {dir}/in.npy -o {dir}/out.npy --priority {dir}/p.npy",
       {{"in.npy", small_npy()},
        {"p.npy",
         npy("{'descr': '|u1', 'fortran_order': False, 'shape': (3, 3), }", std::string(9, '\1'))}},
       {},
       "another size"},
      {"topology: existing skeleton output",
       "topology skeleton {dir}/in.npy -o {dir}/out.npy",
       {{"in.npy", small_npy()}},
       {"out.npy"},
       "exists"},
      // --- 8, 10. TOML values and shape parameters, as the issue wrote them ------------------
      {"TOML tolerance = inf",
       "converge {dir}/run.toml -o {dir}/out --no-plot",
       {{"run.toml", "shape = \"ball:5\"\nestimator = \"gauss-area\"\nh = \"1:0.5:3\"\n"
                     "tolerance = inf\n"}},
       {},
       "key 'tolerance': 'inf' is not a finite number"},
      {"infinite flower angle",
       "converge --shape flower:20,7,6,1e400 --estimator gauss-area --h 1 -o {dir}/out --no-plot",
       {},
       {},
       "'flower:20,7,6,1e400': parameter 4 '1e400' is not a number of the form"},
      {"ball radius that rounds to 0",
       "converge --shape ball:1e-401 --estimator gauss-area --h 1 -o {dir}/out --no-plot",
       {},
       {},
       "'ball:1e-401': parameter 1"},
      // --- every command family that reads files and writes outputs: a bad file, a missing
      // output folder, an existing output without --force ---------------------------------------
      {"convert: truncated PGM",
       "convert {dir}/cut.pgm {dir}/out.npy",
       {{"cut.pgm", kCutPgm}},
       {},
       "cut.pgm:3: truncated pixel data"},
      {"convert: output in a missing folder",
       "convert {dir}/in.npy {dir}/missing/out.vol",
       {{"in.npy", cube_npy()}},
       {},
       "folder '"},
      {"convert: existing output",
       "convert {dir}/in.npy {dir}/out.vol",
       {{"in.npy", cube_npy()}},
       {"out.vol"},
       "out.vol: exists (use --force"},
      {"surface: malformed npy header",
       "surface {dir}/bad.npy -o {dir}/out.ply",
       {{"bad.npy", npy("{'descr': '|u1', 'fortran_order': False, 'shape': }", "")}},
       {},
       "bad.npy: malformed npy header"},
      {"surface: CSV in a missing folder",
       "surface {dir}/in.npy --csv {dir}/missing/surfels.csv",
       {{"in.npy", cube_npy()}},
       {},
       "does not exist"},
      {"surface: existing mesh",
       "surface {dir}/in.npy -o {dir}/out.ply",
       {{"in.npy", cube_npy()}},
       {"out.ply"},
       "out.ply: exists (use --force"},
      {"surface: an existing second output (nothing written)",
       "surface {dir}/in.npy -o {dir}/out.ply --csv {dir}/surfels.csv",
       {{"in.npy", cube_npy()}},
       {"surfels.csv"},
       "surfels.csv: exists (use --force"},
      {"contour: truncated PGM",
       "contour {dir}/cut.pgm -o {dir}/out.svg",
       {{"cut.pgm", kCutPgm}},
       {},
       "cut.pgm:3: truncated pixel data"},
      {"contour: drawing in a missing folder",
       "contour {dir}/in.npy -o {dir}/missing/out.svg",
       {{"in.npy", small_npy()}},
       {},
       "does not exist"},
      {"contour: existing drawing",
       "contour {dir}/in.npy -o {dir}/out.svg",
       {{"in.npy", small_npy()}},
       {"out.svg"},
       "out.svg: exists (use --force"},
      {"topology: truncated .vol",
       "topology betti {dir}/cut.vol",
       {{"cut.vol", kCutVol}},
       {},
       "cut.vol: truncated voxel data"},
      {"topology: thinning into a missing folder",
       "topology thin {dir}/in.npy -o {dir}/missing/out.npy",
       {{"in.npy", cube_npy()}},
       {},
       "does not exist"},
      {"topology: existing labels",
       "topology components {dir}/in.npy -o {dir}/out.npy",
       {{"in.npy", cube_npy()}},
       {"out.npy"},
       "out.npy: exists (use --force"},
      {"paper: unknown name", "paper nosuch -o {dir}/out", {}, {}, "unknown paper 'nosuch'"},
      // --- zdg laplacians (issue #36) ---------------------------------------------------------
      {"laplacians: unknown operator",
       "laplacians --operator nosuch --json",
       {},
       {},
       "unknown operator 'nosuch'"},
      {"laplacians: h not positive", "laplacians --h 0 --json", {}, {}, "--h"},
      {"laplacians: h not a number", "laplacians --h abc --json", {}, {}, "--h"},
      {"laplacians: 2D shape", "laplacians --shape ball:5 --json", {}, {}, "is not 3D"},
      {"laplacians: unknown shape", "laplacians --shape nosuch --json", {}, {}, "unknown shape"},
      {"laplacians: clipped shape",
       "laplacians --shape cylinder --h 1 --json",
       {},
       {},
       "the box clips"},
      {"laplacians: cube too small",
       "laplacians --operator heat --cube 8 --h 0.2 --json",
       {},
       {},
       "take a larger cube"},
      {"laplacians: cube out of range",
       "laplacians --cube 0.5 --json",
       {},
       {},
       "half-side must be in [1, 1000]"},
      {"laplacians: heat kernel too large",
       "laplacians --operator heat --h 0.04 --json",
       {},
       {},
       "take a larger h"},
      {"paper: existing results",
       "paper gauss-area --quick -o {dir}/out --no-plot",
       {},
       {"out/results.csv"},
       "results.csv: exists (use --force"},
      // --- zdg check and zdg serve (issue #20) ------------------------------------------------
      {"check: unknown property",
       "check no.such.property --runs 5",
       {},
       {},
       "unknown property 'no.such.property'"},
      {"check: no property named", "check --runs 5", {}, {}, "name the properties"},
      {"check: bad --type",
       "check floor_sum.oracle --type int32",
       {},
       {},
       "--type 'int32' is not one of"},
      {"check: type the property does not run on",
       "check dt.l2.brute_force --type int128",
       {},
       {},
       "does not run on int128"},
      {"check: zero --runs", "check floor_sum.oracle --runs 0", {}, {}, "--runs 0 is not >= 1"},
      {"check: hexadecimal --runs", "check floor_sum.oracle --runs 0x10", {}, {}, "0x10"},
      {"check: negative --runs", "check floor_sum.oracle --runs -5", {}, {}, "--runs -5"},
      {"check: --bits out of range", "check floor_sum.oracle --bits 0", {}, {}, "--bits 0"},
      {"check: --max-size out of range",
       "check dss.recognize.minimal --max-size 100000",
       {},
       {},
       "--max-size 100000"},
      {"check: --against on a property without an operation",
       "check simple_point.lut --against cat",
       {},
       {},
       "checks no operation"},
      {"check: bad --time-budget",
       "check floor_sum.oracle --time-budget 10x",
       {},
       {},
       "'10x' is not a duration"},
      {"check: bad --request-timeout",
       "check floor_sum.oracle --against cat --request-timeout 0",
       {},
       {},
       "not a positive duration"},
      {"check: bad replay token",
       "check floor_sum.oracle --replay int64.64.nope",
       {},
       {},
       "replay token"},
      {"check: --replay with two properties",
       "check floor_sum.oracle cf.roundtrip --replay int64.64.200.0000000000000001",
       {},
       {},
       "name exactly one"},
      {"serve: unknown operation", "serve frobnicate", {}, {}, "unknown operation 'frobnicate'"},
      // issue #41 (volume-file parsers: NIfTI header, .vol ranges, claims, npy dtypes)
      {"NIfTI-1 vox_offset 0 (was read from byte 348)",
       "convert {dir}/v.nii {dir}/out.npy",
       {{"v.nii", zdg::test::patched<float>(zdg::test::nifti1_bytes(4, 3, 2), 108, 0.0f)}},
       {},
       "v.nii: NIfTI vox_offset 0 is not an integer in [352, 2^31)"},
      {"NIfTI-1 vox_offset NaN",
       "surface {dir}/v.nii -o {dir}/x.ply",
       {{"v.nii", zdg::test::patched<float>(zdg::test::nifti1_bytes(4, 3, 2), 108, NAN)}},
       {},
       "v.nii: NIfTI vox_offset nan is not an integer"},
      {"NIfTI-1 vox_offset 1e30",
       "convert {dir}/v.nii.gz {dir}/out.npy",
       {{"v.nii.gz", zdg::test::gzip_bytes(
                         zdg::test::patched<float>(zdg::test::nifti1_bytes(4, 3, 2), 108, 1e30f))}},
       {},
       "v.nii.gz: NIfTI vox_offset 1.00000002e+30 is not an integer in [352, 2^31)"},
      {"NIfTI-2 dim[0] = 2^31 (crashed inside the library)",
       "surface {dir}/d.nii -o {dir}/x.ply",
       {{"d.nii", zdg::test::patched<std::int64_t>(zdg::test::nifti2_bytes(4, 3, 2), 16,
                                                   std::int64_t{1} << 31)}},
       {},
       "d.nii: NIfTI dim[0] = 2147483648 (1..7)"},
      {"NIfTI-2 .nii.gz dim[0] = -2^63",
       "convert {dir}/d.nii.gz {dir}/out.npy",
       {{"d.nii.gz", zdg::test::gzip_bytes(zdg::test::patched<std::int64_t>(
                         zdg::test::nifti2_bytes(4, 3, 2), 16, INT64_MIN))}},
       {},
       "d.nii.gz: NIfTI dim[0] = -9223372036854775808 (1..7)"},
      {"NIfTI-2 vox_offset inside the header",
       "convert {dir}/o.nii {dir}/out.npy",
       {{"o.nii", zdg::test::patched<std::int64_t>(zdg::test::nifti2_bytes(4, 3, 2), 168, 348)}},
       {},
       "o.nii: NIfTI vox_offset 348 is not in [544, 2^62]"},
      {"NIfTI-2 bitpix that disagrees with the datatype",
       "convert {dir}/b.nii {dir}/out.npy",
       {{"b.nii", zdg::test::patched<std::int16_t>(zdg::test::nifti2_bytes(4, 3, 2), 14, 32)}},
       {},
       "b.nii: NIfTI bitpix 32 disagrees with the datatype uint8"},
      {"NIfTI-2 magic without its check bytes",
       "convert {dir}/m.nii {dir}/out.npy",
       {{"m.nii", zdg::test::patched<char>(zdg::test::nifti2_bytes(4, 3, 2), 8, '\n')}},
       {},
       "m.nii: not a single-file NIfTI-2 volume"},
      {".nii.gz of 1 MB claiming 1000^3 voxels, corrupt after 4 MiB",
       "convert {dir}/c.nii.gz {dir}/out.npy",
       {{"c.nii.gz",
         zdg::test::good_then_garbage(
             zdg::test::patched<std::int16_t>(
                 zdg::test::patched<std::int16_t>(
                     zdg::test::patched<std::int16_t>(zdg::test::nifti1_bytes(1, 1, 1), 42, 1000),
                     44, 1000),
                 46, 1000)
                 .substr(0, 352),
             std::size_t{4} << 20, 1000000, true)}},
       {},
       "c.nii.gz: truncated or corrupt NIfTI data"},
      {".vol Version 3 of 1 MB claiming 1000^3 voxels, corrupt after 4 MiB",
       "surface {dir}/c.vol -o {dir}/x.ply",
       {{"c.vol", "X: 1000\nY: 1000\nZ: 1000\nVersion: 3\n.\n" +
                      zdg::test::good_then_garbage("", std::size_t{4} << 20, 1000000, false)}},
       {},
       "c.vol: corrupt zlib data"},
      {".vol Center-X at INT64_MAX - 1 (its upper bound reached INT64_MAX)",
       "surface {dir}/c.vol -o {dir}/x.ply",
       {{"c.vol", "Center-X: 9223372036854775806\nX: 2\nY: 1\nZ: 1\nVersion: 2\n.\nab"}},
       {},
       "c.vol: vol header 'Center-X: 9223372036854775806' is not in [-2^61, 2^61]"},
      {".vol Center-Y past 2^61",
       "convert {dir}/c.vol {dir}/out.npy",
       {{"c.vol", "Center-Y: 2305843009213693953\nX: 1\nY: 1\nZ: 1\nVersion: 2\n.\na"}},
       {},
       "c.vol: vol header 'Center-Y: 2305843009213693953' is not in [-2^61, 2^61]"},
      {"npy dtype not accepted: the message lists every accepted dtype",
       "convert {dir}/c.npy {dir}/out.vol",
       {{"c.npy",
         npy("{'descr': '<c8', 'fortran_order': False, 'shape': (1, 1), }", std::string(8, '\0'))}},
       {},
       "c.npy: dtype '<c8' is not supported (accepted: bool, uint8, uint16, uint32, uint64, "
       "int8, int16, int32, int64, float32, float64, little-endian)"},
      // issue #41 (numbers, checks and bounds)
      {"hexadecimal literal in a polynomial shape",
       "converge --shape 'poly:x^2+y^2-0x10' --estimator gauss-area --h 1,0.5 -o {dir}/out",
       {},
       {},
       "numbers are decimal"},
      {"exponent in a polynomial shape",
       "converge --shape 'poly:x^2+y^2-1e2' --estimator gauss-area --h 1,0.5",
       {},
       {},
       "numbers are decimal"},
      {"hexadecimal integer in a TOML config",
       "converge {dir}/run.toml -o {dir}/out",
       {{"run.toml", "shape = \"ball:10\"\nestimator = \"gauss-area\"\nh = \"0.5,0.25\"\n"
                     "translations = 0x10\n"}},
       {},
       "run.toml:4: key 'translations' is a hexadecimal integer"},
      {"octal integer in a TOML config",
       "converge {dir}/run.toml",
       {{"run.toml", "shape = \"ball:10\"\nestimator = \"gauss-area\"\nh = \"0.5,0.25\"\n"
                     "seed = 0o10\n"}},
       {},
       "key 'seed' is an octal integer"},
      {"binary integer in a TOML config",
       "converge {dir}/run.toml",
       {{"run.toml", "shape = \"ball:10\"\nestimator = \"gauss-area\"\nh = \"0.5,0.25\"\n"
                     "k = 0b10\n"}},
       {},
       "key 'k' is a binary integer"},
      {"check: empty --against", "check floor_sum.oracle --against ''", {}, {}, "empty command"},
      {"check: blank --against", "check floor_sum.oracle --against ' '", {}, {}, "empty command"},
      {"check: empty --replay", "check floor_sum.oracle --replay ''", {}, {}, "empty replay token"},
      {"plane probe H past its proven step bound",
       "plane probe 1000000007 1000000009 3 --algorithm h",
       {},
       {},
       "needs up to ||N||_1 - 3 = 2000000016 steps"},
      {"plane probe H past a small --max-steps",
       "plane probe 1 50 101 --algorithm h --max-steps 3",
       {},
       {},
       "needs up to ||N||_1 - 3 = 149 steps on this normal, more than max_steps 3"},
      {"plane probe R past the default step budget",
       "plane probe 1000000007 1000000009 3",
       {},
       {},
       "not ended after 1000000 steps (the proven bound for this normal is"},
      {"default --radius larger than the image",
       "contour {dir}/in.npy --estimate ii-curvature",
       {{"in.npy", small_npy()}},
       {},
       "--radius 5v (the default) is 5 pixels"},
      // issue #41 (outputs and paths) --------------------------------------------------------
      {"surface: one file as the mesh and the CSV (relative and absolute names)",
       "surface {dir}/cube.npy -o {rel}/x.ply --csv {dir}/x.ply",
       {{"cube.npy", cube_npy()}},
       {},
       "x.ply are the same file"},
      {"surface: one file as the mesh and the CSV (./ and --force over an existing file)",
       "surface {dir}/cube.npy -o {dir}/x.ply --csv {rel}/./x.ply --force",
       {{"cube.npy", cube_npy()}},
       {"x.ply"},
       "x.ply are the same file"},
      {"surface: one file as the CSV and the picture",
       "surface {dir}/cube.npy --csv {rel}/p.png --png {dir}/sub/../p.png",
       {{"cube.npy", cube_npy()}, {"sub/", ""}},
       {},
       "p.png are the same file"},
      {"contour: one file as the drawing and the CSV",
       "contour {dir}/in.npy -o {dir}/s.svg --csv {rel}/s.svg",
       {{"in.npy", small_npy()}},
       {},
       "s.svg are the same file"},
      {"surface --force: the second output is a folder that cannot be replaced",
       "surface {dir}/cube.npy -o {dir}/a.ply --png {dir}/b.png --force",
       {{"cube.npy", cube_npy()}, {"b.png/x", "inside"}},
       {"a.ply"},
       "b.png: is a folder"},
      {"converge --force: summary.json is a folder that cannot be replaced",
       converge + "-o {dir}/out --force --no-plot",
       {{"out/summary.json/x", "inside"}},
       {"out/results.csv"},
       "summary.json: is a folder"},
      {"transform voronoi of an empty .npy: the message names the file",
       "transform voronoi {dir}/e.npy -o {dir}/v.npy",
       {{"e.npy", npy("{'descr': '|u1', 'fortran_order': False, 'shape': (0, 3), }", "")}},
       {},
       "e.npy: empty array (an extent is 0)"},
      {"transform rma of a 0-D .npy: the message names the file",
       "transform rma {dir}/z.npy -o {dir}/m.npy",
       {{"z.npy", npy("{'descr': '<i4', 'fortran_order': False, 'shape': (), }",
                      std::string("\5\0\0\0", 4))}},
       {},
       "z.npy: a 0-dimensional array is not an image"},
      {"transform dt of an empty .npy into a .pgm (the general path): the message names the file",
       "transform dt {dir}/e.npy -o {dir}/d.pgm",
       {{"e.npy", npy("{'descr': '|u1', 'fortran_order': False, 'shape': (2, 0), }", "")}},
       {},
       "e.npy: empty array (an extent is 0)"},
      {"transform power of an empty int16 .npy: the message names the file",
       "transform power {dir}/e.npy -o {dir}/p.npy",
       {{"e.npy", npy("{'descr': '<i2', 'fortran_order': False, 'shape': (2, 0, 3), }", "")}},
       {},
       "e.npy: empty array (an extent is 0)"},
      {"transform rdt of a Fortran-order empty .npy: the message names the file",
       "transform rdt {dir}/e.npy -o {dir}/r.npy",
       {{"e.npy", npy("{'descr': '<i8', 'fortran_order': True, 'shape': (3, 0), }", "")}},
       {},
       "e.npy: empty array (an extent is 0)"},
      {"convex check: an unknown definition",
       "convex check {dir}/p.txt --definition strict",
       {{"p.txt", "0 0\n1 1\n"}},
       {},
       "--definition: 'strict' (full or hull)"},
      {"convex check: four coordinates a line",
       "convex check {dir}/p.txt",
       {{"p.txt", "0 0 0 0\n"}},
       {},
       "p.txt:1:"},
      {"convex check: an empty point file",
       "convex check {dir}/p.txt",
       {{"p.txt", "# nothing\n"}},
       {},
       "p.txt"},
      {"convex check --definition hull: a sweep past --max-columns",
       "convex check {dir}/p.txt --definition hull --max-columns 10",
       {{"p.txt", "0 0\n1000000000000 1\n"}},
       {},
       "more than 10 lattice columns"},
      {"convex envelope: more lattice points than --max-points",
       "convex envelope {dir}/p.txt -o {dir}/e.txt --max-points 100",
       {{"p.txt", "0 0\n1000000000000 1\n"}},
       {},
       "more than 100 lattice"},
      {"convex envelope: an existing output",
       "convex envelope {dir}/p.txt -o {dir}/e.txt",
       {{"p.txt", "0 0\n"}},
       {"e.txt"},
       "e.txt: exists (use --force"},
      {"convex envelope: the output is the input",
       "convex envelope {dir}/p.txt -o {dir}/p.txt --force",
       {{"p.txt", "0 0\n"}},
       {},
       "p.txt"},
      {"transform thickness of an image without background",
       "transform thickness {dir}/full.npy -o {dir}/t.npy",
       {{"full.npy", npy("{'descr': '|u1', 'fortran_order': False, 'shape': (2, 2), }",
                         std::string("\1\1\1\1", 4))}},
       {},
       "has no background point"},
      {"transform thickness into a .pgm (float32 diameters need an .npy)",
       "transform thickness {dir}/in.npy -o {dir}/t.pgm",
       {{"in.npy", small_npy()}},
       {},
       "the local thickness output is an .npy array"},
      {"transform thickness with a metric (Euclidean only)",
       "transform thickness {dir}/in.npy -o {dir}/t.npy --metric l1",
       {{"in.npy", small_npy()}},
       {},
       "--metric"},
      {"existing thickness output",
       "transform thickness {dir}/in.npy -o {dir}/t.npy",
       {{"in.npy", small_npy()}},
       {"t.npy"},
       "t.npy: exists (use --force"},
      {"topology graph with an output file",
       "topology graph {dir}/cube.npy -o {dir}/g.npy",
       {{"cube.npy", cube_npy()}},
       {},
       "topology graph writes no file (drop -o)"},
      {"topology graph with another adjacency than 26,6",
       "topology graph {dir}/cube.npy --adjacency 6,26",
       {{"cube.npy", cube_npy()}},
       {},
       "joins skeleton points by 26,6 adjacency (got --adjacency 6,26)"},
      {"topology graph with an unknown thinning method",
       "topology graph {dir}/cube.npy --method fast",
       {{"cube.npy", cube_npy()}},
       {},
       "--method 'fast' is not sequential or critical-kernel"},
      // --- zdg topology persistence (issue #39 item 5) -------------------------------------------
      {"topology persistence: an unknown filtration",
       "topology persistence {dir}/cube.npy --filtration height",
       {{"cube.npy", cube_npy()}},
       {},
       "--filtration 'height' is not values or dt"},
      {"topology persistence: a selection with the values filtration",
       "topology persistence {dir}/cube.npy --threshold 1",
       {{"cube.npy", cube_npy()}},
       {},
       "select the object of --filtration dt"},
      {"topology persistence: dt of an image without background",
       "topology persistence {dir}/full.npy --filtration dt",
       {{"full.npy",
         npy("{'descr': '|u1', 'fortran_order': False, 'shape': (3, 3), }", std::string(9, '\1'))}},
       {},
       "full.npy: signed distance: the image has no background point"},
      {"topology persistence: a NaN value",
       "topology persistence {dir}/nan.npy",
       {{"nan.npy", npy("{'descr': '<f8', 'fortran_order': False, 'shape': (1, 2), }",
                        std::string("\0\0\0\0\0\0\xf8\x7f\0\0\0\0\0\0\0\0", 16))}},
       {},
       "nan.npy: value nan at voxel 0 is not finite"},
      {"topology persistence: a 64-bit value past 2^53",
       "topology persistence {dir}/big.npy",
       {{"big.npy", npy("{'descr': '<i8', 'fortran_order': False, 'shape': (1, 2), }",
                        std::string("\x01\0\0\0\0\0\x20\0\0\0\0\0\0\0\0\0", 16))}},
       {},
       "big.npy: the 64-bit value at voxel 0 is 2^53 or more in magnitude"},
      {"topology betti --generators without an output",
       "topology betti {dir}/cube.npy --generators",
       {{"cube.npy", cube_npy()}},
       {},
       "--generators writes the cycles to -o FILE.ply"},
      {"topology betti --generators to another format",
       "topology betti {dir}/cube.npy --generators -o {dir}/c.npy",
       {{"cube.npy", cube_npy()}},
       {},
       "c.npy: the cycles are a .ply file (got '.npy')"},
      {"topology betti --generators with another adjacency",
       "topology betti {dir}/cube.npy --generators -o {dir}/c.ply --adjacency 6,26",
       {{"cube.npy", cube_npy()}},
       {},
       "the union of the closed voxels (--adjacency 26,6; got 6,26)"},
      {"topology betti --generators: existing output",
       "topology betti {dir}/cube.npy --generators -o {dir}/c.ply",
       {{"cube.npy", cube_npy()}},
       {"c.ply"},
       "c.ply: exists (use --force"},
      // --- zdg voxelize (issue #38) -------------------------------------------------------------
      {"voxelize a mesh with a non-finite coordinate",
       "voxelize {dir}/m.ply --h 0.5 -o {dir}/v.npy",
       {{"m.ply", ply_mesh("0 0 0\nnan 0 0\n0 1 0\n", "3 0 1 2\n", 3, 1)}},
       {},
       "not finite"},
      {"voxelize a mesh with a face using a vertex twice",
       "voxelize {dir}/m.ply --h 0.5 -o {dir}/v.npy",
       {{"m.ply", ply_mesh("0 0 0\n1 0 0\n0 1 0\n", "3 0 1 1\n", 3, 1)}},
       {},
       "uses vertex 1 twice (a degenerate face)"},
      {"voxelize a mesh with a vertex index out of range",
       "voxelize {dir}/m.ply --h 0.5 -o {dir}/v.npy",
       {{"m.ply", ply_mesh("0 0 0\n1 0 0\n0 1 0\n", "3 0 1 7\n", 3, 1)}},
       {},
       "out of range"},
      {"voxelize on a grid past --max-voxels",
       "voxelize {dir}/m.ply --h 1e-6 -o {dir}/v.npy",
       {{"m.ply", ply_mesh("0 0 0\n1 0 0\n0 1 0\n", "3 0 1 2\n", 3, 1)}},
       {},
       "exceeds the limit of 4294967296"},
      {"voxelize solid of a mesh that is not closed",
       "voxelize {dir}/m.ply --h 0.5 --mode solid -o {dir}/v.npy",
       {{"m.ply", ply_mesh("0 0 0\n1 0 0\n0 1 0\n", "3 0 1 2\n", 3, 1)}},
       {},
       "not closed: the edge between vertices 0 and 1"},
      {"voxelize with an unknown mode",
       "voxelize {dir}/m.ply --h 0.5 --mode 18 -o {dir}/v.npy",
       {{"m.ply", ply_mesh("0 0 0\n1 0 0\n0 1 0\n", "3 0 1 2\n", 3, 1)}},
       {},
       "--mode: voxelization mode '18' is not 6, 26, conservative or solid"},
      {"voxelize with a step that is not positive",
       "voxelize {dir}/m.ply --h -1 -o {dir}/v.npy",
       {{"m.ply", ply_mesh("0 0 0\n1 0 0\n0 1 0\n", "3 0 1 2\n", 3, 1)}},
       {},
       "--h: -1 is not positive"},
      {"voxelize a mesh that is not a .ply, .obj or .off",
       "voxelize {dir}/m.stl --h 0.5 -o {dir}/v.npy",
       {{"m.stl", "solid x\n"}},
       {},
       "zdg voxelize reads a .ply, .obj or .off mesh"},
      {"voxelize --winding of a surface mode",
       "voxelize {dir}/m.ply --h 0.5 --winding 0.5 -o {dir}/v.npy",
       {{"m.ply", ply_mesh("0 0 0\n1 0 0\n0 1 0\n", "3 0 1 2\n", 3, 1)}},
       {},
       "--winding 0.5: a threshold of the solid (--mode solid)"},
      {"voxelize --winding past its work bound",
       "voxelize {dir}/m.ply --h 0.0008 --mode solid --winding 0.5 -o {dir}/v.npy",
       {{"m.ply", ply_mesh("0 0 0\n1 0 0\n0 1 1\n", "3 0 1 2\n", 3, 1)}},
       {},
       "past the limit of"},
      {"voxelize an OBJ face with an index out of range",
       "voxelize {dir}/m.obj --h 0.5 -o {dir}/v.npy",
       {{"m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n"}},
       {},
       "m.obj:4: vertex index 4 out of range (3 vertices read)"},
      {"voxelize an OFF mesh with a non-finite coordinate",
       "voxelize {dir}/m.off --h 0.5 -o {dir}/v.npy",
       {{"m.off", "OFF\n3 1 0\n0 0 0\ninf 0 0\n0 1 0\n3 0 1 2\n"}},
       {},
       "m.off:4: 'inf' is not finite"},
      {"voxelize with an origin that is not X,Y,Z",
       "voxelize {dir}/m.ply --h 0.5 --origin 1,2 -o {dir}/v.npy",
       {{"m.ply", ply_mesh("0 0 0\n1 0 0\n0 1 0\n", "3 0 1 2\n", 3, 1)}},
       {},
       "--origin: '1,2' is not X,Y,Z"},
      // --- zdg dag, zdg render dag (issue #38 item 2) ------------------------------------------
      {"dag with an unknown kind",
       "dag {dir}/cube.npy --kind octree --json",
       {{"cube.npy", cube_npy()}},
       {},
       "--kind: voxel DAG kind 'octree': expected svo, dag or ssvdag"},
      {"dag of a mesh without --h",
       "dag {dir}/m.ply --json",
       {{"m.ply", ply_mesh("0 0 0\n1 0 0\n0 1 0\n", "3 0 1 2\n", 3, 1)}},
       {},
       "m.ply: a mesh needs the grid step --h"},
      {"dag of a volume with --h",
       "dag {dir}/cube.npy --h 0.5 --json",
       {{"cube.npy", cube_npy()}},
       {},
       "--h 0.5: the step of a mesh's voxelization"},
      {"dag with a ray of five numbers",
       "dag {dir}/cube.npy --ray 1,2,3,4,5 --json",
       {{"cube.npy", cube_npy()}},
       {},
       "--ray: '1,2,3,4,5' is not OX,OY,OZ,DX,DY,DZ[,DEN]"},
      {"dag with a ray that is not integers",
       "dag {dir}/cube.npy --ray 1,2,3,0.5,0,0 --json",
       {{"cube.npy", cube_npy()}},
       {},
       "--ray: "},
      {"dag with a ray of direction zero",
       "dag {dir}/cube.npy --ray 1,2,3,0,0,0 --json",
       {{"cube.npy", cube_npy()}},
       {},
       "digital ray: the direction is zero"},
      {"dag with a ray past the numerator bound",
       "dag {dir}/cube.npy --ray 1,2,3,1,0,0,9000000000000000 --json",
       {{"cube.npy", cube_npy()}},
       {},
       "digital ray: the denominator must lie in [1, 2^42]"},
      {"dag of a mesh with a slab that is not a multiple of 4",
       "dag {dir}/m.ply --h 0.5 --slab 6 --json",
       {{"m.ply", ply_mesh("0 0 0\n1 0 0\n0 1 0\n", "3 0 1 2\n", 3, 1)}},
       {},
       "--slab: 6 is not a positive multiple of 4"},
      {"dag of a mesh with a non-finite coordinate",
       "dag {dir}/m.ply --h 0.5 --json",
       {{"m.ply", ply_mesh("0 0 0\nnan 0 0\n0 1 0\n", "3 0 1 2\n", 3, 1)}},
       {},
       "not finite"},
      {"dag of a mesh with an origin that is not X,Y,Z",
       "dag {dir}/m.ply --h 0.5 --origin 1,2 --json",
       {{"m.ply", ply_mesh("0 0 0\n1 0 0\n0 1 0\n", "3 0 1 2\n", 3, 1)}},
       {},
       "--origin: '1,2' is not X,Y,Z"},
      {"render dag to a file that is not a .png",
       "render dag {dir}/cube.npy -o {dir}/p.jpg",
       {{"cube.npy", cube_npy()}},
       {},
       "p.jpg: the picture is a .png file"},
      {"render dag: existing output",
       "render dag {dir}/cube.npy -o {dir}/p.png",
       {{"cube.npy", cube_npy()}},
       {"p.png"},
       "p.png: exists (use --force"},
      {"render dag with a picture size below the minimum",
       "render dag {dir}/cube.npy -o {dir}/p.png --png-size 10x10",
       {{"cube.npy", cube_npy()}},
       {},
       "--png-size 10x10: picture size 10x10 (200x150 .. 8192x8192)"},
      {"converge --mpi without an MPI launcher (or in a zdg built without MPI)",
       "converge --shape ball:5 --estimator gauss-area --h 0.5 -o {dir}/o --mpi",
       {},
       {},
       "--mpi: "},
  };
}

// Every file under dir with its content and mode: what a run must not change.
std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string rel = fs::relative(e.path(), dir).string();
    if (e.is_directory()) {
      out[rel + "/"] = "";
      continue;
    }
    struct stat st {};
    ::stat(e.path().c_str(), &st);
    out[rel] = std::to_string(st.st_mode) + ":" + zdg::test::read_file(e.path());
  }
  return out;
}

TEST(CliContract, BadInputGivesOneLineExitTwoAndTouchesNothing) {
  for (const auto& c : bad_inputs()) {
    SCOPED_TRACE(c.what + ": zdg " + c.args);
    const fs::path dir = zdg::test::scratch_dir("contract");
    for (const auto& [name, bytes] : c.files) {
      if (name.back() == '/') {
        fs::create_directories(dir / name);
        continue;
      }
      fs::create_directories((dir / name).parent_path());
      std::ofstream(dir / name, std::ios::binary) << bytes;
    }
    for (const auto& name : c.existing) {
      fs::create_directories((dir / name).parent_path());
      std::ofstream(dir / name, std::ios::binary) << "keep";
      fs::permissions(dir / name,
                      fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
    }
    const auto before = snapshot(dir);
    std::string args = c.args;
    for (std::size_t at; (at = args.find("{dir}")) != std::string::npos;) {
      args.replace(at, 5, dir.string());
    }
    for (std::size_t at; (at = args.find("{rel}")) != std::string::npos;) {
      args.replace(at, 5, fs::relative(dir).string());
    }
    const auto run = zdg::test::run_zdg(args);
    EXPECT_EQ(run.status, 2) << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_FALSE(run.err.empty() || run.err.back() != '\n') << run.err;
    EXPECT_EQ(run.err.rfind("zdg: ", 0), 0u) << run.err;
    EXPECT_NE(run.err.find(c.message), std::string::npos)
        << "expected '" << c.message << "' in: " << run.err;
    EXPECT_EQ(snapshot(dir), before) << "files created or changed";
    fs::remove_all(dir);
  }
}

// Output that cannot be written (a full disk) is an error too, not a silent exit 0.
TEST(CliContract, StdoutThatCannotBeWrittenIsAnError) {
  const fs::path dir = zdg::test::scratch_dir("contract");
  const std::string cmd = std::string("'") + zdg::test::cli_path() +
                          "' cf 415/93 --json >/dev/full 2>'" + (dir / "err").string() + "'";
  const int raw = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(raw));
  EXPECT_EQ(WEXITSTATUS(raw), 2);
  const std::string err = zdg::test::read_file(dir / "err");
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  EXPECT_NE(err.find("zdg: cannot write the output to stdout"), std::string::npos) << err;
  fs::remove_all(dir);
}

// Issue #18, reproducer 2: an unwritable output folder (meaningless for root, who may write
// anywhere: skipped then).
TEST(CliContract, UnwritableOutputFolderIsOneLine) {
  if (::geteuid() == 0) GTEST_SKIP() << "root writes into read-only folders";
  const fs::path dir = zdg::test::scratch_dir("contract");
  fs::create_directories(dir / "ro");
  fs::permissions(dir / "ro", fs::perms::owner_read | fs::perms::owner_exec);
  const auto r = zdg::test::run_zdg("hull disc 0 0 5 -o " + (dir / "ro" / "h.txt").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("is not writable"), std::string::npos) << r.err;
  fs::permissions(dir / "ro", fs::perms::owner_all);
  fs::remove_all(dir);
}

// Issue #41, 11 and 14: an output that reaches the file-size limit (ulimit -f) is one line,
// zdg's, naming the user's file: not libpng's own line, not the staging file.
TEST(CliContract, FileSizeLimitIsOneLineNamingTheOutput) {
  const fs::path dir = zdg::test::scratch_dir("contract");
  std::ofstream(dir / "cube.npy", std::ios::binary) << cube_npy();
  const std::string d = dir.string();
  const std::pair<std::string, std::string> cases[] = {
      {"surface " + d + "/cube.npy --png " + d + "/pic.png --quiet", d + "/pic.png"},
      {"surface " + d + "/cube.npy -o " + d + "/mesh.obj --quiet", d + "/mesh.obj"},
      {"converge --shape ball:9 --estimator gauss-area --h 1:0.5:4 --quiet --no-plot -o " + d +
           "/run",
       d + "/run/"}, // results.csv or summary.json, whichever passes the limit first
  };
  for (const auto& [args, output] : cases) {
    SCOPED_TRACE(args);
    const std::string cmd = "ulimit -f 1 && '" + std::string(zdg::test::cli_path()) + "' " + args +
                            " >/dev/null 2>'" + d + "/err'";
    const int raw = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(raw));
    EXPECT_EQ(WEXITSTATUS(raw), 2);
    const std::string err = zdg::test::read_file(dir / "err");
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    EXPECT_EQ(err.rfind("zdg: ", 0), 0u) << err;
    EXPECT_NE(err.find(output), std::string::npos) << err;
    EXPECT_EQ(err.find("zdg-tmp"), std::string::npos) << err;
    fs::remove(dir / "err");
    std::vector<std::string> left;
    for (const auto& e : fs::directory_iterator(dir)) left.push_back(e.path().filename());
    EXPECT_EQ(left, std::vector<std::string>{"cube.npy"}) << "nothing written, nothing left";
  }
  fs::remove_all(dir);
}

// Issue #41, 10: converge with an immutable summary.json (chattr +i, where the file system has
// it; root) leaves results.csv as it was.
TEST(CliContract, AnImmutableSecondOutputLeavesTheFirstAsItWas) {
  const fs::path dir = zdg::test::scratch_dir("contract");
  fs::create_directories(dir / "out");
  std::ofstream(dir / "out" / "results.csv") << "old results";
  std::ofstream(dir / "out" / "summary.json") << "old summary";
  const int fd = ::open((dir / "out" / "summary.json").c_str(), O_RDONLY);
  ASSERT_GE(fd, 0);
  int flags = 0;
  if (::ioctl(fd, FS_IOC_GETFLAGS, &flags) != 0 ||
      (flags |= FS_IMMUTABLE_FL, ::ioctl(fd, FS_IOC_SETFLAGS, &flags)) != 0) {
    ::close(fd);
    fs::remove_all(dir);
    GTEST_SKIP() << "no chattr +i here";
  }
  const auto r = zdg::test::run_zdg("converge --shape ball:5 --estimator gauss-area --h 1:0.5:3 "
                                    "--no-plot --force -o " +
                                    (dir / "out").string());
  flags &= ~FS_IMMUTABLE_FL;
  ::ioctl(fd, FS_IOC_SETFLAGS, &flags);
  ::close(fd);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("summary.json: is immutable"), std::string::npos) << r.err;
  EXPECT_EQ(zdg::test::read_file(dir / "out" / "results.csv"), "old results");
  EXPECT_EQ(zdg::test::read_file(dir / "out" / "summary.json"), "old summary");
  fs::remove_all(dir);
}

// Issue #41, 14: a killed run's staging file is removed by the next run into its folder; the
// staging file of a live process (here this test's) is left alone.
TEST(CliContract, TheNextRunRemovesStagingFilesOfKilledRuns) {
  const fs::path dir = zdg::test::scratch_dir("contract");
  const pid_t dead = ::fork();
  ASSERT_GE(dead, 0);
  if (dead == 0) ::_exit(0);
  ASSERT_EQ(::waitpid(dead, nullptr, 0), dead);
  const fs::path stale = dir / (".summary.json.zdg-tmp-" + std::to_string(dead) + "-0");
  const fs::path live = dir / (".h.txt.zdg-tmp-" + std::to_string(::getpid()) + "-0");
  std::ofstream(stale) << "stale";
  std::ofstream(live) << "in progress";
  const auto r = zdg::test::run_zdg("hull disc 0 0 5 -o " + (dir / "h.txt").string());
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_EQ(zdg::test::read_file(live), "in progress");
  EXPECT_TRUE(fs::exists(dir / "h.txt"));
  fs::remove_all(dir);
}

// The answers of issue #18's first reproducer: integer and rational text is decimal whatever
// its leading zeros, on every path into zdg.
struct DecimalAnswer {
  std::string args, same_as; // `zdg args` prints what `zdg same_as` prints
};

TEST(CliContract, LeadingZerosAreDecimalOnEveryPath) {
  const fs::path dir = zdg::test::scratch_dir("contract");
  std::ofstream(dir / "p010.txt") << "010 0\n0 010\n0 0\n";
  std::ofstream(dir / "p10.txt") << "10 0\n0 10\n0 0\n";
  std::ofstream(dir / "h010.txt") << "01 0 010\n-1 0 0\n0 1 010/01\n0 -1 0.0\n";
  std::ofstream(dir / "h10.txt") << "1 0 10\n-1 0 0\n0 1 10\n0 -1 0\n";
  std::ofstream(dir / "c010.txt") << "010 010 0011\n";
  std::ofstream(dir / "c10.txt") << "10 10 0011\n";
  const std::string d = dir.string();
  const DecimalAnswer cases[] = {
      {"cf 010/3 --json", "cf 10/3 --json"},
      {"cf 09/08 --json", "cf 9/8 --json"},
      {"floor-sum 010 03 01 00 --json", "floor-sum 10 3 1 0 --json"},
      {"christoffel 010/03 --json", "christoffel 10/3 --json"},
      {"dss subsegment 03 07 00 00 010 --json", "dss subsegment 3 7 0 0 10 --json"},
      {"hull disc 0 0 010 --json", "hull disc 0 0 10 --json"},
      {"hull disc 0.50 00 010.0 --json", "hull disc 1/2 0 10 --json"},
      {"hull points " + d + "/p010.txt --json", "hull points " + d + "/p10.txt --json"},
      {"hull halfplanes " + d + "/h010.txt --json", "hull halfplanes " + d + "/h10.txt --json"},
      {"dss recognize " + d + "/c010.txt --json", "dss recognize " + d + "/c10.txt --json"},
      {"hull disc 0 0 1000 --max-vertices 0100", "hull disc 0 0 1000 --max-vertices 100"},
  };
  for (const auto& c : cases) {
    const auto a = zdg::test::run_zdg(c.args), b = zdg::test::run_zdg(c.same_as);
    EXPECT_EQ(a.status, b.status) << c.args << ": " << a.err;
    EXPECT_EQ(a.out, b.out) << c.args;
    EXPECT_EQ(a.err, b.err) << c.args;
  }
  const auto cf = zdg::test::run_zdg("cf 010/3 --json");
  ASSERT_EQ(cf.status, 0) << cf.err;
  const auto j = nlohmann::json::parse(cf.out);
  EXPECT_EQ(j["p"], "10"); // was "8" (octal), issue #18
  EXPECT_EQ(j["q"], "3");
  fs::remove_all(dir);
}

} // namespace
