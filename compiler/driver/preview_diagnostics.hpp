// The errors in a compiler's output (acanthus's own or the C++ compiler's, whose #line
// directives point into the rule file): `file:line:col: error: message` lines.
#pragma once

#include <string>
#include <vector>

namespace acanthus {

struct PreviewDiagnostic {
    std::string file;
    int line = 0;
    int column = 0;
    std::string message;
};

// Every `error:` (and `fatal error:`) line of `output`; notes and source excerpts are skipped.
// Messages without a location (`acanthus: error: ...`) have file set, line and column 0.
std::vector<PreviewDiagnostic> parse_diagnostics(const std::string& output);

// The C++ compiler's output as about the rule file: a diagnostic located in a .acr file (through
// the #line directives) whose excerpt is generated code gets the rule file's own line, the
// column mapped onto it and a caret there; lines about the generated file (deleted by then) go.
std::string in_rule_source(const std::string& output);

}  // namespace acanthus
