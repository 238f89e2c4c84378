// Writing a file the one safe way, shared by the compiler and the runtime: the bytes go to a
// temporary file next to the target, renamed over it only once complete.
#pragma once

#include <string>
#include <string_view>

namespace acanthus {

// Creates an empty temporary file next to `path` (same directory, so the final rename is atomic)
// with the mode a plain open() would give it. Returns its name, or "" with `error` set.
std::string create_temporary_sibling(const std::string& path, std::string& error);

// Writes `bytes` to a new temporary sibling of `path` and returns its name; on failure returns ""
// with `error` set ("cannot write '<path>': <why>") and leaves nothing behind.
std::string write_temporary_sibling(const std::string& path, std::string_view bytes,
                                    std::string& error);

// Renames `temporary` over `path`; on failure removes `temporary` and returns false with `error`.
bool replace_with_temporary(const std::string& temporary, const std::string& path,
                            std::string& error);

// write_temporary_sibling() then replace_with_temporary(): `path` is either the old file or
// the whole new one.
bool write_file_atomically(const std::string& path, std::string_view bytes, std::string& error);

// Removes `path` if it names a file; errors are ignored (cleanup on a failure path).
void remove_if_present(const std::string& path);

}  // namespace acanthus
