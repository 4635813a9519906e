// The registry of named properties and the campaign runner behind `zdg check` (and behind the
// tests that call the same properties through GoogleTest).
//
// A property is a theorem or an oracle comparison over random cases:
//   - an operation property (floor_sum.oracle, dss.recognize.minimal, hull.disc.pick, ...)
//     computes zdg's answer to a request (`compute`, on the integer type the campaign starts
//     on, escalating when it overflows) and judges it against an independent oracle
//     (`oracle`: brute force, a closed form, a definition); the same judgement applies to the
//     answer of a user's external command (--against, the line-JSON protocol of `zdg check
//     --help`), which replaces `compute`;
//   - any other property (simple_point.lut, ...) has a `holds` predicate.
// Each names its theorem and source, its generator parameters (integer type: the tower type the
// computation starts on; bits: the magnitude of the generated integers, which may exceed the
// type so that escalation is exercised; max size: points, image side, terms) and a cost class
// (cheap: well under a millisecond per case; moderate: about a millisecond; heavy: more).
//
// Campaign (run_check): case k is generated from case_seed(seed, k) (convergence/check/
// check_rng.hpp) and evaluated; cases are spread over T threads (kernel/parallel/parallel_for.hpp),
// a failure stops the others at the next case whose index exceeds it, so the reported failure is
// the first failing index whatever T (deterministic, unless the time budget cut the run). The
// failing case is then shrunk greedily (convergence/check/record.hpp) while it stays valid and
// failing. A replay token "TYPE.BITS.MAXSIZE.SEED16HEX" regenerates the failing case alone.
// Cost: runs x (generation + evaluation), plus at most max_shrink_attempts evaluations.
#pragma once

#include <zdg/arith/escalate.hpp>
#include <zdg/convergence/check/check_rng.hpp>
#include <zdg/convergence/check/record.hpp>

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace zdg::check {

/// Generator parameters of one campaign.
struct Params {
  IntKind type = IntKind::int64;
  int bits = 64;
  std::size_t max_size = 16;
};

/// The default magnitude for a type: 64, 128 or 256 bits.
int default_bits(IntKind type);

enum class Cost { cheap, moderate, heavy };
std::string to_string(Cost c);

/// The judgement of one case: holds, or why not (with both answers for an operation).
struct Verdict {
  bool holds = true;
  std::string why;
  std::optional<Record> expected, got;
};

struct Property {
  std::string name;      // family.what, e.g. "floor_sum.oracle"
  std::string theorem;   // what is checked, in one or two sentences
  std::string source;    // the paper, book or oracle it rests on
  std::string operation; // the zdg command whose answers are checked ("" when none)
  std::string sizes;     // what max_size bounds, and what bits means here
  Cost cost = Cost::cheap;
  std::vector<IntKind> types = {IntKind::int64, IntKind::int128, IntKind::bigint};
  bool uses_bits = true;
  std::size_t default_max_size = 16;
  std::size_t min_max_size = 1; // --max-size outside [min, max]: InvalidArgument
  std::size_t max_max_size = 1000;

  std::function<Record(Rng&, const Params&)> generate;
  /// Precondition of a case (the shrinker's candidates are kept only when it holds).
  std::function<bool(const Record&, const Params&)> valid;
  // Operation properties.
  std::function<Record(const Record&)> request; // the request line (null: the case itself)
  std::function<Record(const Record&)> oracle;  // the expected answer
  std::function<Record(const Record&, IntKind)> compute;
  /// The theorem checked on any answer before it is compared, field by field, with the
  /// oracle's (null: the comparison alone).
  std::function<std::optional<std::string>(const Record& c, const Record& expected,
                                           const Record& got)>
      judge;
  // Other properties: nullopt when the theorem holds on the case, else why not.
  std::function<std::optional<std::string>(const Record&, IntKind)> holds;

  bool is_operation() const { return static_cast<bool>(oracle); }
  Record request_of(const Record& c) const { return request ? request(c) : c; }
};

/// Every registered property, sorted by name.
const std::vector<Property>& registry();
/// The property of that name; InvalidArgument (listing the names) when there is none.
const Property& find_property(const std::string& name);

/// A failure of the external command itself (crash, timeout, malformed line): reported as
/// such, never shrunk as a counterexample.
class ExternalFailure : public std::runtime_error {
public:
  explicit ExternalFailure(const std::string& what, std::size_t at = 0)
      : std::runtime_error(what), at_(at) {}
  /// The request (of a batch) the command failed on.
  std::size_t at() const { return at_; }

private:
  std::size_t at_;
};

/// The answers to a batch of requests: got[j] answers request j; when the command failed, it
/// failed on request got.size() and `failure` says how.
struct Answers {
  std::vector<Record> got;
  std::optional<std::string> failure;
};

/// Answers requests on behalf of an external command (one per worker thread). `schema` is the
/// oracle's answer: the names and kinds of the fields to read. Throws ExternalFailure.
class AnswerSource {
public:
  virtual ~AnswerSource() = default;
  virtual Record answer(const Property& p, const Record& request, const Record& schema) = 0;
  /// A batch, in two halves: send_all hands the requests over (an external command starts on
  /// them while zdg computes the oracle's answers), receive_all returns the answers in order
  /// (schemas[j] for request j). The round trip of one line is then not paid per request.
  /// Default: send_all keeps the requests, receive_all asks them one by one.
  virtual void send_all(const Property& p, const std::vector<Record>& requests);
  virtual Answers receive_all(const Property& p, const std::vector<Record>& schemas);

private:
  std::vector<Record> kept_;
};
using AnswerSourceFactory = std::function<std::unique_ptr<AnswerSource>()>;

/// Evaluates one case: zdg's own answer (external == nullptr) or the external one.
Verdict evaluate(const Property& p, const Record& c, IntKind type, AnswerSource* external);

/// The judgement of an operation's answer `got` to case c, the oracle having answered
/// `expected` (the property's judge, then field-by-field equality).
Verdict judge_answer(const Property& p, const Record& c, Record expected, Record got);

struct Options {
  std::uint64_t seed = 1;
  std::int64_t runs = 1000;
  double time_budget_s = 0; // 0: none
  unsigned threads = 1;     // 0: all cores
  std::int64_t max_shrink_attempts = 20000;
  std::int64_t batch = 64; // requests in flight to an external command
  double max_shrink_s = 120;
  AnswerSourceFactory external; // empty: zdg's own answers
  /// Called now and then by one worker with the number of cases done (may be empty).
  std::function<void(std::int64_t done)> progress;
};

struct Failure {
  std::int64_t index = -1; // the failing case of the campaign (-1 for a replay)
  std::string token;       // replays the original failing case
  Record original, shrunk;
  Verdict verdict; // of the shrunk case
  std::int64_t shrink_steps = 0, shrink_attempts = 0;
  bool external_error = false; // the external command crashed, hung or answered garbage
  std::string shrink_note;     // why shrinking stopped early ("" when it reached a minimum)
};

struct Report {
  std::string property;
  Params params;
  std::uint64_t seed = 0;
  std::int64_t runs = 0; // cases evaluated
  std::int64_t requested = 0;
  bool budget_exhausted = false;
  double seconds = 0;
  std::array<std::int64_t, 3> served{}; // zdg's answers by the type that served
  std::optional<Failure> failure;
};

/// Runs a campaign. Throws InvalidArgument for parameters the property does not support.
Report run_check(const Property& p, const Params& params, const Options& opt);

/// Re-runs the case of a replay token (and shrinks it when it fails).
Report replay_check(const Property& p, const std::string& token, const Options& opt);

/// The token of case seed s under params; parse_token is its inverse (InvalidArgument on bad
/// text).
std::string make_token(const Params& params, std::uint64_t case_seed);
std::pair<Params, std::uint64_t> parse_token(const std::string& token);

/// Checks that the property supports the parameters (type, bits, max size).
void validate_params(const Property& p, const Params& params);

// Registration, one function per family (convergence/check/*_properties.cpp).
void add_arith_properties(std::vector<Property>& out);
void add_dss_properties(std::vector<Property>& out);
void add_hull_properties(std::vector<Property>& out);
void add_image_properties(std::vector<Property>& out);
void add_plane_properties(std::vector<Property>& out);

} // namespace zdg::check
