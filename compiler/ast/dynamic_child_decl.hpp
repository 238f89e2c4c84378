// `* var type` in a rule preamble: `var` will hold a dynamic child of `type`.
#pragma once

#include "name.hpp"

namespace acanthus::ast {

struct DynamicChildDecl {
    Name var;
    Name type;
};

}  // namespace acanthus::ast
