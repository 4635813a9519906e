// zdg topology persistence INPUT [--filtration values|dt] [--json]: the persistence diagrams of
// the sublevel filtration of a 2D or 3D image's cubical complex (kernel/topology/
// cubical_persistence.hpp, GUDHI's CubicalComplex(top_dimensional_cells=...) convention).
//   values   the volume's physical values (any dtype; NIfTI scaling applied); no selection option
//   dt       the signed squared Euclidean distance of the object (value != 0, or the selection
//            options): -DT inside, +DT of the background outside
// --json prints {"diagrams": [[[birth, death], ...], ...], ...} (death null when essential).
#include <zdg/arith/error.hpp>
#include <zdg/cli/commands.hpp>
#include <zdg/cli/volume_input.hpp>
#include <zdg/kernel/topology/cubical_persistence.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace zdg::cli {

namespace {

struct PersistenceArgs {
  VolumeInputArgs in;
  std::string filtration = "values";
  unsigned threads = 0;
  bool json = false, quiet = false;
};

// The physical values of the volume, exact in double (a 64-bit integer of magnitude 2^53 or
// more is refused: 2^53 + 1 reads as 2^53).
Image<double> volume_values(const PersistenceArgs& a) {
  const ScalarVolume v = load_volume(a.in, 0, !a.quiet).volume;
  const bool wide = v.array.dtype == DType::I64 || v.array.dtype == DType::U64;
  constexpr double exact = 9007199254740992.0; // 2^53
  Image<double> out(v.domain());
  for (std::int64_t i = 0; i < out.size(); ++i) {
    const double x = v.value(i);
    if (!std::isfinite(x)) {
      throw InvalidArgument(a.in.path + ": value " + std::to_string(x) + " at voxel " +
                            std::to_string(i) + " is not finite");
    }
    if (wide && std::abs(v.array.get_double(i)) >= exact) {
      throw InvalidArgument(a.in.path + ": the 64-bit value at voxel " + std::to_string(i) +
                            " is 2^53 or more in magnitude (not exact as a filtration value)");
    }
    out[i] = x;
  }
  return out;
}

Image<double> dt_values(const PersistenceArgs& a) {
  const Image<std::uint8_t> mask = load_object(a.in, 0, a.threads, !a.quiet).mask;
  try {
    return signed_squared_distance(mask, a.threads);
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(a.in.path + ": " + e.what());
  }
}

void run_persistence(const PersistenceArgs& a) {
  if (a.filtration != "values" && a.filtration != "dt") {
    throw InvalidArgument("--filtration '" + a.filtration + "' is not values or dt");
  }
  if (a.filtration == "values" && has_selection(a.in)) {
    throw InvalidArgument("--threshold, --range, --label and --invert select the object of "
                          "--filtration dt (the values filtration uses every voxel)");
  }
  const Image<double> values = a.filtration == "dt" ? dt_values(a) : volume_values(a);
  const auto t0 = std::chrono::steady_clock::now();
  const PersistenceDiagrams d = cubical_persistence(values);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (a.json) {
    nlohmann::json diagrams = nlohmann::json::array();
    for (const auto& g : d.diagrams) {
      nlohmann::json pairs = nlohmann::json::array();
      for (const auto& p : g) {
        pairs.push_back(
            {p.birth, std::isinf(p.death) ? nlohmann::json(nullptr) : nlohmann::json(p.death)});
      }
      diagrams.push_back(std::move(pairs));
    }
    print_json({{"command", "persistence"},
                {"input", a.in.path},
                {"filtration", a.filtration},
                {"diagrams", diagrams},
                {"seconds", secs}});
    return;
  }
  std::cout << "zdg topology persistence (" << a.filtration << "): " << values.dim() << "D, "
            << values.size() << " voxels (" << secs << " s)\n";
  for (std::size_t k = 0; k < d.diagrams.size(); ++k) {
    auto g = d.diagrams[k];
    std::cout << "dimension " << k << ": " << g.size() << " pairs";
    // The most persistent first (essential classes lead), at most 10.
    std::stable_sort(g.begin(), g.end(), [](const PersistencePair& x, const PersistencePair& y) {
      return x.death - x.birth > y.death - y.birth;
    });
    for (std::size_t i = 0; i < g.size() && i < 10; ++i) {
      std::cout << (i == 0 ? ", longest " : " ") << '[' << g[i].birth << ", ";
      if (std::isinf(g[i].death)) {
        std::cout << "inf";
      } else {
        std::cout << g[i].death;
      }
      std::cout << ')';
    }
    std::cout << '\n';
  }
}

} // namespace

void add_topology_persistence_command(CLI::App& topology) {
  auto args = std::make_shared<PersistenceArgs>();
  auto* sub = topology.add_subcommand(
      "persistence", "persistence diagrams of the sublevel filtration of the image's cubical "
                     "complex (voxels as top cells, GUDHI's convention)");
  add_volume_input_options(*sub, args->in, {.selection = true, .spacing = false});
  sub->add_option("--filtration", args->filtration,
                  "values (the voxels' values) or dt (signed squared Euclidean distance of "
                  "the object: -DT inside, +DT of the background outside)")
      ->capture_default_str();
  sub->add_option("--threads", args->threads, "worker threads for dt (0 = all cores)")
      ->capture_default_str();
  sub->add_flag("--json", args->json,
                "print {\"diagrams\": [[[birth, death], ...], ...]} per dimension 0..d-1 "
                "(death null for an essential class)");
  sub->add_flag("--quiet", args->quiet, "no progress on stderr");
  sub->callback([args] { run_persistence(*args); });
}

} // namespace zdg::cli
