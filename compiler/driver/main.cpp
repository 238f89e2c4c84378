// acanthus: compiles rule files (.acr) to C++, checks them, builds and runs them.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <acanthus/output_file.hpp>
#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>

#include "batch/batch_command.hpp"
#include "compilation.hpp"
#include "dependency_file.hpp"
#include "driver/preview_command.hpp"
#include "toolchain/program_build.hpp"
#include "toolchain/toolchain.hpp"
#include "toolchain/toolchain_config.hpp"

namespace {

namespace fs = std::filesystem;
using acanthus::BuildOptions;
using acanthus::CompileRequest;
using acanthus::Toolchain;

constexpr int kBadInput = 1;
constexpr int kBadUsage = 2;

std::string stem_of(const std::string& path) {
    std::string stem = fs::path(path).stem().string();
    return stem.empty() ? "pattern" : stem;
}

CompileRequest make_request(const std::string& input, const std::vector<std::string>& includes,
                            const Toolchain& toolchain) {
    CompileRequest r;
    r.input = input;
    r.include_dirs = includes;
    r.stdlib_dirs = toolchain.stdlib_dirs;
    return r;
}

int fail(const std::string& message) {
    std::cerr << "acanthus: error: " << message << '\n';
    return kBadInput;
}

constexpr const char* kCommands[] = {"compile", "check", "build", "run", "preview", "batch"};

// CLI11 would say "A subcommand is required"; name the word and list the commands instead.
bool report_unknown_command(int argc, char** argv) {
    std::string word = argc > 1 ? argv[1] : "";
    if (!word.empty() && word[0] == '-') return false;  // options are CLI11's business
    for (const char* c : kCommands)
        if (word == c) return false;
    if (word.empty())
        std::cerr << "acanthus: error: a command is required";
    else
        std::cerr << "acanthus: error: unknown command '" << word << "'";
    std::cerr << "; the commands are:\n"
              << "  compile  compile a rule file to one C++ file\n"
              << "  check    check a rule file and report every error\n"
              << "  build    build a rule file into an executable program\n"
              << "  run      build a rule file (cached) and run it\n"
              << "  preview  serve a live page of a rule file's render, updated on save\n"
              << "  batch    render a manifest's jobs in parallel, check them against references\n"
              << "Run 'acanthus --help' for the options.\n";
    return true;
}

std::string canonical_or_same(const std::string& path) {
    std::error_code ec;
    fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
    return ec ? path : p.string();
}

// An output that would replace a rule file the compilation read (the file or an import).
std::string overwritten_input(const std::string& output, const std::vector<std::string>& inputs) {
    if (output.empty() || output == "-") return {};
    const std::string out = canonical_or_same(output);
    for (const std::string& in : inputs)
        if (canonical_or_same(in) == out) return in;
    return {};
}

int refuse_overwrite(const std::string& output, const std::string& input,
                     const char* option = "-o") {
    std::cerr << "acanthus: error: the output '" << output << "' would overwrite the input '"
              << input << "'; choose another " << option << "\n";
    return kBadUsage;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "acanthus: the Acanthus rule compiler.\n"
        "Compiles a rule file (.acr) to C++, checks it, builds it into a program or runs it."};
    app.set_version_flag("--version", std::string("acanthus ") + ACANTHUS_VERSION_STRING);
    app.require_subcommand(1);
    if (report_unknown_command(argc, argv)) return kBadUsage;

    std::string input, output, depfile;
    std::vector<std::string> includes;
    bool no_lines = false, no_main = false;
    BuildOptions build_options;

    auto* compile = app.add_subcommand("compile", "Compile a rule file to one C++ file");
    compile->add_option("file", input, "Rule file (.acr)")->required();
    compile->add_option("-o,--output", output,
                        "Output C++ file ('-' for stdout; default: FILE's stem + .cpp)");
    compile->add_option("-I", includes, "Directory searched by %import (repeatable, in order)")
        ->allow_extra_args(false);
    compile->add_flag("--no-line-directives", no_lines, "Do not emit #line directives");
    compile->add_flag("--no-main", no_main, "Export acanthus_pattern() instead of main()");
    compile->add_option("--depfile", depfile,
                        "Also write the files the rule file read (it and its imports) as a Make "
                        "rule for OUTPUT (CMake's DEPFILE, Ninja, Make)");

    auto* check = app.add_subcommand("check", "Check a rule file and report every error");
    check->add_option("file", input, "Rule file (.acr)")->required();
    check->add_option("-I", includes, "Directory searched by %import (repeatable, in order)")
        ->allow_extra_args(false);

    auto* build = app.add_subcommand("build", "Build a rule file into an executable program");
    build->add_option("file", input, "Rule file (.acr)")->required();
    build->add_option("-o,--output", output, "Executable to write (default: FILE's stem)");
    build->add_option("-I", includes, "Directory searched by %import (repeatable, in order)")
        ->allow_extra_args(false);
    build->add_option("--cxx", build_options.cxx,
                      "C++ compiler (default: $CXX, then the one Acanthus was built with)");
    build->add_option("-O", build_options.optimization, "Optimization level (default 2)");

    auto* run = app.add_subcommand(
        "run",
        "Build a rule file (cached by content) and run it; arguments after FILE go to the program");
    run->add_option("-I", includes, "Directory searched by %import (repeatable, in order)")
        ->allow_extra_args(false);
    run->add_option("--cxx", build_options.cxx, "C++ compiler");
    run->add_option("-O", build_options.optimization, "Optimization level (default 2)");
    run->prefix_command();
    run->footer(
        "Usage: acanthus run [-I DIR]... [--cxx CXX] [-O LEVEL] FILE.acr [program options...]");

    auto* preview = app.add_subcommand(
        "preview",
        "Serve a live page of the rule file's render on 127.0.0.1, re-rendered on every save; "
        "arguments after FILE go to the program, besides --port N and --host ADDR");
    preview->add_option("-I", includes, "Directory searched by %import (repeatable, in order)")
        ->allow_extra_args(false);
    preview->add_option("--cxx", build_options.cxx, "C++ compiler");
    preview->add_option("-O", build_options.optimization,
                        "Optimization level (default 0: the quickest build)");
    preview->prefix_command();
    preview->footer(
        "Usage: acanthus preview [-I DIR]... [--cxx CXX] [-O LEVEL] FILE.acr [program options...] "
        "[--port N] [--host ADDR]");

    acanthus::batch::BatchOptions batch_options;
    auto* batch = acanthus::batch::add_batch_command(app, batch_options);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : kBadUsage;
    }

    if (batch->parsed()) return acanthus::batch::run_batch_command(batch_options);

    // Previews favour a quick build over a fast program (docs/preview.md, bench/preview.sh).
    if (preview->parsed() && preview->count("-O") == 0) build_options.optimization = "0";
    static const std::string levels[] = {"0", "1", "2", "3", "s", "g", "fast", "z"};
    if (std::find(std::begin(levels), std::end(levels), build_options.optimization) ==
        std::end(levels)) {
        std::cerr << "acanthus: error: bad optimization level '" << build_options.optimization
                  << "' (use 0, 1, 2, 3, s, g, z or fast)\n";
        return kBadUsage;
    }

    Toolchain toolchain = acanthus::find_toolchain();
    if (preview->parsed()) {
        std::vector<std::string> rest = preview->remaining();
        if (rest.empty()) {
            std::cerr << "acanthus: error: 'preview' needs a rule file\n" << preview->help();
            return kBadUsage;
        }
        input = rest.front();
        rest.erase(rest.begin());
        return acanthus::run_preview(input, includes, toolchain, build_options, rest);
    }
    std::vector<std::string> program_args;
    if (run->parsed()) {
        program_args = run->remaining();
        if (program_args.empty()) {
            std::cerr << "acanthus: error: 'run' needs a rule file\n" << run->help();
            return kBadUsage;
        }
        input = program_args.front();
        program_args.erase(program_args.begin());
    }

    CompileRequest request = make_request(input, includes, toolchain);
    request.generate.line_directives = !no_lines;
    request.generate.emit_main = !no_main;
    std::string cpp;

    if (check->parsed()) {
        return acanthus::compile_rule_file(request, false, cpp, std::cerr) ? 0 : kBadInput;
    }

    if (compile->parsed()) {
        if (output.empty()) output = stem_of(input) + ".cpp";
        if (!depfile.empty() && output == "-") {
            std::cerr << "acanthus: error: --depfile needs -o FILE, the target of its rule\n";
            return kBadUsage;
        }
        request.generate.output_name = output == "-" ? "<stdout>" : output;
        std::vector<std::string> inputs;
        if (!acanthus::compile_rule_file(request, true, cpp, std::cerr, &inputs)) return kBadInput;
        if (std::string in = overwritten_input(output, inputs); !in.empty())
            return refuse_overwrite(output, in);
        std::string rule, error;
        if (!depfile.empty()) {
            if (std::string in = overwritten_input(depfile, inputs); !in.empty())
                return refuse_overwrite(depfile, in, "--depfile");
            if (canonical_or_same(depfile) == canonical_or_same(output)) {
                std::cerr << "acanthus: error: --depfile and -o name the same file '" << output
                          << "'\n";
                return kBadUsage;
            }
            if (!acanthus::make_dependency_rule(output, acanthus::rule_file_dependencies(inputs),
                                                rule, error))
                return fail(error);
        }
        if (output == "-") {
            std::cout << cpp << std::flush;
            if (!std::cout) return kBadInput;
        } else if (!acanthus::write_file_atomically(output, cpp, error)) {
            return fail(error);
        }
        // After the C++: a depfile never describes an output that was not written.
        if (!depfile.empty() && !acanthus::write_file_atomically(depfile, rule, error)) {
            acanthus::remove_if_present(output);
            return fail(error);
        }
        return 0;
    }

    std::string stem = stem_of(input);
    request.generate.output_name = stem + ".cpp";
    std::vector<std::string> inputs;
    if (!acanthus::compile_rule_file(request, true, cpp, std::cerr, &inputs)) return kBadInput;
    std::string error;

    if (build->parsed()) {
        if (output.empty()) output = stem;
        if (std::string in = overwritten_input(output, inputs); !in.empty())
            return refuse_overwrite(output, in);
        if (!acanthus::build_executable(toolchain, build_options, stem, cpp, output, error)) {
            return fail(error);
        }
        return 0;
    }

    // run
    std::string executable;
    if (!acanthus::cached_executable(toolchain, build_options, stem, cpp, executable, error)) {
        return fail(error);
    }
    std::vector<char*> args;
    args.push_back(stem.data());
    for (std::string& a : program_args) args.push_back(a.data());
    args.push_back(nullptr);
    std::cout.flush();
    execv(executable.c_str(), args.data());
    return fail("cannot run '" + executable + "': " + std::strerror(errno));
}
