#include "server/host.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <acanthus/output_file.hpp>
#include <filesystem>

#include "toolchain/process.hpp"

namespace acanthus {

namespace fs = std::filesystem;

namespace {

constexpr const char* kHostSource = R"(// acanthus preview host: loads a rule file's code, runs it.
#include <dlfcn.h>

#include <acanthus/program.hpp>
#include <acanthus/rules.hpp>
#include <cstdio>
#include <vector>

// What the rule libraries' prelude declares extern (precompiled_prelude.cpp).
template class std::vector<const acanthus::ElementType*>;
template class std::vector<acanthus::RuleInfo>;
template class std::vector<acanthus::ParamInfo>;
template class std::vector<acanthus::ProxyKind>;
template class std::vector<acanthus::Point>;
template class std::vector<std::vector<acanthus::Point>>;
template class std::vector<acanthus::Circle>;
template class std::vector<acanthus::Element*>;
template class std::vector<double>;
template class std::vector<int>;

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s PATTERN.so [program options]\n", argv[0]);
        return 2;
    }
    void* library = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
    if (!library) {
        std::fprintf(stderr, "acanthus: error: %s\n", dlerror());
        return 1;
    }
    using Pattern = const acanthus::Pattern& (*)();
    auto pattern = reinterpret_cast<Pattern>(dlsym(library, "_Z16acanthus_patternv"));
    if (!pattern) {
        std::fprintf(stderr, "acanthus: error: %s\n", dlerror());
        return 1;
    }
    argv[1] = argv[0];
    return acanthus::run_program(pattern(), argc - 1, argv + 1);
}
)";

}  // namespace

bool preview_host(const Toolchain& toolchain, const BuildOptions& options, std::string& host,
                  std::string& error) {
    BuildOptions plain = options;
    plain.shared_library = false;
    plain.precompiled_header.clear();
    std::vector<std::string> cmd = compiler_flags(toolchain, plain);
    for (const std::string& f : options.extra_flags)
        if (f != "-fPIC") cmd.push_back(f);
    std::vector<std::string> parts = cmd;
    parts.push_back(kHostSource);
    parts.push_back(file_identity(toolchain.runtime_library));
    parts.push_back(file_identity(toolchain.stdlib_library));
    const fs::path dir = fs::path(cache_directory()) / ("preview-host-" + cache_key(parts));
    host = (dir / "host").string();
    if (access(host.c_str(), X_OK) == 0) return true;
    std::error_code ec;
    fs::create_directories(dir, ec);
    const std::string source = (dir / "host.cpp").string();
    if (ec || !write_file_atomically(source, kHostSource, error)) {
        if (error.empty()) error = "cannot create '" + dir.string() + "'";
        return false;
    }
    std::string temp = create_temporary_sibling(host, error);
    if (temp.empty()) return false;
    // Every object of the libraries, exported (-rdynamic): the rule library may use any of them.
    cmd.insert(cmd.end(), {source, "-o", temp, "-rdynamic", "-Wl,--whole-archive"});
    if (!toolchain.stdlib_library.empty()) cmd.push_back(toolchain.stdlib_library);
    cmd.insert(cmd.end(), {toolchain.runtime_library, "-Wl,--no-whole-archive", "-ldl"});
    cmd.insert(cmd.end(), toolchain.link_flags.begin(), toolchain.link_flags.end());
    int status = options.runner ? options.runner(cmd, error) : run_process(cmd, error);
    if (status != 0) {
        if (status > 0)
            error = "building the preview host failed (exit status " + std::to_string(status) + ")";
        remove_if_present(temp);
        return false;
    }
    chmod(temp.c_str(), 0755);
    if (std::rename(temp.c_str(), host.c_str()) != 0) {
        remove_if_present(temp);
        error = "cannot write '" + host + "'";
        return false;
    }
    return true;
}

}  // namespace acanthus
