// The output folder of a run and the record of what slamsph wrote in it.
//
// A folder holds a run when it has the manifest (kManifest), a summary.json or a
// case.resolved.toml. `slamsph run` refuses such a folder (exit 2) unless --overwrite, so
// that two runs' files are never mixed; --overwrite removes what slamsph wrote there and
// nothing else: the files listed in the manifest, and in folders slamsph created (vtk/,
// checkpoints/) only files with the names slamsph writes there. The user's own files in
// the folder are kept. `slamsph resume` continues a run in place and adds to its manifest.
//
// The manifest is a text file, one path per line relative to the folder ("forces.csv",
// "vtk/fluid_00003.vtp"; a folder slamsph created ends in "/"). It is written before any
// other file (with the names the run is about to write) and brought up to date with every
// file that appeared since the folder was opened at each checkpoint and at the end of the
// run (OutputFolder::record), always whole (temporary file and rename).
#pragma once
#include <set>
#include <string>
#include <vector>

namespace slamsph {

class OutputFolder {
 public:
  static constexpr const char* kManifest = ".slamsph_files";

  // True when `dir` holds a run (manifest, summary.json or case.resolved.toml).
  static bool holds_run(const std::string& dir);
  // Throws InputError (exit 2) if `dir` holds a run and `overwrite` is false; names the
  // folder and --overwrite. Called before the case is built, so nothing is computed.
  static void check_free(const std::string& dir, bool overwrite);

  enum class Mode {
    Fresh,     // a new run: clears a previous run's files first (the --overwrite case)
    Continue,  // `resume`: keeps the files and the manifest, adds to it
  };
  // Creates `dir` (std::system_error with path and reason if it cannot), clears a previous
  // run (Mode::Fresh) and notes which files exist now: those are not this run's.
  OutputFolder(std::string dir, Mode mode);

  const std::string& dir() const { return dir_; }
  // Adds `names` (relative paths the run is about to write; folders end in "/") and every
  // file or folder that appeared since the constructor, then rewrites the manifest.
  void record(const std::vector<std::string>& names = {});

  // Removes the files of the run in `dir` (see the header comment); returns how many.
  static std::size_t clear_run(const std::string& dir);

 private:
  std::string dir_;
  std::set<std::string> before_;  // relative paths that existed when the folder was opened
  std::set<std::string> listed_;  // the manifest's entries
};

}  // namespace slamsph
