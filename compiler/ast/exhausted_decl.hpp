// %exhausted / C++ statements returning CONTINUE or STOP / %endexhausted
#pragma once

#include "code_block.hpp"

namespace acanthus::ast {

struct ExhaustedDecl {
    SourceRange keyword;
    CodeBlock body;
};

}  // namespace acanthus::ast
