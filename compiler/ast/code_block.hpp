// Raw C++ text of a section body, kept as a byte range of its file plus its dollar tokens.
#pragma once

#include <vector>

#include "../source_range.hpp"
#include "dollar_token.hpp"

namespace acanthus::ast {

struct CodeBlock {
    SourcePosition begin;  // first byte of the body
    SourcePosition end;    // one past the last byte (the start of the end marker's line)
    std::vector<DollarToken> dollars;  // in text order
    bool terminated = true;            // false: end of file came before the end marker
    bool present = true;               // false: a %rule reached %endrule without a '{' body
};

}  // namespace acanthus::ast
