// A Pattern as constant tables, which generated code gives make_pattern(): the rule file's code
// then constructs no strings or vectors of its own (less code to build at every save).
#pragma once

#include <acanthus/pattern.hpp>
#include <cstddef>
#include <string>
#include <string_view>

namespace acanthus {

struct RuleEntry {
    const char* name;
    int line;
    const char* file;
    const ElementType* parent;
    const ElementType* const* children;  // child_count of them (null when none)
    std::size_t child_count;
    Result (*body)(RuleCall&);
};

struct ParamEntry {
    const char* name;
    const char* type;
    const char* default_text;
    int line;
    bool (*assign)(std::string_view text, std::string& error);
    std::string (*current)();
    const char* low;
    const char* high;
};

struct PatternTables {
    const char* name;
    const char* file;
    const ElementType* const* types;
    std::size_t type_count;
    const ElementType* seed;
    const RuleEntry* rules;
    std::size_t rule_count;
    const ParamEntry* params;  // null when none
    std::size_t param_count;
    Flow (*exhausted)();
    int exhausted_line;
};

Pattern make_pattern(const PatternTables& tables);

}  // namespace acanthus
