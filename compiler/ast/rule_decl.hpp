// %rule / parent --> child... / * var type... / { body } / %endrule
#pragma once

#include <vector>

#include "code_block.hpp"
#include "dynamic_child_decl.hpp"
#include "name.hpp"

namespace acanthus::ast {

struct RuleDecl {
    SourceRange keyword;  // the %rule token
    Name parent;
    std::vector<Name> children;  // static children, in order
    std::vector<DynamicChildDecl> dynamics;
    CodeBlock body;  // starts at '{'
};

}  // namespace acanthus::ast
