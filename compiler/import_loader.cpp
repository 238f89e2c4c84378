#include "import_loader.hpp"

#include <acanthus/input_file.hpp>
#include <filesystem>

#include "parse_driver.hpp"

namespace acanthus {

namespace fs = std::filesystem;

namespace {

// Deep import chains are legal, but not unbounded recursion on the C++ stack.
constexpr int kMaxImportDepth = 200;

std::string canonical_path(const std::string& path) {
    std::error_code ec;
    fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
    return ec ? path : p.string();
}

// Any file but a directory: a FIFO or a device is found, then refused by the reader.
bool is_candidate(const fs::path& p) {
    std::error_code ec;
    return fs::exists(p, ec) && !fs::is_directory(p, ec);
}

}  // namespace

ImportLoader::ImportLoader(SourceFiles& files, Diagnostics& diagnostics,
                           std::vector<std::string> include_dirs,
                           std::vector<std::string> stdlib_dirs)
    : files_(files),
      diagnostics_(diagnostics),
      include_dirs_(std::move(include_dirs)),
      stdlib_dirs_(std::move(stdlib_dirs)) {}

std::string ImportLoader::resolve(const std::string& name, const std::string& from_dir) const {
    if (name.empty()) return {};
    std::vector<std::string> candidates{name};
    if (fs::path(name).extension() != ".acr") candidates.push_back(name + ".acr");
    std::vector<std::string> dirs;
    if (fs::path(name).is_absolute()) {
        dirs.push_back("");
    } else {
        dirs.push_back(from_dir);
        dirs.insert(dirs.end(), include_dirs_.begin(), include_dirs_.end());
        dirs.insert(dirs.end(), stdlib_dirs_.begin(), stdlib_dirs_.end());
    }
    for (const std::string& dir : dirs) {
        for (const std::string& c : candidates) {
            fs::path p = dir.empty() ? fs::path(c) : fs::path(dir) / c;
            if (is_candidate(p)) return p.lexically_normal().string();
        }
    }
    return {};
}

bool ImportLoader::load(const std::string& path, std::string& error) {
    std::string text;
    error = read_input_file(path, text);
    if (!error.empty()) return false;
    main_file_ = files_.add(path, std::move(text));
    load_file(main_file_, canonical_path(path));
    return true;
}

const ast::RuleFile* ImportLoader::load_file(std::uint32_t index, const std::string& canonical) {
    seen_[canonical] = State::loading;
    ParseDriver driver(files_, diagnostics_);
    parsed_.push_back(driver.parse(index));
    ast::RuleFile* file = parsed_.back().get();
    std::string dir = fs::path(files_[index].path()).parent_path().string();
    ++depth_;
    for (ast::Section& section : file->sections) {
        auto* import = std::get_if<ast::ImportDecl>(&section);
        if (!import) continue;
        const std::string& name = import->target.text;
        std::string found = resolve(name, dir);
        if (found.empty()) {
            diagnostics_.error(import->target.where,
                               "cannot find rule file '" + name +
                                   "' (looked in the importing file's directory, the -I "
                                   "directories and the standard library)");
            continue;
        }
        std::string key = canonical_path(found);
        auto it = seen_.find(key);
        if (it != seen_.end()) {
            if (it->second == State::loading) {
                diagnostics_.error(import->target.where,
                                   "cyclic import: '" + found + "' is already being imported");
            }
            continue;  // imported once: later imports add nothing
        }
        if (depth_ >= kMaxImportDepth) {
            diagnostics_.error(import->target.where, "imports nested too deeply");
            continue;
        }
        std::string text;
        if (std::string error = read_input_file(found, text); !error.empty()) {
            diagnostics_.error(import->target.where, "cannot read '" + found + "': " + error);
            continue;
        }
        std::uint32_t imported = files_.add(found, std::move(text));
        import->file = load_file(imported, key);
    }
    --depth_;
    seen_[canonical] = State::done;
    return file;
}

void ImportLoader::flatten(const ast::RuleFile& file, RuleProgram& out) const {
    for (const ast::Section& section : file.sections) {
        out.sections.push_back(SectionRef{&section, file.file});
        if (const auto* import = std::get_if<ast::ImportDecl>(&section); import && import->file) {
            flatten(*import->file, out);
        }
    }
}

RuleProgram ImportLoader::program() const {
    RuleProgram out;
    out.main_file = main_file_;
    if (!parsed_.empty()) flatten(*parsed_.front(), out);
    return out;
}

}  // namespace acanthus
