// One run of the front end and code generator over a rule file: load with imports, check,
// generate. Diagnostics are printed to `diagnostics_out`.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "code_generator.hpp"

namespace acanthus {

struct CompileRequest {
    std::string input;                      // rule file path as given
    std::vector<std::string> include_dirs;  // -I, in order
    std::vector<std::string> stdlib_dirs;   // searched after the -I directories
    GenerateOptions generate;
};

// A checked %param, as the preview shows it.
struct ParamSummary {
    std::string name;
    std::string type;          // "double", "std::string", ...
    std::string default_text;  // as written
    std::string low, high;     // `in [LO, HI]`, empty when not declared
};

// True with `cpp` set when the rule file has no errors. `generate_code` false only checks.
// `read_files`, when given, receives the path of every rule file read (the input, its imports);
// `units`, the same program split into units (generate_cpp_units).
bool compile_rule_file(const CompileRequest& request, bool generate_code, std::string& cpp,
                       std::ostream& diagnostics_out,
                       std::vector<std::string>* read_files = nullptr,
                       std::vector<ParamSummary>* params = nullptr,
                       GeneratedUnits* units = nullptr);

}  // namespace acanthus
