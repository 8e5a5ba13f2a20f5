#include "app/output_folder.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "core/error.h"
#include "io/atomic_file.h"

namespace slamsph {

namespace fs = std::filesystem;

namespace {

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// Every file and folder under `dir`, relative, folders with a trailing '/'; the manifest
// and temporary files (".tmp", renamed in a moment) are not listed.
std::set<std::string> list_tree(const std::string& dir) {
  std::set<std::string> out;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::end(it);
       it.increment(ec)) {
    std::string rel = it->path().lexically_relative(dir).generic_string();
    if (rel.empty() || rel == ".") continue;
    if (rel == OutputFolder::kManifest || ends_with(rel, ".tmp")) continue;
    if (it->is_directory(ec) && !it->is_symlink(ec)) rel += '/';
    out.insert(rel);
  }
  return out;
}

std::vector<std::string> read_manifest(const std::string& dir) {
  std::vector<std::string> out;
  std::ifstream in(dir + "/" + OutputFolder::kManifest);
  std::string line;
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#') out.push_back(line);
  return out;
}

// What a run of slamsph before the manifest existed (session 3) wrote: used to clear such
// a folder with --overwrite.
std::vector<std::string> legacy_manifest() {
  return {"case.resolved.toml",
          "summary.json",
          "forces.csv",
          "probes.csv",
          "bodies.csv",
          "energy.csv",
          "fields.pvd",
          "slamming_force.png",
          "slamming_force.gp",
          "surge_front.gp",
          "slamming_coefficient.png",
          "slamming_coefficient.gp",
          "surge_front.png",
          "plate_tip.png",
          "plate_tip.gp",
          "gate_tip.png",
          "gate_tip.gp",
          "vtk/",
          "checkpoints/"};
}

// A file slamsph writes inside a folder it created (VTK frames and collections,
// checkpoints, plots): removed from such a folder even when a killed run could not list it.
bool slamsph_file_name(const std::string& name) {
  for (const char* ext : {".vtp", ".pvd", ".bin", ".png", ".gp", ".csv", ".tmp"})
    if (ends_with(name, ext)) return true;
  return false;
}

}  // namespace

bool OutputFolder::holds_run(const std::string& dir) {
  std::error_code ec;
  for (const char* f : {kManifest, "summary.json", "case.resolved.toml"})
    if (fs::exists(fs::path(dir) / f, ec)) return true;
  return false;
}

void OutputFolder::check_free(const std::string& dir, bool overwrite) {
  if (overwrite || !holds_run(dir)) return;
  throw InputError(dir +
                   ": the folder holds the results of another run; use --overwrite to replace "
                   "them (only the files slamsph wrote there are removed) or choose another "
                   "--out");
}

std::size_t OutputFolder::clear_run(const std::string& dir) {
  std::vector<std::string> entries = read_manifest(dir);
  std::error_code ec;
  if (entries.empty() && holds_run(dir)) entries = legacy_manifest();
  std::size_t removed = 0;
  std::vector<std::string> folders;
  for (const std::string& e : entries) {
    if (e.empty() || e.find("..") != std::string::npos || e[0] == '/') continue;  // not ours
    if (e.back() == '/') {
      folders.push_back(e);
      continue;
    }
    const fs::path p = fs::path(dir) / e;
    if (fs::is_symlink(p, ec) || fs::is_regular_file(p, ec)) removed += fs::remove(p, ec) ? 1 : 0;
  }
  // Deepest folders first; a folder is removed only when nothing but slamsph's files was in it.
  std::sort(folders.begin(), folders.end(), [](const std::string& a, const std::string& b) {
    return std::count(a.begin(), a.end(), '/') > std::count(b.begin(), b.end(), '/');
  });
  for (const std::string& f : folders) {
    const fs::path p = fs::path(dir) / f;
    if (!fs::is_directory(p, ec) || fs::is_symlink(fs::path(dir) / f.substr(0, f.size() - 1), ec))
      continue;
    for (const auto& e : fs::directory_iterator(p, ec))
      if ((e.is_regular_file(ec) || e.is_symlink(ec)) &&
          slamsph_file_name(e.path().filename().string()))
        removed += fs::remove(e.path(), ec) ? 1 : 0;
    if (fs::is_empty(p, ec)) fs::remove(p, ec);
  }
  for (const char* f : {"summary.json.tmp", "case.resolved.toml.tmp", "fields.pvd.tmp"})
    fs::remove(fs::path(dir) / f, ec);
  fs::remove(fs::path(dir) / (std::string(kManifest) + ".tmp"), ec);
  fs::remove(fs::path(dir) / kManifest, ec);
  return removed;
}

OutputFolder::OutputFolder(std::string dir, Mode mode) : dir_(std::move(dir)) {
  fs::create_directories(dir_);  // std::filesystem_error (a std::system_error): exit 4
  if (mode == Mode::Fresh) {
    if (holds_run(dir_)) clear_run(dir_);
  } else {
    for (const std::string& e : read_manifest(dir_)) listed_.insert(e);
  }
  before_ = list_tree(dir_);
}

void OutputFolder::record(const std::vector<std::string>& names) {
  for (const std::string& n : names)
    if (n.empty() || n.back() != '/' || !before_.count(n)) listed_.insert(n);
  for (const std::string& n : list_tree(dir_))
    if (!before_.count(n)) listed_.insert(n);
  std::string text =
      "# Files and folders (ending in /) slamsph wrote here. 'slamsph run --overwrite' removes\n"
      "# these and nothing else; do not edit.\n";
  for (const std::string& n : listed_) text += n + "\n";
  write_file_atomically(dir_ + "/" + kManifest, text);
}

}  // namespace slamsph
