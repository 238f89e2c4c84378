// Writing output files so that a failed run never leaves a truncated or clobbered file.
#pragma once

#include <string>
#include <string_view>

namespace acanthus::detail {

// Writes `bytes` to a temporary file next to `path` and renames it over `path` once complete
// (while an OutputTransaction is open, it renames the file with the run's other outputs).
// On any failure the temporary file is removed, `path` is left as it was, and InputError is thrown.
void write_file_atomically(const std::string& path, std::string_view bytes);

// Writes `bytes` to standard output (the "-" output path); throws InputError on a write error.
void write_stdout(std::string_view bytes);

}  // namespace acanthus::detail
