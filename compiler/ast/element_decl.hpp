// %element name kind... / member declarations / %endelement
#pragma once

#include <vector>

#include "code_block.hpp"
#include "name.hpp"

namespace acanthus::ast {

struct ElementDecl {
    SourceRange keyword;       // the %element token
    std::vector<Name> header;  // name followed by proxy kinds, as written
    CodeBlock members;         // user field declarations
};

}  // namespace acanthus::ast
