#include "toolchain/program_build.hpp"

#include <elf.h>
#include <sys/stat.h>
#include <unistd.h>

#include <acanthus/output_file.hpp>
#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <thread>

#include "toolchain/process.hpp"

namespace acanthus {

namespace fs = std::filesystem;

namespace {

std::string compiler(const Toolchain& toolchain, const BuildOptions& options) {
    if (!options.cxx.empty()) return options.cxx;
    if (const char* env = std::getenv("CXX"); env && *env) return env;
    return toolchain.default_cxx.empty() ? "c++" : toolchain.default_cxx;
}

// FNV-1a, 64 bit: a cache key, not a security boundary.
class Hash {
  public:
    void add(std::string_view s) {
        for (char c : s) {
            state_ ^= static_cast<unsigned char>(c);
            state_ *= 0x100000001b3ULL;
        }
        state_ ^= 0xff;  // separates fields
        state_ *= 0x100000001b3ULL;
    }
    std::string hex() const {
        static const char digits[] = "0123456789abcdef";
        std::string out(16, '0');
        for (int i = 0; i < 16; ++i) out[15 - i] = digits[(state_ >> (4 * i)) & 15];
        return out;
    }

  private:
    std::uint64_t state_ = 0xcbf29ce484222325ULL;
};

bool is_clang(const std::string& compiler) {
    return fs::path(compiler).filename().string().find("clang") != std::string::npos;
}

// Flags that only the link step reads: left out of the compile-only step.
bool link_only(const std::string& flag) { return flag.rfind("-fuse-ld=", 0) == 0; }

// The arguments of a `-###` line: ` "prog" "arg" ...`, with \" and \\ escaped.
std::vector<std::string> quoted_words(const std::string& line) {
    std::vector<std::string> words;
    for (std::size_t i = 0; i < line.size(); ++i) {
        if (line[i] != '"') continue;
        std::string word;
        for (++i; i < line.size() && line[i] != '"'; ++i) {
            if (line[i] == '\\' && i + 1 < line.size()) ++i;
            word += line[i];
        }
        words.push_back(word);
    }
    return words;
}

}  // namespace

bool direct_link_command(const Toolchain& toolchain, const BuildOptions& options,
                         std::vector<std::string>& command, std::string& error) {
    command.clear();
    std::vector<std::string> cmd = compiler_flags(toolchain, options);
    if (!is_clang(cmd.front())) return false;
    cmd.insert(cmd.end(), options.extra_flags.begin(), options.extra_flags.end());
    // The driver wants its input to exist, even to print the commands.
    std::error_code ec;
    std::string dir = (fs::temp_directory_path(ec) / "acanthus-link.XXXXXX").string();
    if (!mkdtemp(dir.data())) {
        error = "cannot create a temporary directory";
        return false;
    }
    const std::string object = (fs::path(dir) / "object.o").string();
    const std::string output = (fs::path(dir) / "library.so").string();
    std::ofstream(object).put('\n');
    cmd.insert(cmd.end(), {"-shared", "-###", object, "-o", output});
    std::string printed;
    const int status = run_process_output(cmd, printed, error);
    fs::remove_all(dir, ec);
    if (status != 0) {
        if (status > 0) error = "'" + cmd.front() + " -###' failed";
        return false;
    }
    // The last command printed is the linker's.
    std::string line;
    for (std::size_t start = 0; start < printed.size();) {
        std::size_t end = printed.find('\n', start);
        if (end == std::string::npos) end = printed.size();
        if (printed.compare(start, 2, " \"") == 0) line = printed.substr(start, end - start);
        start = end + 1;
    }
    std::vector<std::string> words = quoted_words(line);
    int objects = 0, outputs = 0;
    for (std::string& w : words) {
        if (w == object) w = kLinkObject, ++objects;
        if (w == output) w = kLinkOutput, ++outputs;
    }
    if (words.empty() || objects != 1 || outputs != 1) {
        error = "cannot read the link command from '" + cmd.front() + " -###'";
        return false;
    }
    command = std::move(words);
    return true;
}

std::string file_identity(const std::string& path) {
    if (path.empty()) return "-";
    std::error_code ec;
    auto size = fs::file_size(path, ec);
    auto time = fs::last_write_time(path, ec);
    return path + ":" + std::to_string(size) + ":" +
           std::to_string(time.time_since_epoch().count());
}

std::string cache_key(const std::vector<std::string>& parts) {
    Hash hash;
    for (const std::string& p : parts) hash.add(p);
    return hash.hex();
}

std::vector<std::string> compiler_flags(const Toolchain& toolchain, const BuildOptions& options) {
    std::vector<std::string> cmd{compiler(toolchain, options), "-std=c++20",
                                 "-O" + options.optimization};
    cmd.insert(cmd.end(), toolchain.sanitize_flags.begin(), toolchain.sanitize_flags.end());
    for (const std::string& dir : toolchain.include_dirs) cmd.push_back("-I" + dir);
    if (options.shared_library) cmd.push_back("-fPIC");
    return cmd;
}

namespace {

// The compile-only step of a shared library linked by `options.link_command`.
std::vector<std::string> object_command(const Toolchain& toolchain, const BuildOptions& options,
                                        const std::string& source, const std::string& object) {
    std::vector<std::string> cmd = compiler_flags(toolchain, options);
    if (!options.precompiled_header.empty())
        cmd.insert(cmd.end(), {"-include", options.precompiled_header});
    for (const std::string& f : options.extra_flags)
        if (!link_only(f)) cmd.push_back(f);
    cmd.insert(cmd.end(), {"-c", source, "-o", object});
    return cmd;
}

}  // namespace

std::vector<std::string> compile_command(const Toolchain& toolchain, const BuildOptions& options,
                                         const std::string& source, const std::string& executable) {
    std::vector<std::string> cmd = compiler_flags(toolchain, options);
    if (!options.precompiled_header.empty())
        cmd.insert(cmd.end(), {"-include", options.precompiled_header});
    cmd.insert(cmd.end(), options.extra_flags.begin(), options.extra_flags.end());
    if (options.shared_library) {
        // The runtime comes from the program that loads it (preview/server/host.cpp).
        cmd.insert(cmd.end(), {"-shared", source, "-o", executable});
        return cmd;
    }
    cmd.insert(cmd.end(), {source, "-o", executable, "-Wl,--start-group"});
    if (!toolchain.stdlib_library.empty()) cmd.push_back(toolchain.stdlib_library);
    cmd.push_back(toolchain.runtime_library);
    cmd.push_back("-Wl,--end-group");
    cmd.insert(cmd.end(), toolchain.link_flags.begin(), toolchain.link_flags.end());
    return cmd;
}

bool build_executable(const Toolchain& toolchain, const BuildOptions& options,
                      const std::string& stem, const std::string& cpp,
                      const std::string& executable, std::string& error) {
    std::error_code ec;
    if (!fs::exists(toolchain.runtime_library, ec)) {
        error = "the Acanthus runtime library '" + toolchain.runtime_library +
                "' does not exist (build the 'acanthus_runtime' target first)";
        return false;
    }
    std::string dir_template = (fs::temp_directory_path(ec) / "acanthus-build.XXXXXX").string();
    if (!mkdtemp(dir_template.data())) {
        error = "cannot create a temporary directory";
        return false;
    }
    fs::path work(dir_template);
    std::string source = (work / (stem + ".cpp")).string();
    bool ok = write_file_atomically(source, cpp, error);
    std::string temp;
    if (ok) {
        temp = create_temporary_sibling(executable, error);
        ok = !temp.empty();
    }
    const auto run = [&](const std::vector<std::string>& cmd, const char* what) {
        int status = options.runner ? options.runner(cmd, error) : run_process(cmd, error);
        if (status > 0) error = std::string(what) + " (exit status " + std::to_string(status) + ")";
        return status == 0;
    };
    const bool two_steps = options.shared_library && !options.link_command.empty();
    if (ok && two_steps) {
        const std::string object = (work / (stem + ".o")).string();
        ok = run(object_command(toolchain, options, source, object), "the C++ compiler failed");
        std::vector<std::string> link = options.link_command;
        for (std::string& w : link) w = w == kLinkObject ? object : w == kLinkOutput ? temp : w;
        ok = ok && run(link, "linking the rule code failed");
    } else if (ok) {
        ok = run(compile_command(toolchain, options, source, temp), "the C++ compiler failed");
    }
    if (ok) {
        // The temporary was created 0600; give the program the usual executable mode.
        mode_t mask = umask(0);
        umask(mask);
        chmod(temp.c_str(), 0777 & ~mask);
    }
    if (ok && std::rename(temp.c_str(), executable.c_str()) != 0) {
        error = "cannot write '" + executable + "'";
        ok = false;
    }
    if (!ok) remove_if_present(temp);
    fs::remove_all(work, ec);
    return ok;
}

std::string cache_directory() {
    if (const char* dir = std::getenv("ACANTHUS_CACHE_DIR"); dir && *dir) return dir;
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) {
        return (fs::path(xdg) / "acanthus").string();
    }
    if (const char* home = std::getenv("HOME"); home && *home) {
        return (fs::path(home) / ".cache" / "acanthus").string();
    }
    return (fs::temp_directory_path() / "acanthus-cache").string();
}

bool cached_executable(const Toolchain& toolchain, const BuildOptions& options,
                       const std::string& stem, const std::string& cpp, std::string& executable,
                       std::string& error) {
    Hash hash;
    hash.add(cpp);
    for (const std::string& part : compile_command(toolchain, options, "SOURCE", "EXECUTABLE")) {
        hash.add(part);
    }
    if (options.shared_library)
        for (const std::string& part : options.link_command) hash.add(part);
    hash.add(file_identity(toolchain.runtime_library));
    hash.add(file_identity(toolchain.stdlib_library));
    fs::path dir(cache_directory());
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) {
        error = "cannot create the cache directory '" + dir.string() + "': " + ec.message();
        return false;
    }
    executable = (dir / (stem + "-" + hash.hex() + (options.shared_library ? ".so" : ""))).string();
    if (access(executable.c_str(), X_OK) == 0) return true;
    return build_executable(toolchain, options, stem, cpp, executable, error);
}

}  // namespace acanthus

namespace acanthus {

std::vector<std::string> local_writable_objects(const std::string& object_path) {
    std::vector<std::string> names;
    std::ifstream in(object_path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    Elf64_Ehdr header;
    if (bytes.size() < sizeof header) return names;
    std::memcpy(&header, bytes.data(), sizeof header);
    if (std::memcmp(header.e_ident, ELFMAG, SELFMAG) != 0 ||
        header.e_ident[EI_CLASS] != ELFCLASS64 || header.e_shentsize != sizeof(Elf64_Shdr) ||
        header.e_shoff + std::uint64_t(header.e_shnum) * sizeof(Elf64_Shdr) > bytes.size())
        return names;
    std::vector<Elf64_Shdr> sections(header.e_shnum);
    std::memcpy(sections.data(), bytes.data() + header.e_shoff,
                sections.size() * sizeof(Elf64_Shdr));
    for (const Elf64_Shdr& table : sections) {
        if (table.sh_type != SHT_SYMTAB || table.sh_link >= sections.size()) continue;
        const Elf64_Shdr& strings = sections[table.sh_link];
        if (table.sh_offset + table.sh_size > bytes.size() ||
            strings.sh_offset + strings.sh_size > bytes.size())
            continue;
        for (std::uint64_t at = 0; at + sizeof(Elf64_Sym) <= table.sh_size;
             at += sizeof(Elf64_Sym)) {
            Elf64_Sym symbol;
            std::memcpy(&symbol, bytes.data() + table.sh_offset + at, sizeof symbol);
            const unsigned type = ELF64_ST_TYPE(symbol.st_info);
            if (ELF64_ST_BIND(symbol.st_info) != STB_LOCAL ||
                (type != STT_OBJECT && type != STT_TLS) || symbol.st_shndx >= sections.size() ||
                !(sections[symbol.st_shndx].sh_flags & SHF_WRITE) ||
                symbol.st_name >= strings.sh_size)
                continue;
            const char* name = bytes.data() + strings.sh_offset + symbol.st_name;
            names.emplace_back(name, strnlen(name, strings.sh_size - symbol.st_name));
        }
    }
    return names;
}

namespace {

// A unit's text for its object's cache key: a save that adds a line above a unit's code moves
// its #line numbers, which change nothing in the object (no debug information) unless the code
// names its line.
std::string without_line_numbers(const std::string& unit) {
    for (const char* uses_line : {"__LINE__", "assert", "source_location", "__builtin_LINE"})
        if (unit.find(uses_line) != std::string::npos) return unit;
    std::string out;
    out.reserve(unit.size());
    for (std::size_t start = 0; start < unit.size();) {
        std::size_t end = unit.find('\n', start);
        end = end == std::string::npos ? unit.size() : end + 1;
        if (unit.compare(start, 6, "#line ") == 0) {
            const std::size_t name = unit.find('"', start);
            out += "#line ";
            if (name < end) out.append(unit, name, end - name);
        } else {
            out.append(unit, start, end - start);
        }
        start = end;
    }
    return out;
}

// `static` objects that two units both define: state the single program has once.
bool copies_state(const std::vector<std::string>& objects) {
    std::set<std::string> seen;
    for (const std::string& object : objects) {
        const std::vector<std::string> names = local_writable_objects(object);
        for (const std::string& name : std::set<std::string>(names.begin(), names.end()))
            // (<iostream>'s initialiser is meant to be one per unit)
            if (name != "_ZStL8__ioinit" && !seen.insert(name).second) return true;
    }
    return false;
}

// The unit header precompiled (BuildOptions::unit_header), in the units' cache under the key
// of its text, its command and the prelude it is chained on.
struct UnitHeader {
    std::string header, gch, failed;
    std::string warm_header;           // the header and the rules' warm-up (see warm_up_rules)
    std::vector<std::string> command;  // (output: `gch`'s temporary in place of kLinkOutput)
};

UnitHeader unit_header_of(const Toolchain& toolchain, const BuildOptions& options,
                          const fs::path& unit_dir, const std::string& stem) {
    UnitHeader h;
    std::vector<std::string> cmd = compiler_flags(toolchain, options);
    if (options.unit_header.empty() || !is_clang(cmd.front())) return h;
    // (the header's template instantiations made once, in the .gch, as the prelude's are)
    cmd.push_back("-fpch-instantiate-templates");
    if (!options.precompiled_header.empty())
        cmd.insert(cmd.end(), {"-include", options.precompiled_header});
    for (const std::string& f : options.extra_flags)
        if (!link_only(f)) cmd.push_back(f);
    std::vector<std::string> parts = cmd;
    parts.push_back(file_identity(toolchain.runtime_library));
    parts.push_back(file_identity(toolchain.stdlib_library));
    if (!options.precompiled_header.empty())
        parts.push_back(file_identity(options.precompiled_header + ".gch"));
    // Keyed as the units are, without the #line numbers: a rule body that gained a line moves
    // the %source after it, and the header with the old numbers is still the same code (a
    // new .gch for it cost chinese_vase's save 0.3 s more of the unit's compile). A unit that
    // fails with it is built whole, whose messages have the lines right.
    parts.push_back(without_line_numbers(options.unit_header));
    const std::string base = (unit_dir / (stem + "-" + cache_key(parts))).string();
    h.header = base + ".hpp";
    h.warm_header = base + ".warm.hpp";
    h.gch = base + ".hpp.gch";
    h.failed = base + ".hpp.failed";
    cmd.insert(cmd.end(), {"-x", "c++-header", h.header, "-o", kLinkOutput});
    h.command = std::move(cmd);
    return h;
}

// The rule units' functions, after the header they share, renamed and `inline` (never used,
// so never compiled into an object): precompiled with the header, the templates the rule
// bodies use are instantiated once, in the .gch (-fpch-instantiate-templates), not again by the
// unit of each save that edits a rule. chinese_vase's first rule inserts into a
// std::set<std::tuple<...>>: its unit took 250 ms of processor time, 180 ms so. The rule
// bodies of the build that made the .gch; a later edit that uses a new template instantiates
// it itself.
std::string warm_up_rules(const std::string& header, const std::vector<std::string>& units) {
    static const std::string name = "acanthus::Result acr_rule_";
    std::string text;
    for (std::size_t k = 2; k < units.size(); ++k) {  // (after the tables and the code unit)
        if (units[k].compare(0, header.size(), header) != 0) continue;
        std::string rule = units[k].substr(header.size());
        // The unit as generated: comments and #line, then the rule's function alone.
        const std::size_t at = rule.find(name);
        if (at == std::string::npos || rule.find(name, at + 1) != std::string::npos) continue;
        bool alone = true;
        std::istringstream before(rule.substr(0, at));
        for (std::string line; alone && std::getline(before, line);)
            alone = line.find_first_not_of(" \t") == std::string::npos ||
                    line.rfind("//", 0) == 0 || line.rfind("#line ", 0) == 0;
        if (!alone) continue;
        rule.replace(at, name.size(), "inline acanthus::Result acr_warm_up_rule_");
        text += rule + "\n";
    }
    return text;
}

// Writes `path` unless it exists: never replaced (clang checks that a .gch's header is the one
// it was made from; another preview may be using it).
bool write_once(const std::string& path, const std::string& text, std::string& message) {
    std::error_code ec;
    if (fs::exists(path, ec)) return true;
    const std::string temp = create_temporary_sibling(path, message);
    if (temp.empty() || !write_file_atomically(temp, text, message)) {
        if (!temp.empty()) remove_if_present(temp);
        return false;
    }
    // link(): fails, harmlessly, when another build made it meanwhile
    const bool ok = ::link(temp.c_str(), path.c_str()) == 0 || errno == EEXIST;
    remove_if_present(temp);
    return ok;
}

// Precompiles the unit header, with the rules' warm-up when it compiles, else alone. The .hpp
// files are written once and never replaced, the .gch by a rename. False when it cannot be
// made (a compiler error of the header alone is remembered: not tried again).
bool precompile_unit_header(const BuildOptions& options, const UnitHeader& h,
                            const std::vector<std::string>& units, std::string& message) {
    std::error_code ec;
    if (fs::exists(h.failed, ec)) return false;
    // -1 cancelled, 0 made, 1 failed
    const auto precompile = [&](const std::string& header, const std::string& text) {
        if (!write_once(header, text, message)) return 1;
        const std::string temp = create_temporary_sibling(h.gch, message);
        if (temp.empty()) return 1;
        std::vector<std::string> cmd = h.command;
        for (std::string& w : cmd) {
            if (w == kLinkOutput) w = temp;
            if (w == h.header) w = header;
        }
        const int status =
            options.runner ? options.runner(cmd, message) : run_process(cmd, message);
        if (status == 0 && std::rename(temp.c_str(), h.gch.c_str()) == 0) return 0;
        remove_if_present(temp);
        return status > 0 ? 1 : -1;  // (a rename that failed is not the header's fault)
    };
    const std::string warm = warm_up_rules(options.unit_header, units);
    if (!warm.empty()) {
        const int made = precompile(
            h.warm_header,
            options.unit_header + "\n// The rules, for their templates (never compiled):\n" + warm);
        if (made <= 0) return made == 0;
        message.clear();
    }
    const int made = precompile(h.header, options.unit_header);
    if (made > 0) {
        std::string ignored;
        write_file_atomically(h.failed, "precompiling the unit header failed\n", ignored);
    }
    return made == 0;
}

}  // namespace

bool cached_split_library(const Toolchain& toolchain, const BuildOptions& options,
                          const std::string& stem, const std::vector<std::string>& units,
                          std::string& library, bool& splittable, std::string& error,
                          std::size_t compile_at_most, bool* deferred, bool* code_unit_deferred) {
    splittable = true;
    if (deferred) *deferred = false;
    if (code_unit_deferred) *code_unit_deferred = false;
    const fs::path dir(cache_directory());
    const fs::path unit_dir = dir / "units";
    std::error_code ec;
    fs::create_directories(unit_dir, ec);
    if (ec) {
        error = "cannot create the cache directory '" + unit_dir.string() + "': " + ec.message();
        return false;
    }
    // The code unit may have a level of its own (its flags are in its objects' keys).
    BuildOptions code_options = options;
    if (!options.code_unit_optimization.empty())
        code_options.optimization = options.code_unit_optimization;
    // The precompiled prelude is made at the ordinary level, and clang refuses a .gch made with
    // other predefined macros (__OPTIMIZE__): the code unit at a level of its own includes the
    // prelude's headers itself, as every generated unit does.
    if (code_options.optimization != options.optimization) code_options.precompiled_header.clear();
    const auto key_of = [&](std::size_t k, const BuildOptions& level) {
        std::vector<std::string> parts = object_command(toolchain, level, "SOURCE", "OBJECT");
        parts.push_back(file_identity(toolchain.runtime_library));
        parts.push_back(file_identity(toolchain.stdlib_library));
        if (!options.precompiled_header.empty())
            parts.push_back(file_identity(options.precompiled_header + ".gch"));
        parts.push_back(without_line_numbers(units[k]));
        return cache_key(parts);
    };
    const auto object_of = [&](const std::string& key) {
        return (unit_dir / (stem + "-" + key + ".o")).string();
    };
    std::vector<std::string> objects, keys;
    for (std::size_t k = 0; k < units.size(); ++k) {
        keys.push_back(key_of(k, options));
        objects.push_back(object_of(keys.back()));
    }
    // The code unit holds the %source every unit includes.
    const fs::path whole = unit_dir / (stem + "-" + keys.at(1) + ".whole");
    if (fs::exists(whole, ec)) {
        splittable = false;
        error = "the program is built whole";
        return false;
    }
    bool code_optimised = code_options.optimization != options.optimization;
    if (code_optimised) {
        const std::string key = key_of(1, code_options);
        if (options.code_unit_later && access(object_of(key).c_str(), R_OK) != 0) {
            code_optimised = false;  // this save's picture first
            if (code_unit_deferred) *code_unit_deferred = true;
        } else {
            keys[1] = key;
            objects[1] = object_of(key);
        }
    }
    std::vector<bool> optimised(units.size(), false);
    if (code_options.optimization != options.optimization)
        for (std::size_t k = 2; k < units.size(); ++k) {
            const std::string key = key_of(k, code_options);
            if (!options.optimise_rules && access(object_of(key).c_str(), R_OK) != 0) continue;
            keys[k] = key;
            objects[k] = object_of(key);
            optimised[k] = true;
        }
    const auto unit_options = [&](std::size_t k) -> const BuildOptions& {
        return (k == 1 && code_optimised) || optimised[k] ? code_options : options;
    };
    std::vector<std::string> key_parts = keys;
    key_parts.insert(key_parts.end(), options.link_command.begin(), options.link_command.end());
    library = (dir / (stem + "-" + cache_key(key_parts) + ".so")).string();
    if (access(library.c_str(), R_OK) == 0) return true;
    std::size_t missing = 0;
    for (const std::string& object : objects) missing += access(object.c_str(), R_OK) != 0;
    if (missing > compile_at_most) {
        if (deferred) *deferred = true;
        error = std::to_string(missing) + " units to compile";
        return false;
    }

    std::string work = (fs::temp_directory_path(ec) / "acanthus-build.XXXXXX").string();
    if (!mkdtemp(work.data())) {
        error = "cannot create a temporary directory";
        return false;
    }
    const auto run = [&](const std::vector<std::string>& cmd, const char* what,
                         std::string& message) {
        int status = options.runner ? options.runner(cmd, message) : run_process(cmd, message);
        if (status > 0)
            message = std::string(what) + " (exit status " + std::to_string(status) + ")";
        return status == 0;
    };
    // The units to compile, `options.jobs` at a time: a save that edits a rule body compiles
    // its unit and the tables', which waited for each other before.
    std::vector<std::size_t> todo;
    for (std::size_t k = 0; k < units.size(); ++k)
        if (access(objects[k].c_str(), R_OK) != 0) todo.push_back(k);
    // The part every unit but the tables repeats, precompiled: a unit compiles only its own code.
    const UnitHeader header = unit_header_of(toolchain, options, unit_dir, stem);
    bool header_ready = !header.gch.empty() && access(header.gch.c_str(), R_OK) == 0;
    if (!header.gch.empty() && !header_ready && options.precompile_unit_header && !todo.empty()) {
        std::string message;
        header_ready = precompile_unit_header(options, header, units, message);
    }
    const auto uses_header = [&](std::size_t k) {
        // (the code unit at another level: a .gch is only for the flags it was made with)
        return header_ready && k >= 1 && &unit_options(k) == &options &&
               units[k].compare(0, options.unit_header.size(), options.unit_header) == 0;
    };
    const auto unit_command = [&](std::size_t k, const std::string& source,
                                  const std::string& object) {
        if (!uses_header(k)) return object_command(toolchain, unit_options(k), source, object);
        std::vector<std::string> cmd = compiler_flags(toolchain, options);
        cmd.insert(cmd.end(), {"-include-pch", header.gch});
        for (const std::string& f : options.extra_flags)
            if (!link_only(f)) cmd.push_back(f);
        cmd.insert(cmd.end(), {"-c", source, "-o", object});
        return cmd;
    };
    std::atomic<std::size_t> next{0};
    std::atomic<bool> failed{false};
    std::vector<std::string> errors(units.size());
    const auto compile = [&] {
        for (std::size_t i; !failed && (i = next++) < todo.size();) {
            const std::size_t k = todo[i];
            std::string& message = errors[k];
            const std::string source =
                (fs::path(work) / (stem + "-" + std::to_string(k) + ".cpp")).string();
            std::string temp;
            const std::string text =
                uses_header(k) ? units[k].substr(options.unit_header.size()) : units[k];
            bool done = write_file_atomically(source, text, message) &&
                        !(temp = create_temporary_sibling(objects[k], message)).empty();
            done = done && run(unit_command(k, source, temp), "the C++ compiler failed", message);
            if (done && std::rename(temp.c_str(), objects[k].c_str()) != 0) {
                message = "cannot write '" + objects[k] + "'";
                done = false;
            }
            if (!done && !temp.empty()) remove_if_present(temp);
            if (!done) failed = true;
        }
    };
    {
        std::vector<std::thread> helpers;
        const std::size_t jobs = std::max<std::size_t>(1, options.jobs);
        for (std::size_t j = 1; j < std::min(jobs, todo.size()); ++j) helpers.emplace_back(compile);
        compile();
        for (std::thread& t : helpers) t.join();
    }
    bool ok = !failed;
    for (const std::size_t k : todo)
        if (!errors[k].empty() && error.empty()) error = errors[k];
    std::string temp;
    if (ok && copies_state(objects)) {
        splittable = false;
        error = "the units would each have their own copy of a static variable";
        ok = false;
    }
    if (ok) ok = !(temp = create_temporary_sibling(library, error)).empty();
    if (ok) {
        // References inside the library stay inside it: the %source's functions, now `inline`
        // and exported, are not taken from the host when they share a name with one of its.
        std::vector<std::string> link{options.link_command.front(), "-Bsymbolic"};
        for (std::size_t k = 1; k < options.link_command.size(); ++k) {
            const std::string& w = options.link_command[k];
            if (w == kLinkObject)
                link.insert(link.end(), objects.begin(), objects.end());
            else
                link.push_back(w == kLinkOutput ? temp : w);
        }
        ok = run(link, "linking the rule code failed", error);
        // The units define something twice: %source that only a whole program can have.
        if (!ok && error.find("exit status") != std::string::npos) splittable = false;
    }
    if (ok && std::rename(temp.c_str(), library.c_str()) != 0) {
        error = "cannot write '" + library + "'";
        ok = false;
    }
    if (!ok && !temp.empty()) remove_if_present(temp);
    if (!splittable) {
        std::string ignored;
        write_file_atomically(whole.string(), error + "\n", ignored);
    }
    fs::remove_all(work, ec);
    return ok;
}

}  // namespace acanthus
