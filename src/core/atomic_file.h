// Crash-safe output: write to a temporary file beside the target, flush, fsync, rename.
// A reader sees either the old file or the complete new one, never a half-written file.
#pragma once

#include <string>

namespace mg {

// Creates parent directories as needed. Throws std::runtime_error on I/O failure.
void write_file_atomic(const std::string& path, const std::string& content);

}  // namespace mg
