// zdg csg union|intersection|difference|symmetric-difference A B -o OUT, zdg csg complement A -o
// OUT: Boolean operations on binary volumes (kernel/images/csg.hpp) read by the volume loader
// (any format; the object is value != 0), the result written as 0/1 uint8 in the output's format
// through an OutputSet, with its voxels and Betti numbers (kernel/topology/betti_numbers.hpp)
// and those of the inputs.
#include <zdg/arith/error.hpp>
#include <zdg/cli/commands.hpp>
#include <zdg/cli/volume_input.hpp>
#include <zdg/kernel/images/csg.hpp>
#include <zdg/kernel/images/object_selection.hpp>
#include <zdg/kernel/io/output_files.hpp>
#include <zdg/kernel/io/volume_io.hpp>
#include <zdg/kernel/topology/betti_numbers.hpp>

#include <chrono>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace zdg::cli {

namespace {

struct CsgArgs {
  std::string a, b, output, adjacency;
  unsigned threads = 0;
  bool json = false, force = false;
};

Image<std::uint8_t> read_binary(const std::string& path, unsigned threads) {
  VolumeInputArgs in;
  in.path = path;
  in.physical = false;
  return select_object(load_volume(in, 0).volume, ObjectSelection{}, threads).mask;
}

nlohmann::json topology_json(const Image<std::uint8_t>& set, const AdjacencyPair& pair,
                             unsigned threads) {
  std::int64_t voxels = 0;
  for (auto x : set.values()) voxels += x != 0;
  const BettiNumbers b = betti_numbers(set, pair, threads);
  nlohmann::json betti = nlohmann::json::array();
  for (int k = 0; k < pair.dim; ++k)
    betti.push_back(std::to_string(b.b[static_cast<std::size_t>(k)]));
  return {{"voxels", std::to_string(voxels)},
          {"components", std::to_string(b.b[0])},
          {"euler", std::to_string(b.euler)},
          {"betti", betti}};
}

void run(const CsgArgs& a, const std::string& name, bool binary) {
  // The output is checked before any work: its format, not an input, not existing unless --force.
  const VolumeFormat format = volume_format_of(a.output);
  check_not_input(a.a, a.output);
  if (binary) check_not_input(a.b, a.output);
  OutputSet out(a.force ? Existing::replace : Existing::refuse);
  const std::string staged = out.add(a.output).string();
  const auto t0 = std::chrono::steady_clock::now();
  const Image<std::uint8_t> x = read_binary(a.a, a.threads);
  Image<std::uint8_t> y;
  if (binary) y = read_binary(a.b, a.threads);
  const AdjacencyPair pair = a.adjacency.empty() ? default_adjacency_pair(x.dim())
                                                 : parse_adjacency_pair(a.adjacency, x.dim());
  Image<std::uint8_t> r;
  if (!binary) {
    r = csg_complement(x, a.threads);
  } else {
    CsgOperation op = CsgOperation::union_of;
    if (name == "intersection") op = CsgOperation::intersection;
    if (name == "difference") op = CsgOperation::difference;
    if (name == "symmetric-difference") op = CsgOperation::symmetric_difference;
    r = csg(op, x, y, a.threads);
  }
  if ((format == VolumeFormat::pgm && r.dim() != 2) ||
      (format == VolumeFormat::vol && r.dim() != 3)) {
    throw IoError(a.output + ": a " + lower_extension(a.output) + " image is " +
                  (format == VolumeFormat::pgm ? "2D" : "3D") + " and the result is " +
                  std::to_string(r.dim()) + "D");
  }
  VolumeWriteOptions wo;
  wo.format = format;
  write_volume(staged, make_scalar_volume(r), wo);
  out.commit();
  nlohmann::json result = topology_json(r, pair, a.threads);
  nlohmann::json inputs = nlohmann::json::array();
  auto input_json = [&](const std::string& path, const Image<std::uint8_t>& set) {
    nlohmann::json j = {{"path", path}};
    j.update(topology_json(set, pair, a.threads));
    return j;
  };
  inputs.push_back(input_json(a.a, x));
  if (binary) inputs.push_back(input_json(a.b, y));
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (a.json) {
    nlohmann::json j = {{"command", "csg " + name}, {"inputs", inputs},
                        {"output", a.output},       {"shape", r.domain().extents()},
                        {"adjacency", pair.name()}, {"seconds", secs}};
    j.update(result);
    print_json(j);
    return;
  }
  std::cout << "zdg csg " << name << ": " << result["voxels"].get<std::string>() << " voxels, "
            << result["components"].get<std::string>() << " components, Betti";
  for (const auto& v : result["betti"]) std::cout << ' ' << v.get<std::string>();
  std::cout << " (" << pair.name() << ") -> " << a.output << " (" << secs << " s)\n";
}

} // namespace

void add_csg_commands(CLI::App& app, Context& /*ctx*/) {
  auto* cmd = app.add_subcommand(
      "csg", "Boolean operations on binary volumes (object = value != 0), with the Betti numbers");
  cmd->require_subcommand(1);
  struct Spec {
    const char* name;
    const char* help;
    bool binary;
  };
  static const Spec specs[] = {
      {"union", "A or B", true},
      {"intersection", "A and B", true},
      {"difference", "A and not B", true},
      {"symmetric-difference", "A xor B", true},
      {"complement", "not A, in A's box", false},
  };
  for (const auto& s : specs) {
    auto args = std::make_shared<CsgArgs>();
    auto* sub = cmd->add_subcommand(s.name, s.help);
    sub->add_option("A", args->a, "input volume (.npy, .nii, .vol, .pgm, ...)")->required();
    if (s.binary) {
      sub->add_option("B", args->b, "second input volume, of A's shape")->required();
    }
    sub->add_option("-o,--output", args->output,
                    "output volume, uint8 0/1 (.npy, .nii, .nii.gz, .vol, .pgm)")
        ->required();
    sub->add_option("--adjacency", args->adjacency,
                    "adjacency pair of the Betti numbers: 8,4 or 4,8 (2D); 26,6, 6,26, 18,6, "
                    "6,18 (3D); default 8,4 / 26,6");
    sub->add_option("--threads", args->threads, "worker threads, 0..1024 (0 = all cores)")
        ->check(CLI::Range(0u, 1024u))
        ->capture_default_str();
    sub->add_flag("--force", args->force, "replace the output file if it exists");
    sub->add_flag("--json", args->json, "print a JSON summary on stdout");
    const std::string name = s.name;
    const bool binary = s.binary;
    sub->callback([args, name, binary] { run(*args, name, binary); });
  }
}

} // namespace zdg::cli
