// zdg: the command line of the zdg kernel. See convergence/cli/commands.hpp.
#include <zdg/arith/error.hpp>
#include <zdg/convergence/cli/commands.hpp>

#include <fmt/core.h>

#include <exception>
#include <iostream>
#include <string>

namespace zdg::cli {
void print_json(const nlohmann::json& j) {
  std::cout << j.dump(2) << '\n';
}
} // namespace zdg::cli

namespace {
// Errors are reported on exactly one line.
std::string one_line(std::string s) {
  for (char& c : s) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}
} // namespace

int main(int argc, char** argv) {
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
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    fmt::print(stderr, "zdg: {}\n", one_line(e.what()));
    return 2;
  } catch (const zdg::Error& e) {
    fmt::print(stderr, "zdg: {}\n", one_line(e.what()));
    return 2;
  } catch (const std::bad_alloc&) {
    fmt::print(stderr, "zdg: out of memory\n");
    return 2;
  }
  return ctx.exit_code;
}
