// An identifier as written in a rule file, with where it stands.
#pragma once

#include <string>

#include "../source_range.hpp"

namespace acanthus::ast {

struct Name {
    std::string text;
    SourceRange where;
};

}  // namespace acanthus::ast
