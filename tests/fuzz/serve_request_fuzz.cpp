// Fuzz target: the request lines of zdg serve (cli/serve.hpp serve_answer, the
// line-JSON protocol of zdg check --against). The first byte picks the operation among those
// whose work is bounded by the size of the request; the rest is the line. Expected outcome:
// one line of JSON, an object (the answer or {"error": ...}), never an exception. The
// operations left out (christoffel, hull disc, hull ellipse, hull halfplanes, plane probe,
// sturmian) do work that grows with the values asked for (a word of p + q letters, a disc of
// radius r, the lattice rows of a polygon, up to ||N||_1 probing steps, a period of up to
// O(sqrt(D) log D) terms and a word of `length` letters).
// hull disc and plane probe are bounded for every front end by the library, before the work
// (kHullMaxVertices vertices, kPlaneProbingMaxSteps steps), but a request may raise the bound
// (its max_vertices, max_steps fields) and the default bounds allow seconds of work, more than a
// fuzzer's time per input; christoffel is bounded by its callers (zdg check by the sizes it
// generates and --request-timeout).
#include <zdg/cli/serve.hpp>

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const char* const ops[] = {"floor-sum",       "cf",
                                    "dss recognize",   "dss subsegment",
                                    "dss cover",       "hull points",
                                    "transform dt",    "transform voronoi",
                                    "topology betti",  "topology skeleton",
                                    "surface",         "contour",
                                    "plane recognize", "topology components",
                                    "topology simple", "transform chamfer"};
  if (size == 0) return 0;
  const char* op = ops[data[0] % (sizeof ops / sizeof ops[0])];
  const std::string line(reinterpret_cast<const char*>(data + 1), size - 1);
  const std::string answer = zdg::cli::serve_answer(op, line);
  const auto j = nlohmann::json::parse(answer, nullptr, false);
  if (j.is_discarded() || !j.is_object()) __builtin_trap();
  return 0;
}
