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
    // The source around the line (add_source_context): its first line's number and the lines.
    int context_first = 0;
    std::vector<std::string> context{};
};

// Every `error:` (and `fatal error:`) line of `output`; notes and source excerpts are skipped.
// Messages without a location (`acanthus: error: ...`) have file set, line and column 0.
std::vector<PreviewDiagnostic> parse_diagnostics(const std::string& output);

// A path by which two names of one file compare equal (links and `..` resolved).
std::string same_file_key(const std::string& path);

// The `around` lines before and after each located diagnostic's line, for the diagnostics in one
// of `files` (the rule file and its imports: nothing else is read).
void add_source_context(std::vector<PreviewDiagnostic>& diagnostics,
                        const std::vector<std::string>& files, int around = 2);

// The editor command for a file at a line and column: `command`'s words (split like a shell's,
// quotes kept together, nothing expanded) with {file}, {line} and {column} replaced; a command
// without {file} gets `+LINE FILE` (the convention of vi, emacs, nano, gedit and kate).
std::vector<std::string> editor_command(const std::string& command, const std::string& file,
                                        int line, int column);

// The C++ compiler's output as about the rule file: a diagnostic located in a .acr file (through
// the #line directives) whose excerpt is generated code gets the rule file's own line, the
// column mapped onto it and a caret there; lines about the generated file (deleted by then) go.
std::string in_rule_source(const std::string& output);

}  // namespace acanthus
