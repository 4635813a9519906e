// The external command of `zdg check --against 'COMMAND'`: started once per worker thread with
// /bin/sh -c COMMAND (the user's own command line, run as the user asked), fed one JSON request
// per line on its stdin, read one JSON answer per line on its stdout (fork/exec, two pipes,
// poll with the per-request timeout). Its stderr is the user's terminal.
//
// Failures of the command are ExternalFailure (convergence/check/property.hpp), with one clear
// sentence: it exited or was killed by a signal (crash), it did not answer within the timeout
// (hang: it is killed), or its line is not a JSON object / a field has the wrong type
// (malformed). Cost per request: two system calls each way plus the JSON parse; the command's
// own time dominates (measured in the closing note of issue #20).
#pragma once

#include <zdg/convergence/check/property.hpp>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <sys/types.h>
#include <vector>

namespace zdg::cli {

/// A running COMMAND answering requests.
class ExternalCommand : public check::AnswerSource {
public:
  ExternalCommand(std::string command, double request_timeout_s);
  ~ExternalCommand() override;
  ExternalCommand(const ExternalCommand&) = delete;
  ExternalCommand& operator=(const ExternalCommand&) = delete;

  check::Record answer(const check::Property& p, const check::Record& request,
                       const check::Record& schema) override;
  /// Pipelined: the requests go out at once (what the pipe takes), the command works while
  /// zdg's oracle does, the rest is written while the answers are read (poll on both pipes).
  /// Batches queue: receive_all reads the answers to the oldest schemas.size() requests.
  void send_all(const check::Property& p, const std::vector<check::Record>& requests) override;
  check::Answers receive_all(const check::Property& p,
                             const std::vector<check::Record>& schemas) override;

  /// One raw exchange: writes the line, returns the answer line (without the newline).
  std::string exchange(const std::string& line);
  /// Writes the lines and returns one answer line per line; ExternalFailure (with at() the
  /// request it failed on) when the command dies, hangs past the timeout (renewed by every
  /// answer) or writes more than 256 MiB without a newline.
  std::vector<std::string> exchange_all(const std::vector<std::string>& lines);
  /// The two halves of exchange_all.
  void send(const std::vector<std::string>& lines);
  /// The answers to the first `count` requests in flight (all by default); on a failure,
  /// `answers` holds those read before.
  void receive(std::vector<std::string>& answers, std::size_t count = SIZE_MAX);

private:
  std::string command_;
  double timeout_s_;
  pid_t pid_ = -1;
  int to_child_ = -1, from_child_ = -1;
  std::string buffer_;                 // answer bytes read, not yet split into lines
  std::size_t scanned_ = 0;            // the prefix of buffer_ known to hold no newline
  std::string pending_;                // request bytes not yet written
  std::vector<std::string> in_flight_; // requests sent and not yet answered
  [[noreturn]] void died(const std::string& when, std::size_t at);
  void stop();
};

/// The record as a JSON value (integers as strings, see convergence/check/record.hpp).
nlohmann::json to_json_value(const check::Record& r);

/// Reads the fields of `schema` from an answer object (absent fields stay absent; extra fields
/// are ignored except "integer_type" and "error"); a field of the wrong type throws
/// check::ExternalFailure.
check::Record record_from_answer(const nlohmann::json& j, const check::Record& schema);

/// An integer given as a decimal string or a JSON integer; nullopt otherwise.
std::optional<BigInt> json_integer(const nlohmann::json& v);

/// Shell quoting of one word: 'text' with every ' written '\''.
std::string shell_quote(const std::string& s);

} // namespace zdg::cli
