// `acanthus build` and `acanthus run`: generated C++ -> executable with the system compiler,
// and the content-addressed cache `run` uses.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "toolchain/toolchain.hpp"

namespace acanthus {

// Runs a compiler command line; returns its exit status, or -1 with `error` set.
using CommandRunner = std::function<int(const std::vector<std::string>&, std::string&)>;

struct BuildOptions {
    std::string cxx;                 // empty: $CXX, then the compiler Acanthus was built with
    std::string optimization = "2";  // -O LEVEL
    CommandRunner runner;            // empty: run_process (inherited stdio, not cancellable)
    // Previews: a header compiled ahead (`-include`, its .gch beside it) and flags such as
    // -fuse-ld=lld, all part of the cache key.
    std::string precompiled_header;
    std::vector<std::string> extra_flags;
    // A shared library exporting acanthus_pattern() (`--no-main` code) instead of a program.
    bool shared_library = false;
    // With shared_library: the linker's own command line, as the compiler driver would run it
    // (kLinkObject and kLinkOutput in place of the object and the library; direct_link_command).
    // The build compiles an object (the driver runs the compiler in its own process then) and
    // runs the linker itself. Empty: the driver compiles and links in one command.
    std::vector<std::string> link_command;
    // A split build (cached_split_library): how many units compile at once (the runner is then
    // called from as many threads), and the optimization level of the code unit (units[1]: the
    // %draw bodies, which run for every picture drawn; empty: `optimization`). With
    // `code_unit_later`, a code unit not yet compiled at that level is compiled at
    // `optimization` (quicker to build) and the build says so (`code_unit_deferred`).
    unsigned jobs = 1;
    std::string code_unit_optimization;
    bool code_unit_later = false;
    // The rule units (units[2...]) at the code unit's level: with `optimise_rules`, each is
    // compiled so (a build after a picture); without, a rule unit whose object at that level
    // is in the cache is linked in place of its ordinary one (the rules a save did not edit
    // run optimised; the edited one, compiled at `optimization`, does not wait for it).
    bool optimise_rules = false;
    // A split build with clang: the text the code unit and each rule unit start with (the
    // %param globals, %source and element classes: GeneratedUnits::header). Once precompiled
    // (chained on `precompiled_header`), a unit that starts with it compiles only the rest;
    // `precompile_unit_header` precompiles it when missing (a build after a picture).
    std::string unit_header;
    bool precompile_unit_header = false;
};

inline constexpr const char* kLinkObject = "{object}";
inline constexpr const char* kLinkOutput = "{output}";

// The command the compiler driver would run to link one object into a shared library with
// `options` (its flags, e.g. -fuse-ld=gold), read from `-###`: starting the driver for it took
// more processor time than the link. False (and no command) for a compiler other than clang.
bool direct_link_command(const Toolchain& toolchain, const BuildOptions& options,
                         std::vector<std::string>& command, std::string& error);

// A cache key from `parts` (FNV-1a, not a security boundary), 16 hex digits.
std::string cache_key(const std::vector<std::string>& parts);
// Path, size and modification time: changes whenever the file is rebuilt.
std::string file_identity(const std::string& path);

// The compiler, language level, optimization, sanitizer flags and include directories.
std::vector<std::string> compiler_flags(const Toolchain& toolchain, const BuildOptions& options);

// The compiler command line that turns `source` into `executable`.
std::vector<std::string> compile_command(const Toolchain& toolchain, const BuildOptions& options,
                                         const std::string& source, const std::string& executable);

// Compiles `cpp` (generated from `stem`.acr) into `executable`, atomically. The compiler's
// messages go to stderr. False with `error` set when compiling fails.
bool build_executable(const Toolchain& toolchain, const BuildOptions& options,
                      const std::string& stem, const std::string& cpp,
                      const std::string& executable, std::string& error);

// The executable `run` uses for `cpp`: <cache>/<stem>-<hash>, built when missing (with
// `options.shared_library`, <cache>/<stem>-<hash>.so).
bool cached_executable(const Toolchain& toolchain, const BuildOptions& options,
                       const std::string& stem, const std::string& cpp, std::string& executable,
                       std::string& error);

// With `options.shared_library` and `options.link_command`: the library of a program generated
// as separate units (generate_cpp_units), each unit's object cached by its text and flags, so
// that a save which edits one rule body compiles that unit alone, then links cached objects.
// False with `error` set when a unit does not compile or the objects do not link; `splittable`
// false when the program cannot be split (its %source keeps state that each unit would copy,
// or defines what the units define again), remembered for its code unit: build it whole then.
// More than `compile_at_most` units to compile: false with `deferred` set, nothing compiled.
bool cached_split_library(const Toolchain& toolchain, const BuildOptions& options,
                          const std::string& stem, const std::vector<std::string>& units,
                          std::string& library, bool& splittable, std::string& error,
                          std::size_t compile_at_most = ~std::size_t(0), bool* deferred = nullptr,
                          bool* code_unit_deferred = nullptr);

// The names of the local, writable objects an ELF object file defines (`static` variables):
// empty when it cannot be read.
std::vector<std::string> local_writable_objects(const std::string& object_path);

// $ACANTHUS_CACHE_DIR, else $XDG_CACHE_HOME/acanthus, else ~/.cache/acanthus.
std::string cache_directory();

}  // namespace acanthus
