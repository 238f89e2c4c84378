// A rule file with its imports resolved: every section in rule order (imports stand where
// their %import line stands), each with the file it came from.
#pragma once

#include <cstdint>
#include <vector>

#include "ast/rule_file.hpp"

namespace acanthus {

struct SectionRef {
    const ast::Section* section = nullptr;
    std::uint32_t file = 0;
};

struct RuleProgram {
    std::uint32_t main_file = 0;
    std::vector<SectionRef> sections;
};

}  // namespace acanthus
