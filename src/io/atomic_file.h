// Whole-file writes that never leave a half-written file under the final name: the text
// goes to "<path>.tmp", is flushed to the disk, and is then renamed over <path> (rename is
// atomic on POSIX file systems). Used for the files a reader takes as a whole
// (summary.json, case.resolved.toml, the output manifest).
#pragma once
#include <string>

namespace slamsph {

// Throws std::system_error naming the path and the OS reason (errno) when the file cannot
// be created, written (e.g. disk full), flushed or renamed; the temporary file is removed.
void write_file_atomically(const std::string& path, const std::string& text);

}  // namespace slamsph
