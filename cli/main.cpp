// zdg: the command line of the zdg kernel. See cli/commands.hpp.
//
// The contract with the user (tests/cli/contract_test.cpp checks it): whatever
// the input, the program ends with a status, never an abort. Bad input or a refusal by the
// environment prints one line "zdg: ..." on stderr and exits with 2: zdg::Error, CLI11's
// parse errors, and the standard exceptions that mean the same (std::system_error and
// std::filesystem::filesystem_error: a path or a thread the system refused; std::bad_alloc
// and std::length_error: out of memory; std::out_of_range and std::invalid_argument: text
// that a standard conversion refused). Anything else is a bug of zdg: one line
// "zdg: internal error: <what>" and exit 3. A failed theory check exits 1 (Context).
#include <zdg/arith/error.hpp>
#include <zdg/arith/integer.hpp>
#include <zdg/cli/commands.hpp>
#include <zdg/kernel/io/output_files.hpp>
#include <zdg/kernel/render/picture.hpp>

#include <fmt/core.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <csignal>
#include <cstring>
#include <exception>
#include <filesystem>
#include <iostream>
#include <new>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>

namespace zdg::cli {
void print_json(const nlohmann::json& j) {
  std::cout << j.dump(2) << '\n';
}

double parse_number(const std::string& text, const std::string& option) {
  double v = 0;
  const auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || p != text.data() + text.size() || !std::isfinite(v))
    throw InvalidArgument(option + ": '" + text + "' is not a number");
  return v;
}

std::vector<std::string> split_commas(const std::string& text) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = text.find(',', start);
    parts.push_back(text.substr(start, comma == std::string::npos ? comma : comma - start));
    if (comma == std::string::npos) return parts;
    start = comma + 1;
  }
}

std::array<double, 3> parse_xyz(const std::string& text, const std::string& option) {
  const auto parts = split_commas(text);
  if (parts.size() != 3) throw InvalidArgument(option + ": '" + text + "' is not X,Y,Z");
  return {parse_number(parts[0], option), parse_number(parts[1], option),
          parse_number(parts[2], option)};
}

std::pair<double, double> parse_view(const std::string& text) {
  const auto comma = text.find(',');
  if (comma == std::string::npos)
    throw InvalidArgument("--view '" + text + "': expected AZIMUTH,ELEVATION in degrees");
  const double az = parse_number(text.substr(0, comma), "--view");
  const double el = parse_number(text.substr(comma + 1), "--view");
  if (el < -90 || el > 90)
    throw InvalidArgument("--view '" + text + "': the elevation is between -90 and 90 degrees");
  return {az, el};
}

std::pair<int, int> parse_picture_size(const std::string& text) {
  const auto x = text.find('x');
  int wh[2] = {0, 0};
  const std::string parts[2] = {text.substr(0, x),
                                x == std::string::npos ? "" : text.substr(x + 1)};
  for (int k = 0; k < 2; ++k) {
    const char* b = parts[k].data();
    const auto [q, ec] = std::from_chars(b, b + parts[k].size(), wh[k]);
    if (parts[k].empty() || ec != std::errc() || q != b + parts[k].size())
      throw InvalidArgument("--png-size '" + text + "': expected WIDTHxHEIGHT, e.g. 1200x900");
  }
  check_picture_size(wh[0], wh[1], "--png-size " + text);
  return {wh[0], wh[1]};
}
} // namespace zdg::cli

namespace {

// Errors are reported on exactly one line of printable text, at most about 1000 characters.
std::string one_line(std::string s) {
  for (char& c : s) {
    if (c == '\n' || c == '\r' || c == '\t') c = ' ';
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  }
  while (!s.empty() && s.back() == ' ') s.pop_back();
  constexpr std::size_t kMax = 1000;
  if (s.size() > kMax) s = s.substr(0, kMax) + "... (message cut)";
  return s;
}

// A writer handed a staging file names it in its message: the line names the user's output.
int fail(const std::string& what, int status = 2) {
  std::fflush(stdout);
  fmt::print(stderr, "zdg: {}\n", one_line(zdg::name_outputs(what)));
  return status;
}

// Integer options are decimal like every other number of zdg: CLI11 would read them with
// strtoll(..., 0), where "010" is eight and "0x10" sixteen, and where a value beyond 64 bits
// silently becomes the largest one. Every INT / UINT option of every subcommand first goes
// through zdg::parse_integer and is handed on in canonical decimal (no leading zero), which
// CLI11 then reads right; the narrower types are range-checked by CLI11 itself.
void make_integer_options_decimal(CLI::App& app) {
  for (CLI::Option* opt : app.get_options()) {
    if (opt->get_type_size() == 0) continue; // a flag
    const std::string type = opt->get_type_name();
    const bool is_unsigned = type.rfind("UINT", 0) == 0;
    if (!is_unsigned && type.rfind("INT", 0) != 0) continue;
    opt->transform(CLI::Validator(
                       [is_unsigned](std::string& text) -> std::string {
                         try {
                           text = is_unsigned
                                      ? std::to_string(zdg::parse_integer<std::uint64_t>(text))
                                      : std::to_string(zdg::parse_integer<std::int64_t>(text));
                           return {};
                         } catch (const zdg::Error& e) {
                           return e.what();
                         }
                       },
                       ""),
                   "decimal");
  }
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
    make_integer_options_decimal(*sub);
  }
}

// Everything a command printed must reach its destination (a full disk, a closed pipe).
int check_stdout(int status) {
  std::cout.flush();
  if (!std::cout || std::fflush(stdout) != 0 || std::ferror(stdout) != 0) {
    return fail(std::string("cannot write the output to stdout (") + std::strerror(errno) + ")");
  }
  return status;
}

} // namespace

int main(int argc, char** argv) {
  // A file-size limit (ulimit -f) reached by an output is a write error (EFBIG: one line, exit
  // 2, the staged output removed), not a core dump by SIGXFSZ.
  std::signal(SIGXFSZ, SIG_IGN);
  try {
    CLI::App app{"zdg: exact-arithmetic research kernel for digital geometry", "zdg"};
    app.require_subcommand(1);
    zdg::cli::Context ctx;
    zdg::cli::add_arith_commands(app, ctx);
    zdg::cli::add_dss_commands(app, ctx);
    zdg::cli::add_converge_commands(app, ctx);
    zdg::cli::add_transform_commands(app, ctx);
    zdg::cli::add_hull_commands(app, ctx);
    zdg::cli::add_convert_commands(app, ctx);
    zdg::cli::add_topology_commands(app, ctx);
    zdg::cli::add_surface_commands(app, ctx);
    zdg::cli::add_plane_commands(app, ctx);
    zdg::cli::add_check_commands(app, ctx);
    zdg::cli::add_serve_commands(app, ctx);
    zdg::cli::add_view_commands(app, ctx);
    zdg::cli::add_mesh_commands(app, ctx);
    zdg::cli::add_reconstruct_commands(app, ctx);
    zdg::cli::add_points_commands(app, ctx);
    zdg::cli::add_render_commands(app, ctx);
    zdg::cli::add_csg_commands(app, ctx);
    zdg::cli::add_convex_commands(app, ctx);
    zdg::cli::add_motion_commands(app, ctx);
    zdg::cli::add_voxelize_commands(app, ctx);
    zdg::cli::add_dag_commands(app, ctx);
    make_integer_options_decimal(app);
    try {
      app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
      return check_stdout(app.exit(e));
    } catch (const CLI::CallForAllHelp& e) {
      return check_stdout(app.exit(e));
    } catch (const CLI::CallForVersion& e) {
      return check_stdout(app.exit(e));
    }
    return check_stdout(ctx.exit_code);
  } catch (const CLI::ParseError& e) {
    return fail(e.what());
  } catch (const zdg::Error& e) {
    return fail(e.what());
  } catch (const std::bad_alloc&) {
    return fail("out of memory");
  } catch (const std::length_error& e) {
    return fail(std::string("out of memory (") + e.what() + ")");
  } catch (const std::filesystem::filesystem_error& e) {
    // "filesystem error: cannot ...: Not a directory [/etc/passwd/sub]"
    return fail(e.what());
  } catch (const std::system_error& e) {
    return fail(std::string("the system refused: ") + e.what());
  } catch (const std::out_of_range& e) {
    return fail(std::string("value out of range (") + e.what() + ")");
  } catch (const std::invalid_argument& e) {
    return fail(std::string("invalid value (") + e.what() + ")");
  } catch (const std::exception& e) {
    return fail(std::string("internal error: ") + e.what(), 3);
  } catch (...) {
    return fail("internal error: unknown exception", 3);
  }
}
