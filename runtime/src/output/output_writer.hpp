// Where a run's output bytes go: a file written atomically (with the run's other outputs while
// an OutputTransaction is open) or standard output.
#pragma once

#include <string>
#include <string_view>

namespace acanthus::detail {

// Writes `bytes` to a temporary file next to `path` and renames it over `path` once complete
// (while an OutputTransaction is open, it renames the file with the run's other outputs).
// On any failure the temporary file is removed, `path` is left as it was, and InputError is thrown.
void write_output_file(const std::string& path, std::string_view bytes);

// Writes `bytes` to standard output (the "-" output path); throws InputError on a write error.
void write_stdout(std::string_view bytes);

// An output path as the options give it: "-" is standard output, anything else a file written
// with write_output_file().
void write_output(const std::string& path, std::string_view bytes);

}  // namespace acanthus::detail
