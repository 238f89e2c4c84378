// Writes files through a temporary name in the same directory and a rename, so a failed run
// never leaves a partial output behind.
#pragma once

#include <string>
#include <string_view>

namespace acanthus {

// Writes `content` to `path` atomically; false with `error` set on failure.
bool write_file_atomically(const std::string& path, std::string_view content, std::string& error);

// A unique temporary name next to `path` (same directory, so rename() is atomic). The file
// exists (empty) when this returns; remove_if_present() cleans it up.
std::string temporary_sibling(const std::string& path, std::string& error);
void remove_if_present(const std::string& path);

}  // namespace acanthus
