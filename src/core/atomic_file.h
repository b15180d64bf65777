// Crash-safe output: the content is written to an unnamed file in the target's directory
// (O_TMPFILE), flushed and fsynced, then linked in under its name (a new file) or under a
// temporary name renamed over the old one. A reader sees either the old file or the complete new
// one, never a half-written file; a killed writer leaves at most a temporary file named
// `<target>.tmp.<pid>.<n>` (only where O_TMPFILE is unsupported, or in the instant between link
// and rename), which remove_stale_temporaries() deletes.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace mg {

// Creates parent directories as needed. Throws std::runtime_error on I/O failure (the message
// names the path); nothing is left behind then.
void write_file_atomic(const std::string& path, const std::string& content);

// Several files that belong together (a report's json, md and html): each written as above, in
// order; when one fails, those already written by this call are removed before the error
// propagates, so no partial set is left.
void write_files_atomic(const std::vector<std::pair<std::string, std::string>>& path_and_content);

// Deletes the temporary files of write_file_atomic left in `dir` by processes that no longer
// run (killed while writing); returns how many. Files of live writers are left alone.
int remove_stale_temporaries(const std::string& dir);

}  // namespace mg
