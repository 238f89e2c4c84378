// Checks a rule program against the language's rules (section 4 of DESIGN.md) and builds the
// PatternModel the code generator uses. Every problem found goes to the diagnostics.
#pragma once

#include "diagnostics.hpp"
#include "pattern_model.hpp"
#include "rule_program.hpp"

namespace acanthus {

PatternModel check_program(const RuleProgram& program, const SourceFiles& files,
                           Diagnostics& diagnostics);

}  // namespace acanthus
