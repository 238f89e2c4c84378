#include "server/diagnostics.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace acanthus {

std::vector<PreviewDiagnostic> parse_diagnostics(const std::string& output) {
    static const std::regex located(R"(^(.+?):(\d+):(\d+): (?:fatal )?error: (.*)$)");
    static const std::regex unlocated(R"(^([^ :][^:]*): (?:fatal )?error: (.*)$)");
    std::vector<PreviewDiagnostic> out;
    std::istringstream in(output);
    std::string line;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::smatch m;
        if (std::regex_match(line, m, located)) {
            try {
                out.push_back({m[1], std::stoi(m[2]), std::stoi(m[3]), m[4]});
            } catch (const std::exception&) {
                out.push_back({m[1], 0, 0, m[4]});
            }
        } else if (std::regex_match(line, m, unlocated)) {
            // The program names the rule file and line of a failing rule: `x.acr:31: rule ...`.
            static const std::regex rule(R"(^(.+?\.acr):(\d+): (.*)$)");
            std::smatch r;
            const std::string message = m[2];
            if (std::regex_match(message, r, rule))
                out.push_back({r[1], std::stoi(r[2]), 0, r[3]});
            else
                out.push_back({m[1], 0, 0, message});
        }
    }
    return out;
}

namespace {

// Line `n` (1-based) of `file`, without its newline; false when there is none.
bool line_of(const std::string& file, int n, std::string& out) {
    std::ifstream in(file, std::ios::binary);
    for (int i = 1; in && i <= n; ++i)
        if (!std::getline(in, out)) return false;
    return static_cast<bool>(in) || !out.empty();
}

// The column in `source` of column `column` (1-based) of `generated`, the same line after the
// compiler rewrote it ($goal -> acanthus::body::goal()): a column in the common start stays, one
// in the common end keeps its distance from the end, one in between goes to the changed part.
int source_column(const std::string& generated, const std::string& source, int column) {
    std::size_t head = 0;
    while (head < generated.size() && head < source.size() && generated[head] == source[head])
        ++head;
    std::size_t tail = 0;
    while (tail < generated.size() - head && tail < source.size() - head &&
           generated[generated.size() - 1 - tail] == source[source.size() - 1 - tail])
        ++tail;
    const std::size_t c = static_cast<std::size_t>(column > 0 ? column - 1 : 0);
    if (c < head) return column;
    if (c >= generated.size() - tail) {
        const std::size_t from_end = generated.size() - c;
        return static_cast<int>(source.size() - std::min(from_end, source.size())) + 1;
    }
    return static_cast<int>(head) + 1;
}

}  // namespace

std::string in_rule_source(const std::string& output) {
    static const std::regex located(R"(^(.+\.acr):(\d+):(\d+): (.*)$)");
    static const std::regex gcc_excerpt(R"(^(\s*\d+ \| )(.*)$)");
    static const std::regex temporary(R"(^(In file included from )?[^ ]*/acanthus-build\.[^/ ]+/)");
    std::vector<std::string> lines;
    std::istringstream in(output);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    std::string out;
    std::smatch m;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string& line = lines[i];
        // The generated file is gone when the page shows this: its lines and their excerpts.
        if (std::regex_search(line, m, temporary)) {
            while (i + 1 < lines.size() && !lines[i + 1].empty() && lines[i + 1][0] == ' ') ++i;
            continue;
        }
        std::string source;
        if (!std::regex_match(line, m, located) || i + 1 >= lines.size() ||
            !line_of(m[1], std::stoi(m[2]), source)) {
            out += line + "\n";
            continue;
        }
        const std::string file = m[1], at = m[2], message = m[4];
        const int column = std::stoi(m[3]);
        std::string prefix, generated = lines[i + 1];
        std::smatch e;
        if (std::regex_match(lines[i + 1], e, gcc_excerpt)) {
            prefix = e[1];
            generated = e[2];
        }
        if (generated == source) {
            out += line + "\n";
            continue;
        }
        const int mapped = source_column(generated, source, column);
        out += file + ":" + at + ":" + std::to_string(mapped) + ": " + message + "\n";
        out += prefix + source + "\n";
        std::string caret = prefix;
        if (!prefix.empty()) caret = std::string(prefix.size() - 2, ' ') + "| ";
        out += caret + std::string(static_cast<std::size_t>(mapped - 1), ' ') + "^\n";
        ++i;  // the excerpt; then its caret and fix-it lines, which were for the generated line
        while (i + 1 < lines.size() && !lines[i + 1].empty() && lines[i + 1][0] == ' ' &&
               !std::regex_match(lines[i + 1], e, gcc_excerpt))
            ++i;
    }
    return out;
}

std::string same_file_key(const std::string& path) {
    std::error_code ec;
    const std::filesystem::path p = std::filesystem::weakly_canonical(path, ec);
    return ec ? path : p.string();
}

void add_source_context(std::vector<PreviewDiagnostic>& diagnostics,
                        const std::vector<std::string>& files, int around) {
    std::vector<std::string> known;
    for (const std::string& f : files) known.push_back(same_file_key(f));
    for (PreviewDiagnostic& d : diagnostics) {
        if (d.line <= 0 ||
            std::find(known.begin(), known.end(), same_file_key(d.file)) == known.end())
            continue;
        std::ifstream in(d.file);
        d.context.clear();
        d.context_first = std::max(1, d.line - around);
        int number = 0;
        for (std::string line; number < d.line + around && std::getline(in, line);)
            if (++number >= d.context_first) d.context.push_back(line.substr(0, 400));
        if (d.context.empty()) d.context_first = 0;
    }
}

std::vector<std::string> editor_command(const std::string& command, const std::string& file,
                                        int line, int column) {
    std::vector<std::string> words;
    std::string word;
    bool in_word = false;
    char quote = 0;
    for (char c : command) {
        if (quote) {
            if (c == quote)
                quote = 0;
            else
                word += c;
        } else if (c == '\'' || c == '"') {
            quote = c;
            in_word = true;
        } else if (c == ' ' || c == '\t') {
            if (in_word) words.push_back(word);
            word.clear();
            in_word = false;
        } else {
            word += c;
            in_word = true;
        }
    }
    if (in_word) words.push_back(word);
    bool named = false;
    const auto replace_all = [](std::string& text, const std::string& what, const std::string& by) {
        for (std::size_t at = text.find(what); at != std::string::npos;
             at = text.find(what, at + by.size()))
            text.replace(at, what.size(), by);
    };
    for (std::string& w : words) {
        named = named || w.find("{file}") != std::string::npos;
        replace_all(w, "{line}", std::to_string(line));
        replace_all(w, "{column}", std::to_string(column));
        replace_all(w, "{file}", file);
    }
    if (!named && !words.empty()) {
        words.push_back("+" + std::to_string(line));
        words.push_back(file);
    }
    return words;
}

}  // namespace acanthus
