// Writing output files safely: atomically, all or nothing, never over an existing file by
// accident.
//
//   OutputSet out(Existing::refuse);                 // or Existing::replace (--force)
//   auto a = out.add("dt.npy"), b = out.add("dt.json");  // checked now, before any work
//   write_npy(a.string(), ...); write_text(b, ...);  // the content goes to staging files
//   out.commit();                                    // renames every staged file in place
//
// add() checks at once (so that a command fails before it computes anything): the folder of
// the output exists, is a folder and is writable; the output is not a folder nor any other
// non-regular file; an existing output is refused unless the policy is Existing::replace, and
// then it must be replaceable (not immutable or append-only, not another user's file in a
// sticky folder); no file is named twice. Outputs are compared as directory entries, not as
// strings: the canonical folder plus the file name, or the same (st_dev, st_ino) where both
// exist, so "x.ply", "./x.ply" and "$PWD/x.ply" are one file.
//
// The staging file sits in the same folder (".NAME.zdg-tmp-PID-K", so the final rename is
// atomic). commit() checks every output again, then replaces them one by one, each existing
// output kept under a hidden backup name (".NAME.zdg-old-PID-K", a hard link, or the file
// moved aside where the file system has no links) until all are in place: when a rename
// fails, the outputs already replaced get their old content back (those that did not exist
// are removed), so that the set is all or nothing; the backups are removed on success. An
// OutputSet destroyed without commit() (an exception on the way) removes its staging files.
//
// A killed run leaves its staging files behind: add() removes, in the folder of each output,
// the staging files and backups whose process (the PID in the name, this machine's) no longer
// exists; a backup whose output is missing (killed between moving it aside and the rename) is
// put back in place. Files of live processes are left alone.
//
// All failures are IoError naming the user's file (never a staging name); name_outputs()
// rewrites a message that came from a writer given a staging path.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace zdg {

enum class Existing { refuse, replace };

class OutputSet {
public:
  explicit OutputSet(Existing policy = Existing::refuse) : policy_(policy) {}
  ~OutputSet();
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  /// Declares an output; returns the staging path its content must be written to.
  std::filesystem::path add(const std::filesystem::path& final_path);
  /// Gives up an output declared by add() (an optional output that could not be made): its
  /// staging file is removed and commit() leaves that output as it was.
  void drop(const std::filesystem::path& final_path);
  /// Moves every staged file onto its output (in the order added), all or nothing.
  void commit();

private:
  struct Entry {
    std::filesystem::path final_path, staging;
  };
  Existing policy_;
  std::vector<Entry> entries_;
  std::vector<std::filesystem::path> cleaned_; // folders whose stale staging files are gone
  bool committed_ = false;
};

/// Checks that `path` could be an output under `policy` (the checks of OutputSet::add, except
/// for the names given twice).
void check_output_path(const std::filesystem::path& path, Existing policy);

/// Whether two output paths name the same file: the same directory entry (canonical folder
/// and file name), or the same existing file (st_dev and st_ino, symbolic links not followed).
/// A path whose folder does not exist is compared by its absolute, normalized spelling.
bool same_output(const std::filesystem::path& a, const std::filesystem::path& b);

/// Refuses (IoError naming both paths) an output that is the input file: the same existing
/// file (st_dev and st_ino, symbolic links followed) or the same directory entry.
void check_not_input(const std::filesystem::path& input, const std::filesystem::path& output);

/// `message` with every staging path of this process's recent outputs (the last 4096 added)
/// replaced by the output's own path: for errors thrown by a writer that was handed the
/// staging path. Thread-safe.
std::string name_outputs(std::string message);

/// Writes bytes to path through a staging file and a rename (one-file OutputSet).
void write_file_atomically(const std::string& path, std::string_view bytes,
                           Existing policy = Existing::replace);

namespace detail {
/// Test hook: when set, called by commit() just before each output is renamed in place
/// (after its backup is made), with that output's path; it may change the file system to
/// make the rename fail. Not thread-safe; for tests only.
extern void (*before_output_rename)(const std::filesystem::path& final_path);
} // namespace detail

} // namespace zdg
