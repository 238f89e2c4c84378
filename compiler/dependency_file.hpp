// The files a compilation read (the rule file and its imports, recursively), as one list that
// `acanthus compile --depfile`, acanthus_add_pattern() (CMake's DEPFILE) and the batch's cache
// keys all use, so they can never disagree on what a rule file depends on.
#pragma once

#include <string>
#include <vector>

namespace acanthus {

// `read_files` (compile_rule_file's list) made absolute and normal, each once, in read order.
std::vector<std::string> rule_file_dependencies(const std::vector<std::string>& read_files);

// A Make rule `TARGET: DEP...` as GCC's -MD writes it, which Make, Ninja and CMake's DEPFILE
// read. False with `error` set when a path cannot be spelled in that syntax (a newline in it).
bool make_dependency_rule(const std::string& target, const std::vector<std::string>& dependencies,
                          std::string& text, std::string& error);

}  // namespace acanthus
