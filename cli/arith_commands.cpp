// zdg cf, zdg christoffel, zdg floor-sum, zdg sturmian: the arithmetic operations
// (operations/arith_operations.hpp) on the command line: parse, call, print.
#include <zdg/arith/error.hpp>
#include <zdg/cli/commands.hpp>
#include <zdg/operations/arith_operations.hpp>

#include <cstdint>
#include <iostream>
#include <string>
#include <vector>

namespace zdg::cli {

namespace {

void run_cf(const std::string& text, bool json) {
  const ContinuedFractionResult r = continued_fraction_operation(parse_fraction(text));
  if (json) return print_json(to_json(r));
  std::cout << r.p << "/" << r.q << " = [";
  for (std::size_t i = 0; i < r.terms.size(); ++i) {
    std::cout << (i == 0 ? "" : (i == 1 ? "; " : ", ")) << r.terms[i];
  }
  std::cout << "]\nconvergents:";
  for (const auto& [p, q] : r.convergents) std::cout << ' ' << p << '/' << q;
  std::cout << "\n(computed on " << to_string(r.served) << ")\n";
}

void run_christoffel(const std::string& text, bool upper, bool no_word, bool json) {
  const ChristoffelResult r = christoffel_operation({parse_fraction(text), upper, !no_word});
  if (json) return print_json(to_json(r));
  std::cout << (upper ? "upper" : "lower") << " Christoffel word of slope " << r.p << "/" << r.q;
  if (!no_word) std::cout << ":\n" << r.letters;
  std::cout << '\n';
  if (r.parents) {
    const auto& [l, h] = *r.parents;
    std::cout << "Stern-Brocot parents: " << l.p << "/" << l.q << " and " << h.p << "/" << h.q
              << '\n';
    if (r.factorization) {
      std::cout << "standard factorization: (" << r.factorization->first << ")("
                << r.factorization->second << ")\n";
    }
  } else {
    std::cout << "0/1 is a root of the Stern-Brocot tree: no parents, no factorization\n";
  }
}

BigInt parse_big(const std::string& text, const std::string& what) {
  try {
    return parse_integer<BigInt>(text);
  } catch (const InvalidArgument&) {
    throw InvalidArgument(what + ": '" + text + "' is not an integer");
  }
}

void run_floor_sum(const std::vector<std::string>& args, bool json) {
  const FloorSumResult r = floor_sum_operation({parse_big(args[0], "N"), parse_big(args[1], "M"),
                                                parse_big(args[2], "A"), parse_big(args[3], "B")});
  if (json) return print_json(to_json(r));
  std::cout << r.value << '\n';
}

void run_sturmian(const std::vector<std::string>& args, std::uint64_t length, bool json) {
  const SturmianResult r =
      sturmian_operation({parse_big(args[0], "A"), parse_big(args[1], "B"), parse_big(args[2], "D"),
                          parse_big(args[3], "C"), length});
  if (json) return print_json(to_json(r));
  std::cout << "(" << r.P << " + sqrt(" << r.D << "))/" << r.Q << " = [";
  for (std::size_t i = 0; i < r.preperiod.size(); ++i) {
    std::cout << (i == 0 ? "" : (i == 1 ? "; " : ", ")) << r.preperiod[i];
  }
  std::cout << (r.preperiod.empty() ? "(" : (r.preperiod.size() == 1 ? "; (" : ", ("));
  for (std::size_t i = 0; i < r.period.size(); ++i) std::cout << (i ? ", " : "") << r.period[i];
  std::cout << ")]\ncharacteristic word of the fractional part (" << r.alpha_P << " + sqrt(" << r.D
            << "))/" << r.Q << ":\n"
            << r.word << "\nChristoffel convergents:";
  for (const auto& [p, q] : r.christoffel) std::cout << ' ' << p << '/' << q;
  std::cout << "\n(computed on " << to_string(r.served) << ")\n";
}

} // namespace

void add_arith_commands(CLI::App& app, Context& /*ctx*/) {
  {
    auto* cmd = app.add_subcommand("cf", "Continued fraction and convergents of P/Q (any size)");
    auto text = std::make_shared<std::string>();
    auto json = std::make_shared<bool>(false);
    cmd->add_option("fraction", *text, "P/Q with Q != 0 (or an integer P)")->required();
    cmd->add_flag("--json", *json, "Machine-readable output");
    cmd->callback([text, json] { run_cf(*text, *json); });
  }
  {
    auto* cmd =
        app.add_subcommand("christoffel", "Christoffel word of slope P/Q, standard factorization");
    auto text = std::make_shared<std::string>();
    auto upper = std::make_shared<bool>(false), no_word = std::make_shared<bool>(false),
         json = std::make_shared<bool>(false);
    cmd->add_option("slope", *text, "P/Q with P >= 0, Q > 0 (reduced first)")->required();
    cmd->add_flag("--upper", *upper, "The upper word (the reverse of the lower one)");
    cmd->add_flag("--no-word", *no_word, "Omit the word and its factors (for huge slopes)");
    cmd->add_flag("--json", *json, "Machine-readable output");
    cmd->callback([=] { run_christoffel(*text, *upper, *no_word, *json); });
  }
  {
    auto* cmd =
        app.add_subcommand("floor-sum", "sum_{i=0}^{N-1} floor((A i + B) / M), exact, in O(log M)");
    auto args = std::make_shared<std::vector<std::string>>();
    auto json = std::make_shared<bool>(false);
    cmd->add_option("N M A B", *args, "N >= 0, M != 0, any A and B")->required()->expected(4);
    cmd->add_flag("--json", *json, "Machine-readable output");
    cmd->callback([=] { run_floor_sum(*args, *json); });
  }
  {
    auto* cmd = app.add_subcommand(
        "sturmian", "Periodic continued fraction of (A + B sqrt D)/C and the Sturmian word of its "
                    "fractional part, exact");
    auto args = std::make_shared<std::vector<std::string>>();
    auto length = std::make_shared<std::uint64_t>(64);
    auto json = std::make_shared<bool>(false);
    cmd->add_option("A B D C", *args, "B != 0, C != 0, D > 0 not a square")
        ->required()
        ->expected(4);
    cmd->add_option("--length", *length, "letters of the characteristic word (0 .. 10^8)")
        ->capture_default_str();
    cmd->add_flag("--json", *json, "Machine-readable output");
    cmd->callback([=] { run_sturmian(*args, *length, *json); });
  }
}

} // namespace zdg::cli
