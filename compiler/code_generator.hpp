// Turns a checked PatternModel into one C++ translation unit that compiles against the
// runtime's public headers (docs/language.md, "The generated C++").
#pragma once

#include <string>

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

}  // namespace acanthus
