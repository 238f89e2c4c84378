// Reading an input file (rule file, import, region SVG, stroke SVG, ...) the one safe way:
// regular files only, never blocking on a FIFO, never reading more than a size limit.
#pragma once

#include <cstddef>
#include <string>

namespace acanthus {

// Larger inputs are refused while reading (a device or a growing file cannot exhaust memory).
inline constexpr std::size_t kMaxInputFileBytes = std::size_t{64} << 20;

// Reads the whole file at `path` into `text`. Returns an empty string on success, otherwise
// why not, e.g. "not a regular file (a FIFO)", "larger than the 64 MiB limit" or the system's
// error text. Directories, FIFOs, sockets and devices are refused without reading; at most
// `max_bytes` + 1 bytes are ever read.
std::string read_input_file(const std::string& path, std::string& text,
                            std::size_t max_bytes = kMaxInputFileBytes);

// read_input_file(), throwing InputError "<path>: cannot read <what>: <why>" on failure.
std::string read_input_file_or_throw(const std::string& path, const std::string& what,
                                     std::size_t max_bytes = kMaxInputFileBytes);

}  // namespace acanthus
