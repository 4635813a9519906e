#include <zdg/operations/progress.hpp>

#include <ctime>

namespace zdg {

double process_cpu_seconds() {
  timespec t{};
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

OperationProgress::OperationProgress(ProgressCallback callback) : callback_(std::move(callback)) {}

void OperationProgress::start(const std::string& what) {
  what_ = what;
  t0_ = std::chrono::steady_clock::now();
  cpu0_ = process_cpu_seconds();
  if (callback_) callback_({what, "", false, 0});
}

void OperationProgress::done(const std::string& key, const std::string& detail) {
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
  seconds[key] = s;
  cpu_seconds[key] = process_cpu_seconds() - cpu0_;
  if (callback_) callback_({what_, detail, true, s});
}

} // namespace zdg
