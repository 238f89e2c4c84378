// Turns a checked PatternModel into one C++ translation unit that compiles against the
// runtime's public headers (docs/language.md, "The generated C++").
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "pattern_model.hpp"
#include "source_files.hpp"

namespace acanthus {

struct GenerateOptions {
    std::string output_name;      // the generated file's name in #line directives back to it
    bool line_directives = true;  // --no-line-directives turns them off
    bool emit_main = true;        // false: export acanthus_pattern() instead of main()
};

std::string generate_cpp(const PatternModel& model, const SourceFiles& files,
                         const GenerateOptions& options);

// The same program as translation units that change independently, for the preview's builds
// (a save that edits one rule body compiles one small unit). Only with `emit_main` false.
struct GeneratedUnits {
    std::string tables;              // the pattern's tables, no user code
    std::string header;              // what `code` and each rule unit start with (no tables)
    std::string code;                // %draw, %exhausted, the parameters' access, element creation
    std::vector<std::string> rules;  // one per rule, in the pattern's order
};
GeneratedUnits generate_cpp_units(const PatternModel& model, const SourceFiles& files,
                                  const GenerateOptions& options);

// `cpp` (%source text) with its variables and functions at namespace scope made `inline`: every
// split unit includes the %source, and its variables and functions must be one, not one per
// unit or a definition twice. `static` becomes `inline` in place; other definitions get an
// `inline ` in front. Templates, constants (`constexpr`) and declarations are left alone.
std::string inline_namespace_definitions(std::string_view cpp);

}  // namespace acanthus
