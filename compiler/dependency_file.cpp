#include "dependency_file.hpp"

#include <algorithm>
#include <filesystem>

namespace acanthus {

namespace fs = std::filesystem;

namespace {

// Make's escapes: a space or '#' after a backslash, '$' doubled. A backslash is literal
// unless it precedes one of those, so only a backslash run before a space or '#' is doubled.
std::string make_escaped(const std::string& path) {
    std::string out;
    std::size_t backslashes = 0;
    for (char c : path) {
        if (c == ' ' || c == '#') {
            out.append(backslashes, '\\');
            out += '\\';
        }
        if (c == '$') out += '$';
        out += c;
        backslashes = c == '\\' ? backslashes + 1 : 0;
    }
    return out;
}

}  // namespace

std::vector<std::string> rule_file_dependencies(const std::vector<std::string>& read_files) {
    std::vector<std::string> out;
    for (const std::string& file : read_files) {
        std::error_code ec;
        fs::path absolute = fs::absolute(file, ec);
        std::string path = (ec ? fs::path(file) : absolute).lexically_normal().string();
        if (std::find(out.begin(), out.end(), path) == out.end()) out.push_back(path);
    }
    return out;
}

bool make_dependency_rule(const std::string& target, const std::vector<std::string>& dependencies,
                          std::string& text, std::string& error) {
    text = make_escaped(target) + ":";
    for (const std::string& path : dependencies) {
        if (path.find_first_of("\n\r") != std::string::npos) {
            error = "a depfile cannot name '" + path + "' (a line break in the path)";
            return false;
        }
        text += " \\\n  " + make_escaped(path);
    }
    if (target.find_first_of("\n\r") != std::string::npos) {
        error = "a depfile cannot name '" + target + "' (a line break in the path)";
        return false;
    }
    text += '\n';
    return true;
}

}  // namespace acanthus
