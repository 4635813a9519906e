// zdg serve OPERATION: answers one JSON request per line of stdin with one JSON line on
// stdout (cli/serve_handlers.cpp answers; this file reads, batches and writes).
#include <zdg/arith/error.hpp>
#include <zdg/cli/commands.hpp>
#include <zdg/cli/serve.hpp>

#include <cerrno>
#include <iostream>
#include <memory>
#include <string>
#include <unistd.h>
#include <vector>

namespace zdg::cli {

namespace {

// The answers go straight to file descriptor 1 (iostreams write every line on their own).
bool write_all(const std::string& s) {
  std::cout.flush();
  std::size_t done = 0;
  while (done < s.size()) {
    const ssize_t w = ::write(1, s.data() + done, s.size() - done);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    done += static_cast<std::size_t>(w);
  }
  return true;
}

void run_serve(const std::vector<std::string>& words) {
  std::string op;
  for (const auto& w : words) op += (op.empty() ? "" : " ") + w;
  serve_answer(op, "{}"); // an unknown operation is a usage error, before any input is read
  std::ios::sync_with_stdio(false);
  std::string line, out;
  while (std::getline(std::cin, line)) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    out += serve_answer(op, line);
    out += '\n';
    // Written before waiting for input (never an answer held while zdg check waits for it),
    // not after each line while requests are queued: one write for a batch of answers.
    if (std::cin.rdbuf()->in_avail() <= 0 || out.size() > (1u << 16)) {
      if (!write_all(out)) return; // the reader is gone
      out.clear();
    }
  }
  write_all(out);
}

} // namespace

void add_serve_commands(CLI::App& app, Context& /*ctx*/) {
  auto words = std::make_shared<std::vector<std::string>>();
  auto* cmd = app.add_subcommand(
      "serve", "Answer one JSON request per line of stdin (the --against protocol of zdg check) "
               "with zdg's own implementation of OPERATION");
  cmd->footer(
      "Operations: floor-sum, cf, christoffel, dss recognize, dss subsegment, hull "
      "points, hull disc, transform dt, topology betti, dss cover, transform voronoi, topology "
      "skeleton, plane probe, surface. Example:\n"
      "  echo '{\"n\":\"5\",\"m\":\"7\",\"a\":\"-3\",\"b\":\"12\"}' | zdg serve floor-sum");
  cmd->add_option("OPERATION", *words, "the operation, e.g. floor-sum or dss recognize")
      ->required()
      ->expected(1, 2);
  cmd->callback([words] { run_serve(*words); });
}

} // namespace zdg::cli
