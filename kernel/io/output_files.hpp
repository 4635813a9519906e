// Writing output files safely: atomically, all or nothing, never over an existing file by
// accident.
//
//   OutputSet out(Existing::refuse);                 // or Existing::replace (--force)
//   auto a = out.add("dt.npy"), b = out.add("dt.json");  // checked now, before any work
//   write_npy(a.string(), ...); write_text(b, ...);  // the content goes to staging files
//   out.commit();                                    // renames every staged file in place
//
// add() checks at once (so that a command fails before it computes anything): the folder of
// the output exists and is a folder, the output is not a folder, no output is named twice,
// and an existing output is refused unless the policy is Existing::replace. The staging file
// sits in the same folder (".NAME.zdg-tmp-PID-K", so the final rename is atomic). commit()
// renames them all; an OutputSet destroyed without commit() (an exception on the way) removes
// its staging files, so a failed command leaves the outputs as they were.
// All failures are IoError naming the file.
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
  /// Renames every staged file onto its output (in the order added).
  void commit();

private:
  struct Entry {
    std::filesystem::path final_path, staging;
  };
  Existing policy_;
  std::vector<Entry> entries_;
  bool committed_ = false;
};

/// Checks that `path` could be an output under `policy` (the checks of OutputSet::add).
void check_output_path(const std::filesystem::path& path, Existing policy);

/// Writes bytes to path through a staging file and a rename (one-file OutputSet).
void write_file_atomically(const std::string& path, std::string_view bytes,
                           Existing policy = Existing::replace);

} // namespace zdg
