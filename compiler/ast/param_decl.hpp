// %param TYPE NAME = DEFAULT [in [LO, HI]];
#pragma once

#include <optional>
#include <vector>

#include "name.hpp"

namespace acanthus::ast {

// `in [LO, HI]`: the values a numeric parameter may take, bounds included.
struct ParamRange {
    SourceRange where;  // from `in` to `]`
    Name low;
    Name high;
};

struct ParamDecl {
    SourceRange keyword;
    std::vector<Name> type;  // one or more words, e.g. `double` or `std::string`
    Name name;
    Name default_value;  // the default as written (string literals keep their quotes)
    std::optional<ParamRange> range;
};

}  // namespace acanthus::ast
