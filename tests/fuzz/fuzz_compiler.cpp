// libFuzzer target: scanner, parser, checks and code generation on arbitrary bytes.
// Imports are not followed (the input is one file). Built with -DACANTHUS_FUZZ=ON and clang;
// run with `scripts/fuzz compiler [SECONDS]`.
#include <cstddef>
#include <cstdint>
#include <sstream>

#include "code_generator.hpp"
#include "diagnostics.hpp"
#include "parse_driver.hpp"
#include "semantic_checker.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace acanthus;
    SourceFiles files;
    Diagnostics diagnostics(files);
    std::uint32_t index =
        files.add("fuzz.acr", std::string(reinterpret_cast<const char*>(data), size));
    ParseDriver driver(files, diagnostics);
    std::unique_ptr<ast::RuleFile> file = driver.parse(index);
    RuleProgram program;
    program.main_file = index;
    for (const ast::Section& s : file->sections) program.sections.push_back({&s, index});
    PatternModel model = check_program(program, files, diagnostics);
    if (diagnostics.error_count() == 0) {
        GenerateOptions options;
        options.output_name = "fuzz.cpp";
        std::string cpp = generate_cpp(model, files, options);
        if (cpp.empty()) __builtin_trap();
    }
    std::ostringstream out;
    diagnostics.print(out);
    return 0;
}
