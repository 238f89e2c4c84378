#include "batch/rule_programs.hpp"

#include <filesystem>
#include <sstream>

#include "batch/child_process.hpp"
#include "batch/job_state.hpp"
#include "compilation.hpp"
#include "dependency_file.hpp"
#include "toolchain/toolchain_config.hpp"

namespace acanthus::batch {

namespace fs = std::filesystem;

RuleProgram prepare_rule_program(const std::string& rule, const Toolchain& toolchain,
                                 const BuildOptions& options) {
    RuleProgram program;
    program.rule = rule;
    CompileRequest request;
    request.input = rule;
    request.stdlib_dirs = toolchain.stdlib_dirs;
    request.generate.output_name = fs::path(rule).stem().string() + ".cpp";
    std::ostringstream diagnostics;
    std::vector<std::string> read_files;
    if (!compile_rule_file(request, true, program.cpp, diagnostics, &read_files)) {
        program.error = diagnostics.str();
        if (program.error.empty()) program.error = rule + ": the rule file has errors";
        return program;
    }
    std::vector<std::string> parts{program.cpp, ACANTHUS_VERSION_STRING,
                                   file_identity(toolchain.runtime_library),
                                   file_identity(toolchain.stdlib_library)};
    // The C++ misses what generates no code (a comment, an import's own text): the files count
    // too, the same list a CMake build's depfile names.
    program.dependencies = rule_file_dependencies(read_files);
    for (const std::string& file : program.dependencies)
        parts.insert(parts.end(), {"read", file, content_key(file)});
    for (const std::string& part : compile_command(toolchain, options, "SOURCE", "EXECUTABLE"))
        parts.push_back(part);
    program.key = cache_key(parts);
    return program;
}

bool build_rule_program(RuleProgram& program, const Toolchain& toolchain,
                        const BuildOptions& options) {
    if (!program.error.empty()) return false;
    BuildOptions captured = options;
    // The compiler's messages become the failure's message instead of interleaving on stderr.
    // build_executable() replaces the error text with the exit status, so keep them aside.
    std::string messages;
    captured.runner = [&messages](const std::vector<std::string>& cmd, std::string& error) {
        ChildResult child = run_child(cmd, "", true);
        messages = child.output;
        if (child.exit_status < 0) error = child.error;
        return child.exit_status;
    };
    std::string error;
    const std::string stem = fs::path(program.rule).stem().string();
    if (!cached_executable(toolchain, captured, stem, program.cpp, program.executable, error)) {
        program.error = messages.empty() ? error : error + "\n" + messages;
        return false;
    }
    return true;
}

}  // namespace acanthus::batch
