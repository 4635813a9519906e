// The progress of an operation, step by step, and the seconds each step took.
//
//   OperationProgress p(callback);   // callback may be empty (no report)
//   p.start("boundary surfels");     // reports {what, "", started}
//   ...
//   p.done("surfels", "41 surfels"); // reports {what, detail, seconds}; records the wall-clock
//                                    // and process CPU seconds under the key "surfels"
//
// The front ends turn the reports into their own form (the command line: a line on stderr
// when it is a terminal); the recorded seconds are part of an operation's result and of its
// JSON form ("seconds", "cpu_seconds"). Not thread-safe: one operation, one progress.
#pragma once

#include <chrono>
#include <functional>
#include <map>
#include <string>

namespace zdg {

struct ProgressEvent {
  std::string what;   ///< the step, in words ("boundary surfels")
  std::string detail; ///< when done: what it found ("41 surfels"), possibly empty
  bool done = false;  ///< false: the step starts
  double seconds = 0; ///< when done: its wall-clock seconds
};
using ProgressCallback = std::function<void(const ProgressEvent&)>;

/// CPU seconds of the process so far (all threads).
double process_cpu_seconds();

class OperationProgress {
public:
  explicit OperationProgress(ProgressCallback callback = {});
  void start(const std::string& what);
  /// Ends the step begun by start(), recorded under `key`.
  void done(const std::string& key, const std::string& detail = "");
  std::map<std::string, double> seconds, cpu_seconds;

private:
  ProgressCallback callback_;
  std::string what_;
  std::chrono::steady_clock::time_point t0_;
  double cpu0_ = 0;
};

} // namespace zdg
