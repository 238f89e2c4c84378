// Every rule file read during one compilation: its path as given, its text, its line starts.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace acanthus {

class SourceFile {
  public:
    SourceFile(std::string path, std::string text);

    const std::string& path() const { return path_; }
    const std::string& text() const { return text_; }
    // The text of 1-based line `line`, without its newline; empty past the end.
    std::string_view line_text(std::uint32_t line) const;

  private:
    std::string path_;
    std::string text_;
    mutable std::vector<std::size_t> line_starts_;  // built on first use
};

class SourceFiles {
  public:
    // Adds a file and returns its index.
    std::uint32_t add(std::string path, std::string text);
    const SourceFile& operator[](std::uint32_t index) const { return *files_.at(index); }
    std::uint32_t size() const { return static_cast<std::uint32_t>(files_.size()); }

  private:
    std::vector<std::unique_ptr<SourceFile>> files_;
};

}  // namespace acanthus
