// Braces of one C++ body, counted by the scanner outside strings, characters, comments and
// preprocessor lines, so that an unclosed '{' is reported at its own .acr line instead of as a
// C++ error somewhere in the generated file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "diagnostics.hpp"
#include "source_range.hpp"

namespace acanthus {

class BraceBalance {
  public:
    // Positions kept for at most this many open braces (deeper nesting is only counted).
    static constexpr std::size_t kMaxTracked = 4096;

    // `indent`: the indentation (columns) of the brace's line.
    void open(const SourceRange& where, std::uint32_t indent);
    // An unmatched '}' is reported once per body.
    void close(const SourceRange& where, std::uint32_t indent, Diagnostics& diagnostics,
               const std::string& section);
    // At the end marker, when a '{' is still open, reports the brace whose '}' is missing: the
    // first '{' closed by a '}' indented less than its own line (the '}' that was meant for an
    // outer brace), else the innermost '{' still open. Then starts over.
    void finish(const SourceRange& end_marker, Diagnostics& diagnostics, const std::string& section,
                const std::string& end_marker_name);
    // Starts over without reporting (an unterminated section has its own error).
    void reset();

    // Inside a preprocessor line ('#' first on the line, with '\' continuations).
    bool in_directive = false;

  private:
    struct Open {
        SourceRange where;
        std::uint32_t indent;
    };
    std::vector<Open> open_;
    std::size_t depth_ = 0;
    bool have_suspect_ = false;
    SourceRange suspect_;
    bool reported_unmatched_ = false;
};

}  // namespace acanthus
