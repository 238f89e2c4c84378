// %draw TYPE / C++ statements drawing one element through `canvas` / %enddraw
#pragma once

#include <vector>

#include "code_block.hpp"
#include "name.hpp"

namespace acanthus::ast {

struct DrawDecl {
    SourceRange keyword;
    std::vector<Name> header;  // exactly one name when well formed
    CodeBlock body;
};

}  // namespace acanthus::ast
