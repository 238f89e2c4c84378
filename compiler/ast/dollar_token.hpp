// A dollar token ($$, $, $(k), $$j, $j, $j(k), $$var, $var, $var(k), $goal) found in C++ text.
#pragma once

#include <string>

#include "../source_range.hpp"

namespace acanthus::ast {

struct DollarToken {
    enum class Target {
        parent,  // $$, $, $(k)
        child,   // $$j, $j, $j(k)
        var,     // $$var, $var, $var(k)
        goal,    // $goal
        bad,     // a '$' form the language does not have; `problem` says why
    };
    Target target = Target::parent;
    bool element = false;         // $$ forms: the element itself rather than one of its proxies
    long child = -1;              // j for Target::child (-1 when the number does not fit)
    std::string var;              // var for Target::var
    long proxy = 0;               // k of (k); 0 when absent (-1 when the number does not fit)
    bool explicit_proxy = false;  // written with (k)
    std::string problem;          // for Target::bad
    SourceRange where;            // the token's extent in its file
};

}  // namespace acanthus::ast
