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

// The standard library as generated code uses it most (vectors of points, circles and numbers,
// strings, the element type's and the pattern's members), instantiated once in the precompiled
// prelude (with clang's -fpch-instantiate-templates), not again at every save: C++20 makes these
// members constexpr, which instantiates them in every file whatever `extern template` says. Half
// of the front end's time for flowers' rule code; never called.
constexpr const char* kCommonInstantiations = R"(#include <vector>
namespace acanthus::prelude_detail {
template <class T>
inline void use_vector(const T& x) {
    std::vector<T> v, w(v), u{x};
    v = w;
    v = std::move(u);
    v.push_back(x);
    v.push_back(T(x));
    v.emplace_back(x);
    v.insert(v.end(), w.begin(), w.end());
    v.reserve(v.size() + v.capacity());
    v.erase(v.begin());
    v.pop_back();
    (void)v.empty();
    (void)v.front();
    (void)v.back();
    (void)v[0];
    (void)v.at(0);
    (void)v.data();
    for (const T& y : v) (void)y;
    for (T& y : v) (void)y;
    v.clear();
}
inline void use_string(std::string s, std::string_view view) {
    std::string t = "", u(view), c(s);
    t = s;
    t = "";
    t = std::move(u);
    t += s;
    t += "";
    t += 'c';
    t = s + t;
    t = s + "";
    t = "" + s;
    (void)(s == t);
    (void)(s == "");
    (void)(s != "");
    (void)(s < t);
    (void)s.substr(0, 1);
    (void)s.find("");
    (void)s.find('c');
    (void)s.size();
    (void)s.empty();
    (void)s.c_str();
    (void)s[0];
    view = s;
    (void)std::to_string(0);
    (void)std::to_string(0.0);
}
inline void instantiate() {
    const acanthus::ElementType type{"", {acanthus::ProxyKind::point}, nullptr, nullptr, 0};
    const acanthus::Pattern pattern;
    use_string({}, {});
    use_vector(acanthus::Point{});
    use_vector(std::vector<acanthus::Point>{});
    use_vector(acanthus::Circle{});
    use_vector(static_cast<acanthus::Element*>(nullptr));
    use_vector(0.0);
    use_vector(0);
}
}  // namespace acanthus::prelude_detail
)";

// The standard headers (`#include <algorithm>`) and Acanthus's own (`<acanthus/stdlib/growth.hpp>`,
// from an imported library's %source) the generated code includes: parsing <algorithm> alone took
// a third of a small rule file's build, the growth library's and the cells library's headers half
// of arrangement's and facade's. Only names of those forms, which do not change while the
// preview runs (the prelude's cache key has the libraries they come with).
//
// A library's header may have a `_prelude.hpp` beside it (<acanthus/stdlib/growth_prelude.hpp>):
// what the library's rule code instantiates, instantiated once with the prelude too. Its size and
// time are in the prelude's text, so an edited one makes a new prelude.
std::string library_includes(const std::string& cpp, const std::vector<std::string>& dirs) {
    static const std::regex include(
        R"(^[ \t]*#[ \t]*include[ \t]*<([a-z_]+|acanthus/[A-Za-z0-9_/]+\.hpp)>)",
        std::regex::multiline);
    std::set<std::string> names;
    for (auto it = std::sregex_iterator(cpp.begin(), cpp.end(), include);
         it != std::sregex_iterator(); ++it)
        names.insert((*it)[1]);
    std::string text;
    for (const std::string& name : names) text += "#include <" + name + ">\n";
    for (const std::string& name : names) {
        if (name.rfind("acanthus/", 0) != 0) continue;
        const std::string extra = name.substr(0, name.size() - 4) + "_prelude.hpp";
        for (const std::string& dir : dirs) {
            const std::string path = (fs::path(dir) / extra).string();
            if (!fs::is_regular_file(path)) continue;
            text += "#include <" + extra + ">  // " + file_identity(path) + "\n";
            break;
        }
    }
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
    prelude += kCommonInstantiations;
    const std::string own = library_includes(generated, toolchain.include_dirs);
    // A misspelt header fails here too: then the prelude without them (the build reports it).
    if (!own.empty() && precompile(toolchain, options, prelude + own, error)) return true;
    error.clear();
    return precompile(toolchain, options, prelude, error);
}

}  // namespace acanthus
