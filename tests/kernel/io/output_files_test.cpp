#include <zdg/kernel/io/output_files.hpp>

#include <zdg/arith/error.hpp>

#include <gtest/gtest.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

#include <fcntl.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#if defined(__linux__)
#include <linux/fs.h>
#endif

namespace {

namespace fs = std::filesystem;
using zdg::Existing;
using zdg::OutputSet;

struct Scratch {
  fs::path dir;
  Scratch() {
    dir = fs::temp_directory_path() /
          ("zdg_output_files_" + std::to_string(::getpid()) + "_" +
           ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  ~Scratch() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  std::size_t entries() const {
    return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir), {}));
  }
};

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

void write(const fs::path& p, const std::string& s) {
  std::ofstream(p, std::ios::binary) << s;
}

TEST(OutputFiles, AllOrNothing) {
  Scratch s;
  write(s.dir / "a.txt", "old a");
  {
    OutputSet out(Existing::replace);
    write(out.add(s.dir / "a.txt"), "new a");
    write(out.add(s.dir / "b.txt"), "new b");
    // destroyed without commit: an exception on the way
  }
  EXPECT_EQ(read(s.dir / "a.txt"), "old a");
  EXPECT_FALSE(fs::exists(s.dir / "b.txt"));
  EXPECT_EQ(s.entries(), 1u); // no staging file left behind
  OutputSet out(Existing::replace);
  write(out.add(s.dir / "a.txt"), "new a");
  write(out.add(s.dir / "b.txt"), "new b");
  out.commit();
  EXPECT_EQ(read(s.dir / "a.txt"), "new a");
  EXPECT_EQ(read(s.dir / "b.txt"), "new b");
  EXPECT_EQ(s.entries(), 2u);
}

TEST(OutputFiles, RefusesAnExistingFileUnlessReplacing) {
  Scratch s;
  write(s.dir / "x", "keep");
  fs::permissions(s.dir / "x", fs::perms::owner_read);
  OutputSet out(Existing::refuse);
  try {
    out.add(s.dir / "x");
    FAIL();
  } catch (const zdg::IoError& e) {
    EXPECT_NE(std::string(e.what()).find("use --force"), std::string::npos) << e.what();
  }
  EXPECT_EQ(read(s.dir / "x"), "keep");
}

TEST(OutputFiles, ChecksEveryOutputBeforeAnyWork) {
  Scratch s;
  fs::create_directories(s.dir / "summary.json");
  OutputSet out(Existing::replace);
  EXPECT_THROW(out.add(s.dir / "summary.json"), zdg::IoError);      // a folder
  EXPECT_THROW(out.add(s.dir / "missing" / "f.npy"), zdg::IoError); // no such folder
  EXPECT_THROW(out.add(s.dir / "summary.json" / ""), zdg::IoError); // no file name
  out.add(s.dir / "c.txt");
  EXPECT_THROW(out.add(s.dir / "c.txt"), zdg::IoError); // named twice
}

TEST(OutputFiles, CommitFailsWhenAnOutputWasNotWritten) {
  Scratch s;
  OutputSet out;
  write(out.add(s.dir / "a"), "a");
  out.add(s.dir / "b");
  EXPECT_THROW(out.commit(), zdg::IoError);
  EXPECT_FALSE(fs::exists(s.dir / "a"));
}

// An optional output given up (a plot that could not be drawn) leaves its file as it was,
// the others are committed, and no staging file remains.
TEST(OutputFiles, DroppedOutputIsLeftAsItWas) {
  Scratch s;
  write(s.dir / "plot.png", "old plot");
  OutputSet out(Existing::replace);
  write(out.add(s.dir / "a.csv"), "new a");
  write(out.add(s.dir / "plot.png"), "half a plot");
  out.drop(s.dir / "plot.png");
  EXPECT_THROW(out.drop(s.dir / "never.txt"), zdg::IoError);
  out.commit();
  EXPECT_EQ(read(s.dir / "a.csv"), "new a");
  EXPECT_EQ(read(s.dir / "plot.png"), "old plot");
  EXPECT_EQ(s.entries(), 2u);
}

TEST(OutputFiles, WriteFileAtomically) {
  Scratch s;
  zdg::write_file_atomically((s.dir / "f").string(), "one");
  zdg::write_file_atomically((s.dir / "f").string(), "two");
  EXPECT_EQ(read(s.dir / "f"), "two");
  EXPECT_THROW(zdg::write_file_atomically((s.dir / "f").string(), "three", Existing::refuse),
               zdg::IoError);
  EXPECT_EQ(read(s.dir / "f"), "two");
  EXPECT_EQ(s.entries(), 1u);
}

// The message of the IoError that f throws ("" when none).
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const zdg::IoError& e) {
    return e.what();
  }
  return "";
}

bool has(const std::string& text, const std::string& piece) {
  return text.find(piece) != std::string::npos;
}

// The names in dir that start with '.' (staging files and backups).
std::vector<std::string> hidden_files(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string n = e.path().filename().string();
    if (!n.empty() && n[0] == '.') out.push_back(n);
  }
  return out;
}

struct WorkingDirectory {
  fs::path saved = fs::current_path();
  explicit WorkingDirectory(const fs::path& dir) { fs::current_path(dir); }
  ~WorkingDirectory() { fs::current_path(saved); }
};

// Issue #41, 4: outputs are compared as files, not as strings (`-o x.ply --csv ./x.ply` wrote
// the CSV over the mesh).
TEST(OutputFiles, OneFileNamedTwiceIsRefusedWhateverItsSpelling) {
  Scratch s;
  fs::create_directories(s.dir / "sub");
  fs::create_directory_symlink(".", s.dir / "here");
  const WorkingDirectory cwd(s.dir);
  const fs::path same[][2] = {{"x.ply", "./x.ply"},
                              {"x.ply", s.dir / "x.ply"},
                              {"./x.ply", s.dir / "." / "x.ply"},
                              {"sub/../x.ply", "x.ply"},
                              {"here/x.ply", "x.ply"},
                              {"sub/y", s.dir / "here" / "sub" / "y"}};
  for (const auto& [a, b] : same) {
    SCOPED_TRACE(a.string() + " / " + b.string());
    EXPECT_TRUE(zdg::same_output(a, b));
    OutputSet out(Existing::replace);
    out.add(a);
    const std::string e = error_of([&] { out.add(b); });
    EXPECT_TRUE(has(e, a.string()) && has(e, b.string()) && has(e, "same file")) << e;
  }
  // Two names of one existing file (a hard link): one file.
  write(s.dir / "h1", "h");
  fs::create_hard_link(s.dir / "h1", s.dir / "h2");
  EXPECT_TRUE(zdg::same_output("h1", "./h2"));
  // Different entries: other names, or a symbolic link (the rename replaces the link itself).
  fs::create_symlink("h1", s.dir / "l1");
  EXPECT_FALSE(zdg::same_output("h1", "l1"));
  EXPECT_FALSE(zdg::same_output("x.ply", "y.ply"));
  EXPECT_FALSE(zdg::same_output("x.ply", "sub/x.ply"));
  OutputSet out(Existing::replace);
  write(out.add("x.ply"), "mesh");
  write(out.add("./sub/x.ply"), "csv");
  out.commit();
  EXPECT_EQ(read(s.dir / "x.ply"), "mesh");
  EXPECT_EQ(read(s.dir / "sub" / "x.ply"), "csv");
}

TEST(OutputFiles, AnOutputThatIsTheInputIsRefused) {
  Scratch s;
  write(s.dir / "in.npy", "input");
  fs::create_hard_link(s.dir / "in.npy", s.dir / "hard.npy");
  fs::create_symlink("in.npy", s.dir / "soft.npy");
  const WorkingDirectory cwd(s.dir);
  for (const char* output : {"in.npy", "./in.npy", "hard.npy", "soft.npy", "sub/../in.npy"}) {
    SCOPED_TRACE(output);
    fs::create_directories(s.dir / "sub");
    const std::string e = error_of([&] { zdg::check_not_input("in.npy", output); });
    EXPECT_TRUE(has(e, "is the input file") && has(e, output) && has(e, "in.npy")) << e;
  }
  EXPECT_NO_THROW(zdg::check_not_input("in.npy", "out.npy"));
  EXPECT_NO_THROW(zdg::check_not_input("missing.npy", "out.npy"));
  EXPECT_EQ(read(s.dir / "in.npy"), "input");
}

// Issue #41, 10: every output is checked before the first rename: one that cannot be replaced
// (here a folder put in its place during the work; it fails even for root) leaves the others
// as they were.
TEST(OutputFiles, AnOutputThatCannotBeReplacedStopsTheCommitBeforeAnyRename) {
  Scratch s;
  write(s.dir / "a.txt", "old a");
  {
    OutputSet out(Existing::replace);
    write(out.add(s.dir / "a.txt"), "new a");
    write(out.add(s.dir / "b.txt"), "new b");
    fs::create_directories(s.dir / "b.txt" / "inside");
    const std::string e = error_of([&] { out.commit(); });
    EXPECT_TRUE(has(e, (s.dir / "b.txt").string()) && has(e, "folder")) << e;
  }
  EXPECT_EQ(read(s.dir / "a.txt"), "old a");
  EXPECT_TRUE(hidden_files(s.dir).empty());
  // A component of the folder that became a file.
  fs::remove_all(s.dir / "b.txt");
  fs::create_directories(s.dir / "sub");
  {
    OutputSet out(Existing::replace);
    write(out.add(s.dir / "a.txt"), "new a");
    write(out.add(s.dir / "sub" / "b.txt"), "new b");
    fs::remove_all(s.dir / "sub");
    write(s.dir / "sub", "a file");
    EXPECT_FALSE(error_of([&] { out.commit(); }).empty());
  }
  EXPECT_EQ(read(s.dir / "a.txt"), "old a");
  EXPECT_TRUE(hidden_files(s.dir).empty());
}

TEST(OutputFiles, OnlyRegularFilesAreReplaced) {
  Scratch s;
  ASSERT_EQ(::mkfifo((s.dir / "pipe").c_str(), 0644), 0);
  OutputSet out(Existing::replace);
  const std::string e = error_of([&] { out.add(s.dir / "pipe"); });
  EXPECT_TRUE(has(e, "not a regular file")) << e;
  EXPECT_TRUE(fs::is_fifo(s.dir / "pipe"));
}

// A rename that fails after others succeeded (the hook puts a non-empty folder where the
// output goes, between the checks and the rename): the outputs already replaced get their
// old content back, the new ones are removed, and no staging file or backup remains.
fs::path g_blocked;
void block_rename(const fs::path& final_path) {
  if (final_path == g_blocked) fs::create_directories(final_path / "inside");
}

TEST(OutputFiles, AFailedRenamePutsBackWhatWasReplaced) {
  Scratch s;
  write(s.dir / "a.txt", "old a");
  write(s.dir / "c.txt", "old c");
  g_blocked = s.dir / "c.txt.d";
  zdg::detail::before_output_rename = block_rename;
  {
    OutputSet out(Existing::replace);
    write(out.add(s.dir / "a.txt"), "new a");
    write(out.add(s.dir / "n.txt"), "new n");
    write(out.add(s.dir / "c.txt"), "new c");
    write(out.add(g_blocked), "new d");
    const std::string e = error_of([&] { out.commit(); });
    EXPECT_TRUE(has(e, g_blocked.string()) && has(e, "cannot move the output in place") &&
                has(e, "every output was left as it was"))
        << e;
  }
  zdg::detail::before_output_rename = nullptr;
  EXPECT_EQ(read(s.dir / "a.txt"), "old a");
  EXPECT_EQ(read(s.dir / "c.txt"), "old c");
  EXPECT_FALSE(fs::exists(s.dir / "n.txt"));
  EXPECT_TRUE(fs::is_directory(g_blocked)); // what "someone else" put there
  EXPECT_TRUE(hidden_files(s.dir).empty());
  // Committed, the backups are gone.
  OutputSet out(Existing::replace);
  write(out.add(s.dir / "a.txt"), "new a");
  write(out.add(s.dir / "c.txt"), "new c");
  out.commit();
  EXPECT_EQ(read(s.dir / "a.txt"), "new a");
  EXPECT_EQ(read(s.dir / "c.txt"), "new c");
  EXPECT_TRUE(hidden_files(s.dir).empty());
}

// chattr +i where the file system has it (ext4, xfs, btrfs, tmpfs from Linux 6.0); root only.
TEST(OutputFiles, AnImmutableOutputIsRefusedBeforeAnyWork) {
#if defined(__linux__) && defined(FS_IOC_SETFLAGS)
  Scratch s;
  write(s.dir / "summary.json", "old");
  const int fd = ::open((s.dir / "summary.json").c_str(), O_RDONLY);
  ASSERT_GE(fd, 0);
  int flags = 0;
  const bool set = ::ioctl(fd, FS_IOC_GETFLAGS, &flags) == 0 &&
                   (flags |= FS_IMMUTABLE_FL, ::ioctl(fd, FS_IOC_SETFLAGS, &flags) == 0);
  if (!set) {
    ::close(fd);
    GTEST_SKIP() << "no chattr +i here (" << std::strerror(errno) << ")";
  }
  OutputSet out(Existing::replace);
  write(out.add(s.dir / "results.csv"), "new");
  const std::string e = error_of([&] { out.add(s.dir / "summary.json"); });
  flags &= ~FS_IMMUTABLE_FL;
  ::ioctl(fd, FS_IOC_SETFLAGS, &flags);
  ::close(fd);
  EXPECT_TRUE(has(e, "immutable")) << e;
#else
  GTEST_SKIP() << "no inode flags";
#endif
}

// Another user's file in a sticky folder (/tmp): only its owner or the folder's may replace
// it. Checked in a child that takes another user id (the test needs root for that).
TEST(OutputFiles, AnotherUsersFileInAStickyFolderIsRefused) {
  if (::geteuid() != 0) GTEST_SKIP() << "needs root to give the file to another user";
  Scratch s;
  fs::permissions(s.dir, fs::perms::all | fs::perms::sticky_bit);
  write(s.dir / "b.png", "theirs");
  ASSERT_EQ(::chown((s.dir / "b.png").c_str(), 12345, 12345), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    if (::setegid(65534) != 0 || ::seteuid(65534) != 0) ::_exit(3);
    OutputSet out(Existing::replace);
    out.add(s.dir / "a.ply");
    const std::string e = error_of([&] { out.add(s.dir / "b.png"); });
    ::_exit(has(e, "another user in a sticky folder") ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
}

// Issue #41, 14: what a killed run left (its staging files, its backups) is cleaned by the
// next run into that folder; the files of a live process are left alone.
TEST(OutputFiles, StagingFilesOfDeadProcessesAreRemoved) {
  Scratch s;
  const pid_t dead = ::fork();
  ASSERT_GE(dead, 0);
  if (dead == 0) ::_exit(0);
  ASSERT_EQ(::waitpid(dead, nullptr, 0), dead);
  const pid_t live = ::fork();
  ASSERT_GE(live, 0);
  if (live == 0) {
    ::pause();
    ::_exit(0);
  }
  const std::string d = std::to_string(dead), l = std::to_string(live);
  write(s.dir / (".results.csv.zdg-tmp-" + d + "-3"), "stale");
  write(s.dir / (".summary.json.zdg-tmp-" + l + "-0"), "in progress");
  write(s.dir / (".kept.txt.zdg-old-" + d + "-1"), "old kept"); // its output is missing
  write(s.dir / "present.txt", "present");
  write(s.dir / (".present.txt.zdg-old-" + d + "-2"), "old present"); // its output is there
  write(s.dir / ".notes.zdg-tmp-x-1", "not a staging name");
  {
    OutputSet out(Existing::refuse);
    write(out.add(s.dir / "results.csv"), "new");
    out.commit();
  }
  ::kill(live, SIGKILL);
  ::waitpid(live, nullptr, 0);
  EXPECT_EQ(read(s.dir / "results.csv"), "new");
  EXPECT_FALSE(fs::exists(s.dir / (".results.csv.zdg-tmp-" + d + "-3")));
  EXPECT_EQ(read(s.dir / (".summary.json.zdg-tmp-" + l + "-0")), "in progress");
  EXPECT_EQ(read(s.dir / "kept.txt"), "old kept");
  EXPECT_FALSE(fs::exists(s.dir / (".kept.txt.zdg-old-" + d + "-1")));
  EXPECT_EQ(read(s.dir / "present.txt"), "present");
  EXPECT_FALSE(fs::exists(s.dir / (".present.txt.zdg-old-" + d + "-2")));
  EXPECT_TRUE(fs::exists(s.dir / ".notes.zdg-tmp-x-1"));
  EXPECT_EQ(s.entries(), 5u) << "results.csv, kept.txt, present.txt, .notes, the live one";
}

// Issue #41, 14: a writer handed the staging path names it in its error; the message the
// user sees names the output.
TEST(OutputFiles, MessagesNameTheOutputNotTheStagingFile) {
  Scratch s;
  OutputSet out(Existing::replace);
  const fs::path final_path = s.dir / "m.ply";
  const fs::path staging = out.add(final_path);
  EXPECT_EQ(zdg::name_outputs("cannot write '" + staging.string() + "' (disk full?)"),
            "cannot write '" + final_path.string() + "' (disk full?)");
  // A staging file of a staging file (a writer that stages again), and the bare file name.
  OutputSet inner(Existing::replace);
  const fs::path staging2 = inner.add(staging);
  EXPECT_EQ(zdg::name_outputs(staging2.string() + ": write failed; " + staging.filename().string()),
            final_path.string() + ": write failed; m.ply");
  EXPECT_EQ(zdg::name_outputs("nothing to rename in /x/.y.zdg-tmp-1-1"),
            "nothing to rename in /x/.y.zdg-tmp-1-1");
}

} // namespace
