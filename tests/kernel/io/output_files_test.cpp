#include <zdg/kernel/io/output_files.hpp>

#include <zdg/arith/error.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

#include <unistd.h>

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

} // namespace
