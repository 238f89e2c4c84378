#include "toolchain/toolchain.hpp"

#include <filesystem>

#include "toolchain/toolchain_config.hpp"

namespace acanthus {

namespace fs = std::filesystem;

namespace {

bool path_exists(const fs::path& p) {
    std::error_code ec;
    return fs::exists(p, ec);
}

fs::path own_directory() {
    std::error_code ec;
    fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    return ec ? fs::path() : exe.parent_path();
}

}  // namespace

Toolchain find_toolchain() {
    Toolchain t;
    t.link_flags = {ACANTHUS_LINK_FLAGS};
    t.sanitize_flags = {ACANTHUS_SANITIZE_FLAGS};
    t.default_cxx = ACANTHUS_DEFAULT_CXX;
    t.preview_strokes = ACANTHUS_PREVIEW_STROKES;
    fs::path dir = own_directory();
    if (!dir.empty()) {
        fs::path prefix = dir.parent_path();
        if (path_exists(prefix / "include/acanthus/rules.hpp")) {
            for (const char* libdir : {ACANTHUS_INSTALL_LIBDIR, "lib", "lib64"}) {
                fs::path lib = prefix / libdir / "libacanthus.a";
                if (!path_exists(lib)) continue;
                t.installed = true;
                t.include_dirs.push_back((prefix / "include").string());
                t.runtime_library = lib.string();
                fs::path stdlib = prefix / libdir / "libacanthus_stdlib.a";
                if (path_exists(stdlib)) t.stdlib_library = stdlib.string();
                t.stdlib_dirs.push_back((prefix / "share/acanthus/stdlib").string());
                t.preview_dir = (prefix / "share/acanthus/preview").string();
                t.panels_dir = (prefix / "share/acanthus/panels").string();
                return t;
            }
        }
    }
    t.include_dirs = {ACANTHUS_BUILD_INCLUDE_DIRS};
    t.runtime_library = ACANTHUS_BUILD_RUNTIME_LIB;
    std::string stdlib = ACANTHUS_BUILD_STDLIB_LIB;
    if (!stdlib.empty() && path_exists(stdlib)) t.stdlib_library = stdlib;
    t.stdlib_dirs.push_back(ACANTHUS_SOURCE_STDLIB_DIR);
    t.stdlib_dirs.push_back(ACANTHUS_INSTALL_STDLIB_DIR);
    t.preview_dir = ACANTHUS_SOURCE_PREVIEW_DIR;
    t.panels_dir = ACANTHUS_SOURCE_PANELS_DIR;
    return t;
}

}  // namespace acanthus
