// %import "name": the named rule file's sections stand here.
#pragma once

#include "name.hpp"

namespace acanthus::ast {

struct RuleFile;

struct ImportDecl {
    SourceRange keyword;
    Name target;  // the name between the quotes
    // The imported file once resolved; null when not found, cyclic, or already imported.
    const RuleFile* file = nullptr;
};

}  // namespace acanthus::ast
