// %source / verbatim C++ at namespace scope / %endsource
#pragma once

#include "code_block.hpp"

namespace acanthus::ast {

struct SourceDecl {
    SourceRange keyword;
    CodeBlock code;
};

}  // namespace acanthus::ast
