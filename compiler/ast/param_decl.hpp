// %param TYPE NAME = DEFAULT;
#pragma once

#include <vector>

#include "name.hpp"

namespace acanthus::ast {

struct ParamDecl {
    SourceRange keyword;
    std::vector<Name> type;  // one or more words, e.g. `double` or `std::string`
    Name name;
    Name default_value;  // the default as written (string literals keep their quotes)
};

}  // namespace acanthus::ast
