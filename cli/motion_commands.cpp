// zdg motion check [INPUT] --rotation A,B,C | --quaternion W,X,Y,Z, zdg motion apply INPUT ...:
// digitized rigid motions (kernel/images/rigid_motion.hpp). Without INPUT, `check` certifies
// whether the digitized rotation is a bijection of Z^2 (with a witness when it is not); with
// INPUT it applies the motion to the object and reports its injectivity on the object (a
// colliding pair), and the topology before and after (Betti numbers under the default pair,
// well-composedness). `apply` writes D(X) through an OutputSet.
#include <zdg/arith/error.hpp>
#include <zdg/arith/rational.hpp>
#include <zdg/cli/commands.hpp>
#include <zdg/cli/volume_input.hpp>
#include <zdg/kernel/images/rigid_motion.hpp>
#include <zdg/kernel/io/output_files.hpp>
#include <zdg/kernel/io/volume_io.hpp>
#include <zdg/kernel/topology/betti_numbers.hpp>
#include <zdg/kernel/topology/well_composed.hpp>

#include <chrono>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace zdg::cli {

namespace {

struct MotionArgs {
  MotionArgs() { in.physical = false; }
  VolumeInputArgs in;
  bool has_input = false;
  std::string rotation, quaternion, center, translation, output;
  bool expand = false, json = false, force = false;
  unsigned threads = 0;
};

std::vector<BigInt> integers(const std::string& text, std::size_t count, const char* option) {
  const auto parts = split_commas(text);
  if (parts.size() != count) {
    throw InvalidArgument(std::string(option) + " " + text + ": expected " + std::to_string(count) +
                          " integers separated by commas");
  }
  std::vector<BigInt> v;
  for (const auto& p : parts) v.push_back(parse_integer<BigInt>(p));
  return v;
}

std::vector<Rational<BigInt>> rationals(const std::string& text, int dim, const char* option) {
  const auto parts = split_commas(text);
  if (static_cast<int>(parts.size()) != dim) {
    throw InvalidArgument(std::string(option) + " " + text + ": expected " + std::to_string(dim) +
                          " numbers (x,y" + (dim == 3 ? ",z" : "") + ") for a " +
                          std::to_string(dim) + "D motion");
  }
  std::vector<Rational<BigInt>> v;
  for (const auto& p : parts) v.push_back(parse_rational<BigInt>(p));
  return v;
}

std::string rational_text(const Rational<BigInt>& r) {
  return r.den() == 1 ? to_string(r.num()) : to_string(r.num()) + "/" + to_string(r.den());
}

nlohmann::json rationals_json(const std::vector<Rational<BigInt>>& v) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& r : v) j.push_back(rational_text(r));
  return j;
}

template <class Seq>
nlohmann::json strings_json(const Seq& v) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& x : v) {
    if constexpr (std::is_same_v<std::decay_t<decltype(x)>, BigInt>) {
      j.push_back(to_string(x));
    } else {
      j.push_back(std::to_string(x));
    }
  }
  return j;
}

struct Motion {
  RigidMotion rotation, motion;
  std::vector<Rational<BigInt>> center, translation;
  nlohmann::json json;
};

// The rotation of --rotation or --quaternion; the center is the given one, else `default_center`.
Motion make_motion(const MotionArgs& a, const std::vector<Rational<BigInt>>& default_center) {
  if (a.rotation.empty() == a.quaternion.empty()) {
    throw InvalidArgument("motion: give exactly one of --rotation A,B,C (2D) and --quaternion "
                          "W,X,Y,Z (3D)");
  }
  Motion m;
  if (!a.rotation.empty()) {
    const auto t = integers(a.rotation, 3, "--rotation");
    m.rotation = rotation_2d(t[0], t[1], t[2]);
    m.json["rotation"] = strings_json(t);
  } else {
    const auto q = integers(a.quaternion, 4, "--quaternion");
    m.rotation = rotation_3d(q[0], q[1], q[2], q[3]);
    m.json["quaternion"] = strings_json(q);
  }
  const int dim = m.rotation.dim;
  m.center = a.center.empty() ? default_center : rationals(a.center, dim, "--center");
  if (static_cast<int>(m.center.size()) != dim) {
    throw InvalidArgument("motion: a " + std::to_string(dim) + "D motion for a " +
                          std::to_string(m.center.size()) + "D input");
  }
  m.translation = a.translation.empty()
                      ? std::vector<Rational<BigInt>>(static_cast<std::size_t>(dim))
                      : rationals(a.translation, dim, "--translation");
  m.motion = motion_about(m.rotation, m.center, m.translation);
  nlohmann::json matrix = nlohmann::json::array();
  for (int k = 0; k < dim; ++k) {
    nlohmann::json row = nlohmann::json::array();
    for (int j = 0; j < dim; ++j) {
      row.push_back(
          to_string(m.rotation.m[static_cast<std::size_t>(k)][static_cast<std::size_t>(j)]));
    }
    matrix.push_back(row);
  }
  m.json["dim"] = dim;
  m.json["matrix"] = matrix;
  m.json["denominator"] = to_string(m.rotation.n);
  m.json["center"] = rationals_json(m.center);
  m.json["translation"] = rationals_json(m.translation);
  return m;
}

nlohmann::json lattice_json(const RigidMotion& motion) {
  const LatticeBijectivity b = lattice_bijectivity(motion);
  nlohmann::json j = {
      {"bijective", b.bijective}, {"method", b.method}, {"period", to_string(b.period)}};
  if (b.collision) {
    j["witness"] = {{"points", nlohmann::json::array({strings_json((*b.collision)[0]),
                                                      strings_json((*b.collision)[1])})},
                    {"image", strings_json(*b.collision_image)},
                    {"hole", b.hole ? strings_json(*b.hole) : nlohmann::json(nullptr)}};
  } else {
    j["witness"] = nullptr;
  }
  return j;
}

// The domain's centre, (lower + upper) / 2 per axis, geometric order.
std::vector<Rational<BigInt>> domain_center(const Domain& d) {
  std::vector<Rational<BigInt>> c;
  for (int k = d.dim() - 1; k >= 0; --k) {
    c.emplace_back(BigInt(d.lower(k)) + BigInt(d.upper(k)), BigInt(2));
  }
  return c;
}

nlohmann::json topology_json(const Image<std::uint8_t>& set) {
  const BettiNumbers b = betti_numbers(set, default_adjacency_pair(set.dim()), 0);
  const WellComposedness w = well_composedness(set);
  nlohmann::json betti = nlohmann::json::array();
  for (int k = 0; k < set.dim(); ++k)
    betti.push_back(std::to_string(b.b[static_cast<std::size_t>(k)]));
  nlohmann::json j = {
      {"betti", betti}, {"euler", std::to_string(b.euler)}, {"well_composed", w.well_composed}};
  if (!w.well_composed) {
    std::vector<std::int64_t> corner(w.corner.rbegin(), w.corner.rend());
    j["critical"] = {{"corner", strings_json(corner)}, {"configuration", w.configuration}};
  }
  return j;
}

void run_check(const MotionArgs& a) {
  const auto t0 = std::chrono::steady_clock::now();
  if (!a.has_input) {
    const int dim = a.rotation.empty() ? 3 : 2;
    const Motion m = make_motion(a, std::vector<Rational<BigInt>>(static_cast<std::size_t>(dim)));
    if (m.rotation.dim != 2) {
      throw InvalidArgument("motion check --quaternion: the bijectivity certificate is for Z^2; "
                            "give INPUT to check the motion on a 3D object");
    }
    nlohmann::json j = m.json;
    j["command"] = "motion check";
    j.update(lattice_json(m.motion));
    j["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (a.json) {
      print_json(j);
      return;
    }
    std::cout << "zdg motion check: the digitized rotation is "
              << (j["bijective"].get<bool>() ? "" : "not ") << "a bijection of Z^2 (period "
              << j["period"].get<std::string>() << ", by the " << j["method"].get<std::string>()
              << ")";
    if (!j["witness"].is_null()) {
      const auto& w = j["witness"];
      std::cout << "; (" << w["points"][0][0].get<std::string>() << ", "
                << w["points"][0][1].get<std::string>() << ") and ("
                << w["points"][1][0].get<std::string>() << ", "
                << w["points"][1][1].get<std::string>() << ") go to ("
                << w["image"][0].get<std::string>() << ", " << w["image"][1].get<std::string>()
                << ")";
    }
    std::cout << "\n";
    return;
  }
  const LoadedObject obj = load_object(a.in, 0, a.threads);
  const Motion m = make_motion(a, domain_center(obj.mask.domain()));
  const MotionOnImage r = apply_motion(obj.mask, m.motion, true);
  nlohmann::json j = m.json;
  j["command"] = "motion check";
  j["input"] = obj.json;
  j["points"] = std::to_string(r.points);
  j["images"] = std::to_string(r.images);
  j["bijective"] = r.points == r.images;
  if (r.collision) {
    j["witness"] = {{"points", nlohmann::json::array({strings_json((*r.collision)[0]),
                                                      strings_json((*r.collision)[1])})},
                    {"image", strings_json(r.collision_image)}};
  } else {
    j["witness"] = nullptr;
  }
  const nlohmann::json before = topology_json(obj.mask), after = topology_json(r.image);
  j["topology"] = {{"input", before}, {"image", after}};
  j["topology_preserved"] = before["betti"] == after["betti"];
  if (m.motion.dim == 2) j["lattice"] = lattice_json(m.motion);
  j["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (a.json) {
    print_json(j);
    return;
  }
  std::cout << "zdg motion check: " << r.points << " points, " << r.images << " images ("
            << (r.points == r.images ? "injective" : "not injective") << "), Betti";
  for (const auto& v : before["betti"]) std::cout << ' ' << v.get<std::string>();
  std::cout << " ->";
  for (const auto& v : after["betti"]) std::cout << ' ' << v.get<std::string>();
  std::cout << (j["topology_preserved"].get<bool>() ? " (preserved)" : " (changed)") << "\n";
}

void run_apply(const MotionArgs& a) {
  const VolumeFormat format = volume_format_of(a.output);
  check_not_input(a.in.path, a.output);
  OutputSet out(a.force ? Existing::replace : Existing::refuse);
  const std::string staged = out.add(a.output).string();
  const auto t0 = std::chrono::steady_clock::now();
  const LoadedObject obj = load_object(a.in, 0, a.threads);
  const Motion m = make_motion(a, domain_center(obj.mask.domain()));
  const MotionOnImage r = apply_motion(obj.mask, m.motion, a.expand);
  if ((format == VolumeFormat::pgm && r.image.dim() != 2) ||
      (format == VolumeFormat::vol && r.image.dim() != 3)) {
    throw IoError(a.output + ": a " + lower_extension(a.output) + " image is " +
                  (format == VolumeFormat::pgm ? "2D" : "3D") + " and the result is " +
                  std::to_string(r.image.dim()) + "D");
  }
  VolumeWriteOptions wo;
  wo.format = format;
  write_volume(staged, make_scalar_volume(r.image), wo);
  out.commit();
  const Domain& d = r.image.domain();
  std::vector<std::int64_t> origin(d.lowers().rbegin(), d.lowers().rend());
  nlohmann::json j = m.json;
  j["command"] = "motion apply";
  j["input"] = obj.json;
  j["output"] = a.output;
  j["shape"] = d.extents();
  j["origin"] = strings_json(origin);
  j["points"] = std::to_string(r.points);
  j["images"] = std::to_string(r.images);
  j["bijective"] = r.points == r.images;
  j["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (a.json) {
    print_json(j);
    return;
  }
  std::cout << "zdg motion apply: " << r.points << " points -> " << r.images << " voxels"
            << (r.points == r.images ? "" : " (collisions)") << " -> " << a.output << "\n";
}

void add_motion_options(CLI::App& sub, MotionArgs& args) {
  sub.add_option("--rotation", args.rotation,
                 "2D rotation of a Pythagorean triple A,B,C (A^2 + B^2 = C^2): cos = A/C, "
                 "sin = B/C");
  sub.add_option("--quaternion", args.quaternion,
                 "3D rotation of the integer quaternion W,X,Y,Z (R = M / (W^2+X^2+Y^2+Z^2))");
  sub.add_option("--center", args.center,
                 "center of the rotation, x,y[,z] (integers, fractions p/q or decimals); "
                 "default: the domain's centre, or the origin without INPUT");
  sub.add_option("--translation", args.translation,
                 "translation after the rotation, x,y[,z] (rationals; default 0)");
  sub.add_option("--threads", args.threads, "worker threads, 0..1024 (0 = all cores)")
      ->check(CLI::Range(0u, 1024u))
      ->capture_default_str();
  sub.add_flag("--json", args.json, "print a JSON summary on stdout");
}

} // namespace

void add_motion_commands(CLI::App& app, Context& /*ctx*/) {
  auto* cmd = app.add_subcommand(
      "motion", "Digitized rigid motions: D(p) = round(R (p - center) + center + translation)");
  cmd->require_subcommand(1);
  {
    auto args = std::make_shared<MotionArgs>();
    auto* sub = cmd->add_subcommand(
        "check", "Without INPUT: whether the digitized rotation is a bijection of Z^2, with a "
                 "witness; with INPUT: its injectivity on the object and the topology before "
                 "and after");
    add_volume_input_options(*sub, args->in, VolumeOptionSet{true, false});
    sub->get_option("INPUT")->required(false);
    add_motion_options(*sub, *args);
    sub->callback([args, sub] {
      args->has_input = sub->get_option("INPUT")->count() > 0;
      run_check(*args);
    });
  }
  {
    auto args = std::make_shared<MotionArgs>();
    auto* sub = cmd->add_subcommand(
        "apply", "D(X) for the object X of INPUT, written as a 0/1 uint8 volume (collisions "
                 "and holes as the motion makes them)");
    add_volume_input_options(*sub, args->in, VolumeOptionSet{true, false});
    add_motion_options(*sub, *args);
    sub->add_option("-o,--output", args->output,
                    "output volume, uint8 0/1 (.npy, .nii, .nii.gz, .vol, .pgm)")
        ->required();
    sub->add_flag("--expand", args->expand,
                  "grow the domain to hold every image (its lower corner: \"origin\")");
    sub->add_flag("--force", args->force, "replace the output file if it exists");
    sub->callback([args] {
      args->has_input = true;
      run_apply(*args);
    });
  }
}

} // namespace zdg::cli
