#include "toolchain/precompiled_prelude.hpp"

#include <unistd.h>

#include <acanthus/output_file.hpp>
#include <filesystem>
#include <regex>
#include <set>

#include "toolchain/process.hpp"

namespace acanthus {

namespace fs = std::filesystem;

namespace {

// The includes at the top of every generated file (code_generator.cpp writes the same ones).
constexpr const char* kPrelude =
    "#include <acanthus/rules.hpp>\n"
    "#include <cstddef>\n"
    "#include <stdexcept>\n"
    "#include <string>\n"
    "#include <string_view>\n";

// For rule code loaded by the preview host: the vectors generated files use most are
// instantiated once, in the host (preview/server/host.cpp), not again at every save.
constexpr const char* kHostInstantiations =
    "#include <vector>\n"
    "extern template class std::vector<const acanthus::ElementType*>;\n"
    "extern template class std::vector<acanthus::RuleInfo>;\n"
    "extern template class std::vector<acanthus::ParamInfo>;\n"
    "extern template class std::vector<acanthus::ProxyKind>;\n"
    "extern template class std::vector<acanthus::Point>;\n"
    "extern template class std::vector<std::vector<acanthus::Point>>;\n"
    "extern template class std::vector<acanthus::Circle>;\n"
    "extern template class std::vector<acanthus::Element*>;\n"
    "extern template class std::vector<double>;\n"
    "extern template class std::vector<int>;\n";

// The standard headers (`#include <algorithm>`) and Acanthus's own (`<acanthus/stdlib/growth.hpp>`,
// from an imported library's %source) the generated code includes: parsing <algorithm> alone took
// a third of a small rule file's build, the growth library's and the cells library's headers half
// of arrangement's and facade's. Only names of those forms, which do not change while the
// preview runs (the prelude's cache key has the libraries they come with).
std::string library_includes(const std::string& cpp) {
    static const std::regex include(
        R"(^[ \t]*#[ \t]*include[ \t]*<([a-z_]+|acanthus/[A-Za-z0-9_/]+\.hpp)>)",
        std::regex::multiline);
    std::set<std::string> names;
    for (auto it = std::sregex_iterator(cpp.begin(), cpp.end(), include);
         it != std::sregex_iterator(); ++it)
        names.insert((*it)[1]);
    std::string text;
    for (const std::string& name : names) text += "#include <" + name + ">\n";
    return text;
}

bool is_clang(const std::string& compiler) {
    return fs::path(compiler).filename().string().find("clang") != std::string::npos;
}

}  // namespace

namespace {

bool precompile(const Toolchain& toolchain, BuildOptions& options, const std::string& prelude,
                std::string& error) {
    BuildOptions plain = options;
    plain.precompiled_header.clear();
    std::vector<std::string> flags = compiler_flags(toolchain, plain);
    // clang otherwise leaves the header's pending template instantiations to every file that
    // includes it: 0.1 s of each build.
    std::vector<std::string> header_flags;
    if (is_clang(flags.front())) header_flags.push_back("-fpch-instantiate-templates");
    std::vector<std::string> parts = flags;
    parts.insert(parts.end(), header_flags.begin(), header_flags.end());
    parts.insert(parts.end(), options.extra_flags.begin(), options.extra_flags.end());
    parts.push_back(prelude);
    // The headers change with the library they come with.
    parts.push_back(file_identity(toolchain.runtime_library));
    parts.push_back(file_identity(toolchain.stdlib_library));
    const fs::path dir = fs::path(cache_directory()) / ("prelude-" + cache_key(parts));
    const fs::path header = dir / "prelude.hpp";
    const fs::path gch = dir / "prelude.hpp.gch";
    const fs::path failed = dir / "failed";  // not tried again at every save
    std::error_code ec;
    if (fs::exists(gch, ec) && fs::exists(header, ec)) {
        options.precompiled_header = header.string();
        return true;
    }
    if (fs::exists(failed, ec)) {
        error = "precompiling the prelude failed before";
        return false;
    }
    fs::create_directories(dir, ec);
    if (ec || !write_file_atomically(header.string(), prelude, error)) {
        if (error.empty()) error = "cannot create '" + dir.string() + "'";
        return false;
    }
    std::string temp = create_temporary_sibling(gch.string(), error);
    if (temp.empty()) return false;
    std::vector<std::string> cmd = flags;
    cmd.insert(cmd.end(), header_flags.begin(), header_flags.end());
    cmd.insert(cmd.end(), {"-x", "c++-header", header.string(), "-o", temp});
    int status = options.runner ? options.runner(cmd, error) : run_process(cmd, error);
    if (status != 0 || std::rename(temp.c_str(), gch.c_str()) != 0) {
        if (status > 0) {
            error = "precompiling the prelude failed (exit status " + std::to_string(status) + ")";
            std::string ignored;
            write_file_atomically(failed.string(), error + "\n", ignored);
        }
        remove_if_present(temp);
        return false;
    }
    options.precompiled_header = header.string();
    return true;
}

}  // namespace

bool use_precompiled_prelude(const Toolchain& toolchain, BuildOptions& options, std::string& error,
                             const std::string& generated) {
    std::string prelude = kPrelude;
    if (options.shared_library) prelude += kHostInstantiations;
    const std::string own = library_includes(generated);
    // A misspelt header fails here too: then the prelude without them (the build reports it).
    if (!own.empty() && precompile(toolchain, options, prelude + own, error)) return true;
    error.clear();
    return precompile(toolchain, options, prelude, error);
}

}  // namespace acanthus
