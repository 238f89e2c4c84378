// Positions in rule files: what diagnostics point at and what #line directives name.
#pragma once

#include <cstddef>
#include <cstdint>

namespace acanthus {

// A point in a loaded file. Lines and columns are 1-based; columns count bytes.
struct SourcePosition {
    std::uint32_t file = 0;  // index into SourceFiles
    std::uint32_t line = 1;
    std::uint32_t column = 1;
    std::size_t offset = 0;  // byte offset into the file's text
};

// Half-open range [begin, end) of one file; also the Bison location type.
struct SourceRange {
    SourcePosition begin;
    SourcePosition end;
    // Bison's default location actions and error reporting need nothing more.
};

}  // namespace acanthus
