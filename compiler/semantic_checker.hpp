// Checks a rule program against the language's rules (docs/language.md) and builds the
// PatternModel the code generator uses. Every problem found goes to the diagnostics.
#pragma once

#include "diagnostics.hpp"
#include "pattern_model.hpp"
#include "rule_program.hpp"

namespace acanthus {

PatternModel check_program(const RuleProgram& program, const SourceFiles& files,
                           Diagnostics& diagnostics);

}  // namespace acanthus
