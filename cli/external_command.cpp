#include <zdg/arith/error.hpp>
#include <zdg/cli/external_command.hpp>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace zdg::cli {

namespace {

std::string cut(const std::string& s, std::size_t n = 200) {
  std::string t = s.size() > n ? s.substr(0, n) + "..." : s;
  for (char& c : t) {
    if (static_cast<unsigned char>(c) < 0x20) c = ' ';
  }
  return t;
}

std::string describe_status(int status) {
  if (WIFEXITED(status)) {
    const int code = WEXITSTATUS(status);
    std::string s = "exited with status " + std::to_string(code);
    if (code > 128 && code < 128 + 65) {
      // The shell's report of a program it started and a signal killed.
      const char* name = strsignal(code - 128);
      s += " (signal " + std::to_string(code - 128) + ", " + (name ? name : "?") +
           ", as the shell "
           "reports it)";
    }
    return s;
  }
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    const char* name = strsignal(sig);
    return "was killed by signal " + std::to_string(sig) + " (" + (name ? name : "?") + ")";
  }
  return "stopped (status " + std::to_string(status) + ")";
}

using Clock = std::chrono::steady_clock;

int remaining_ms(Clock::time_point deadline) {
  const auto ms =
      std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
  return ms < 0 ? 0 : static_cast<int>(std::min<long long>(ms, 1 << 30));
}

} // namespace

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) {
    if (c == '\'') {
      out += "'\\''";
    } else {
      out += c;
    }
  }
  return out + "'";
}

ExternalCommand::ExternalCommand(std::string command, double request_timeout_s)
    : command_(std::move(command)), timeout_s_(request_timeout_s) {
  if (command_.find_first_not_of(" \t") == std::string::npos) {
    throw InvalidArgument("--against: the command is empty");
  }
  int in[2], out[2];
  if (::pipe2(in, O_CLOEXEC) != 0) throw IoError(std::string("pipe: ") + std::strerror(errno));
  if (::pipe2(out, O_CLOEXEC) != 0) {
    ::close(in[0]);
    ::close(in[1]);
    throw IoError(std::string("pipe: ") + std::strerror(errno));
  }
  pid_ = ::fork();
  if (pid_ < 0) {
    const int e = errno;
    for (int fd : {in[0], in[1], out[0], out[1]}) ::close(fd);
    throw IoError(std::string("cannot start the external command (fork: ") + std::strerror(e) +
                  ")");
  }
  if (pid_ == 0) {
    // The child: its own process group (a timeout kills the shell and what it started).
    ::setpgid(0, 0);
    ::dup2(in[0], 0);
    ::dup2(out[1], 1);
    ::signal(SIGPIPE, SIG_DFL);
    ::execl("/bin/sh", "sh", "-c", command_.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::setpgid(pid_, pid_); // also from the parent: no race with the first kill
  ::close(in[0]);
  ::close(out[1]);
  to_child_ = in[1];
  from_child_ = out[0];
  ::fcntl(to_child_, F_SETFL, ::fcntl(to_child_, F_GETFL) | O_NONBLOCK);
}

ExternalCommand::~ExternalCommand() {
  stop();
}

void ExternalCommand::stop() {
  if (to_child_ >= 0) {
    ::close(to_child_);
    to_child_ = -1;
  }
  if (pid_ > 0) {
    // End of input: a well-behaved command exits; give it a second, then kill it.
    int status = 0;
    const auto deadline = Clock::now() + std::chrono::seconds(1);
    pid_t r = 0;
    while ((r = ::waitpid(pid_, &status, WNOHANG)) == 0 && Clock::now() < deadline) {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    if (r == 0) {
      ::kill(-pid_, SIGKILL);
      ::waitpid(pid_, &status, 0);
    }
    pid_ = -1;
  }
  if (from_child_ >= 0) {
    ::close(from_child_);
    from_child_ = -1;
  }
}

void ExternalCommand::died(const std::string& when, std::size_t at) {
  int status = 0;
  pid_t r = 0;
  const auto deadline = Clock::now() + std::chrono::milliseconds(500);
  while ((r = ::waitpid(pid_, &status, WNOHANG)) == 0 && Clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  std::string what;
  if (r == pid_) {
    what = describe_status(status);
    pid_ = -1;
  } else {
    what = "closed its output";
    ::kill(-pid_, SIGKILL);
    ::waitpid(pid_, &status, 0);
    pid_ = -1;
  }
  stop();
  throw check::ExternalFailure("the external command " + what + " " + when + " (crash)", at);
}

std::string ExternalCommand::exchange(const std::string& line) {
  return exchange_all({line}).at(0);
}

void ExternalCommand::send(const std::vector<std::string>& lines) {
  if (pid_ < 0) throw check::ExternalFailure("the external command is not running");
  for (const auto& l : lines) {
    pending_ += l;
    pending_ += '\n';
    in_flight_.push_back(l);
  }
  // What the pipe takes now; the rest goes while the answers are read.
  while (!pending_.empty()) {
    const ssize_t w = ::write(to_child_, pending_.data(), pending_.size());
    if (w <= 0) break; // EAGAIN (pipe full), EPIPE (reported when reading), EINTR
    pending_.erase(0, static_cast<std::size_t>(w));
  }
}

void ExternalCommand::receive(std::vector<std::string>& answers, std::size_t count) {
  answers.clear();
  const std::size_t want = std::min(count, in_flight_.size());
  const auto timeout = std::chrono::milliseconds(static_cast<long long>(timeout_s_ * 1000));
  auto deadline = Clock::now() + timeout; // renewed by every answer
  auto request = [&]() { return cut(in_flight_[answers.size()]); };
  auto fail_at = [&]() {
    const std::size_t at = answers.size();
    in_flight_.clear();
    pending_.clear();
    return at;
  };
  auto hang = [&]() {
    const std::string req = request();
    ::kill(-pid_, SIGKILL);
    int status = 0;
    ::waitpid(pid_, &status, 0);
    pid_ = -1;
    stop();
    const std::size_t at = fail_at();
    throw check::ExternalFailure("the external command did not answer within " +
                                     std::to_string(timeout_s_) +
                                     " s (--request-timeout): killed (hang) at the request " + req,
                                 at);
  };
  while (answers.size() < want) {
    // scanned_: the bytes of buffer_ already known to hold no newline (a long line is scanned
    // once, not once per read).
    for (auto nl = buffer_.find('\n', scanned_); nl != std::string::npos && answers.size() < want;
         nl = buffer_.find('\n')) {
      answers.push_back(buffer_.substr(0, nl));
      buffer_.erase(0, nl + 1);
      scanned_ = 0;
      deadline = Clock::now() + timeout;
    }
    if (answers.size() == want) break;
    scanned_ = buffer_.size();
    if (buffer_.size() > (std::size_t{1} << 28)) {
      const std::size_t at = fail_at();
      throw check::ExternalFailure("malformed answer: a line longer than 256 MiB", at);
    }
    // The timeout covers the whole answer: a line that keeps arriving (poll returns at once)
    // but does not end in time is a hang too.
    if (Clock::now() >= deadline) hang();
    // Write what the pipe takes and read what is there, never blocking on one while the
    // command waits on the other.
    pollfd fds[2] = {{from_child_, POLLIN, 0}, {to_child_, POLLOUT, 0}};
    const nfds_t n = pending_.empty() ? 1 : 2;
    const int pr = ::poll(fds, n, remaining_ms(deadline));
    if (pr < 0) {
      if (errno == EINTR) continue;
      throw IoError(std::string("poll: ") + std::strerror(errno));
    }
    if (pr == 0) hang();
    if (n == 2 && (fds[1].revents & (POLLOUT | POLLERR)) != 0) {
      const ssize_t w = ::write(to_child_, pending_.data(), pending_.size());
      if (w < 0 && errno == EPIPE) {
        const std::string req = request();
        const std::size_t at = fail_at();
        died("while the request " + req + " was written", at);
      }
      if (w < 0 && errno != EINTR && errno != EAGAIN) {
        throw IoError(std::string("writing to the external command: ") + std::strerror(errno));
      }
      if (w > 0) pending_.erase(0, static_cast<std::size_t>(w));
    }
    if ((fds[0].revents & (POLLIN | POLLHUP | POLLERR)) != 0) {
      char buf[65536];
      const ssize_t r = ::read(from_child_, buf, sizeof buf);
      if (r < 0 && errno != EINTR && errno != EAGAIN) {
        throw IoError(std::string("reading from the external command: ") + std::strerror(errno));
      }
      if (r == 0) {
        const std::string req = request();
        const std::size_t at = fail_at();
        died("before answering the request " + req, at);
      }
      if (r > 0) buffer_.append(buf, static_cast<std::size_t>(r));
    }
  }
  in_flight_.erase(in_flight_.begin(), in_flight_.begin() + static_cast<std::ptrdiff_t>(want));
}

std::vector<std::string> ExternalCommand::exchange_all(const std::vector<std::string>& lines) {
  send(lines);
  std::vector<std::string> answers;
  receive(answers);
  return answers;
}

namespace {

check::Record parse_answer(const std::string& ans, const std::string& line,
                           const check::Record& schema, std::size_t at) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(ans);
  } catch (const nlohmann::json::exception&) {
    throw check::ExternalFailure(
        "malformed answer (not JSON): '" + cut(ans) + "' to the request " + cut(line), at);
  }
  try {
    return record_from_answer(j, schema);
  } catch (const check::ExternalFailure& e) {
    throw check::ExternalFailure(std::string(e.what()) + " in the answer '" + cut(ans) +
                                     "' to the request " + cut(line),
                                 at);
  }
}

} // namespace

check::Record ExternalCommand::answer(const check::Property&, const check::Record& request,
                                      const check::Record& schema) {
  const std::string line = check::to_json(request);
  return parse_answer(exchange(line), line, schema, 0);
}

void ExternalCommand::send_all(const check::Property&, const std::vector<check::Record>& requests) {
  std::vector<std::string> lines;
  for (const auto& r : requests) lines.push_back(check::to_json(r));
  try {
    send(lines);
  } catch (const check::ExternalFailure&) {
    // Reported by receive_all.
  }
}

check::Answers ExternalCommand::receive_all(const check::Property&,
                                            const std::vector<check::Record>& schemas) {
  check::Answers a;
  // The first schemas.size() requests in flight are this batch (a later one may follow).
  const std::vector<std::string> lines(
      in_flight_.begin(), in_flight_.begin() + static_cast<std::ptrdiff_t>(
                                                   std::min(schemas.size(), in_flight_.size())));
  std::vector<std::string> answers; // those read before a failure too
  std::optional<std::string> failure;
  try {
    if (pid_ < 0 && !schemas.empty())
      throw check::ExternalFailure("the external command is not running");
    receive(answers, schemas.size());
  } catch (const check::ExternalFailure& e) {
    failure = e.what();
  }
  try {
    for (std::size_t j = 0; j < answers.size(); ++j) {
      a.got.push_back(parse_answer(answers[j], lines.at(j), schemas.at(j), j));
    }
    a.failure = failure;
  } catch (const check::ExternalFailure& e) {
    a.failure = e.what(); // a malformed answer comes before the later failure
  }
  return a;
}

std::optional<BigInt> json_integer(const nlohmann::json& v) {
  if (v.is_number_integer()) {
    if (v.is_number_unsigned()) return BigInt(v.get<std::uint64_t>());
    return BigInt(v.get<std::int64_t>());
  }
  if (v.is_string()) {
    const auto& s = v.get_ref<const std::string&>();
    if (is_decimal_integer(s)) return parse_integer<BigInt>(s);
  }
  return std::nullopt;
}

namespace {

[[noreturn]] void malformed(const std::string& name, const std::string& what) {
  throw check::ExternalFailure("malformed answer: field '" + name + "' is not " + what);
}

void read_array(const nlohmann::json& v, std::size_t axis, std::size_t rank, check::Field& f) {
  if (!v.is_array()) malformed(f.name, "a nested list of rank " + std::to_string(rank));
  if (f.shape.size() <= axis) {
    f.shape.push_back(v.size());
  } else if (f.shape[axis] != v.size()) {
    malformed(f.name, "a rectangular nested list");
  }
  for (const auto& e : v) {
    if (axis + 1 == rank) {
      auto x = json_integer(e);
      if (!x) malformed(f.name, "a list of integers");
      f.ints.push_back(*x);
    } else {
      read_array(e, axis + 1, rank, f);
    }
  }
  if (v.empty()) {
    // An empty list: the inner extents are those of the schema.
    while (f.shape.size() < rank) f.shape.push_back(0);
  }
}

// A list of objects, each with the keys f.columns (integer values): rows of an {n, k} array.
void read_rows(const nlohmann::json& v, check::Field& f) {
  const std::string what = "a list of objects with integer fields";
  if (!v.is_array()) malformed(f.name, what);
  for (const auto& row : v) {
    if (!row.is_object()) malformed(f.name, what);
    for (const auto& key : f.columns) {
      if (!row.contains(key)) malformed(f.name, what + " (a row has no '" + key + "')");
      auto x = json_integer(row.at(key));
      if (!x) malformed(f.name, what + " ('" + key + "' is not an integer)");
      f.ints.push_back(*x);
    }
  }
  f.shape = {v.size(), f.columns.size()};
}

} // namespace

check::Record record_from_answer(const nlohmann::json& j, const check::Record& schema) {
  using check::FieldKind;
  if (!j.is_object()) throw check::ExternalFailure("malformed answer: not a JSON object");
  check::Record r;
  for (const auto& f : schema.fields) {
    if (!j.contains(f.name)) continue;
    const auto& v = j.at(f.name);
    switch (f.kind) {
    case FieldKind::integer: {
      auto x = json_integer(v);
      if (!x) malformed(f.name, "an integer (a decimal string or a JSON integer)");
      r.integer(f.name, *x);
      break;
    }
    case FieldKind::boolean:
      if (!v.is_boolean()) malformed(f.name, "true or false");
      r.boolean(f.name, v.get<bool>());
      break;
    case FieldKind::text:
      if (!v.is_string()) malformed(f.name, "a string");
      r.text(f.name, v.get<std::string>());
      break;
    case FieldKind::texts: {
      if (!v.is_array()) malformed(f.name, "a list of strings");
      std::vector<std::string> t;
      for (const auto& e : v) {
        if (!e.is_string()) malformed(f.name, "a list of strings");
        t.push_back(e.get<std::string>());
      }
      r.texts(f.name, std::move(t));
      break;
    }
    case FieldKind::array: {
      check::Field g;
      g.name = f.name;
      g.kind = FieldKind::array;
      g.numbers = f.numbers;
      g.columns = f.columns;
      if (!f.columns.empty()) {
        read_rows(v, g);
      } else {
        read_array(v, 0, f.shape.size(), g);
      }
      r.fields.push_back(std::move(g));
      break;
    }
    }
  }
  for (const char* extra : {"integer_type", "error"}) {
    if (j.contains(extra) && j.at(extra).is_string() && !r.has(extra)) {
      r.text(extra, j.at(extra).get<std::string>());
    }
  }
  return r;
}

nlohmann::json to_json_value(const check::Record& r) {
  return nlohmann::json::parse(check::to_json(r));
}

} // namespace zdg::cli
