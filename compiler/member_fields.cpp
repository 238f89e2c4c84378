#include "member_fields.hpp"

#include <algorithm>
#include <array>

namespace acanthus {

namespace {

struct Token {
    enum Kind { ident, number, literal, punct } kind;
    std::size_t offset;
    std::string_view text;
};

bool ident_start(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; }
bool ident_char(char c) { return ident_start(c) || (c >= '0' && c <= '9'); }

// A rough C++ tokenizer: enough to find declarations, skipping comments and literals.
std::vector<Token> tokenize(std::string_view s) {
    std::vector<Token> out;
    std::size_t i = 0;
    while (i < s.size()) {
        char c = s[i];
        if (c == '/' && i + 1 < s.size() && s[i + 1] == '/') {
            while (i < s.size() && s[i] != '\n') ++i;
        } else if (c == '/' && i + 1 < s.size() && s[i + 1] == '*') {
            std::size_t end = s.find("*/", i + 2);
            i = end == std::string_view::npos ? s.size() : end + 2;
        } else if (c == '"' || c == '\'') {
            std::size_t start = i++;
            while (i < s.size() && s[i] != c && s[i] != '\n') i += s[i] == '\\' ? 2 : 1;
            i = std::min(i + 1, s.size());
            out.push_back({Token::literal, start, s.substr(start, i - start)});
        } else if (ident_start(c)) {
            std::size_t start = i;
            while (i < s.size() && ident_char(s[i])) ++i;
            out.push_back({Token::ident, start, s.substr(start, i - start)});
        } else if (c >= '0' && c <= '9') {
            std::size_t start = i;
            while (i < s.size() && (ident_char(s[i]) || s[i] == '.' || s[i] == '\'')) ++i;
            out.push_back({Token::number, start, s.substr(start, i - start)});
        } else if (c == ':' && i + 1 < s.size() && s[i + 1] == ':') {
            out.push_back({Token::punct, i, s.substr(i, 2)});
            i += 2;
        } else if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v') {
            ++i;
        } else {
            out.push_back({Token::punct, i, s.substr(i, 1)});
            ++i;
        }
    }
    return out;
}

bool is(const Token& t, std::string_view text) { return t.text == text; }

constexpr std::array<std::string_view, 16> kNotSimple{
    "static",   "using",   "typedef",   "friend", "struct",   "class",    "enum",      "union",
    "template", "virtual", "constexpr", "inline", "explicit", "operator", "consteval", "extern"};

constexpr std::array<std::string_view, 8> kRecordedTypes{
    "int", "long", "unsigned", "unsigned int", "float", "double", "bool", "std::string"};

std::string join_type(const std::vector<Token>& tokens, std::size_t begin, std::size_t end) {
    std::string out;
    for (std::size_t i = begin; i < end; ++i) {
        bool glue = is(tokens[i], "::") || (i > begin && is(tokens[i - 1], "::"));
        if (!out.empty() && !glue) out += ' ';
        out += tokens[i].text;
    }
    return out;
}

}  // namespace

MemberAnalysis analyze_members(std::string_view text) {
    MemberAnalysis result;
    std::vector<Token> tokens = tokenize(text);
    std::vector<std::size_t> inserts;  // offsets where `{}` goes

    std::size_t i = 0;
    while (i < tokens.size()) {
        // One statement: up to a top-level ';', or a function body's closing '}'.
        std::size_t start = i;
        int depth = 0;
        bool paren_seen = false;
        std::size_t end = tokens.size();
        for (std::size_t j = i; j < tokens.size(); ++j) {
            const Token& t = tokens[j];
            if (is(t, "(") || is(t, "[") || is(t, "{")) {
                if (is(t, "(") && depth == 0) paren_seen = true;
                ++depth;
            } else if (is(t, ")") || is(t, "]") || is(t, "}")) {
                depth = std::max(0, depth - 1);
                if (is(t, "}") && depth == 0 && paren_seen &&
                    (j + 1 >= tokens.size() || !is(tokens[j + 1], ";"))) {
                    end = j;  // a member function definition
                    break;
                }
            } else if (is(t, ";") && depth == 0) {
                end = j;
                break;
            }
        }
        i = end + 1;
        // Access specifiers.
        while (start + 1 < end && tokens[start].kind == Token::ident &&
               (is(tokens[start], "public") || is(tokens[start], "private") ||
                is(tokens[start], "protected")) &&
               is(tokens[start + 1], ":")) {
            start += 2;
        }
        if (start >= end || end >= tokens.size() || !is(tokens[end], ";")) continue;
        if (std::find(kNotSimple.begin(), kNotSimple.end(), tokens[start].text) !=
            kNotSimple.end()) {
            continue;
        }
        if (paren_seen) continue;
        bool odd = false;
        for (std::size_t j = start; j < end; ++j) {
            if (is(tokens[j], "operator") || is(tokens[j], "~")) odd = true;
        }
        if (odd) continue;

        // Declarators, split at top-level commas (angle brackets count before an initializer).
        std::vector<std::pair<std::size_t, std::size_t>> declarators;
        {
            int nest = 0, angle = 0;
            bool in_init = false;
            std::size_t d_begin = start;
            for (std::size_t j = start; j <= end; ++j) {
                const Token& t = tokens[j];
                if (j == end || (is(t, ",") && nest == 0 && angle == 0)) {
                    declarators.emplace_back(d_begin, j);
                    d_begin = j + 1;
                    in_init = false;
                    continue;
                }
                if (is(t, "(") || is(t, "[") || is(t, "{")) ++nest;
                if (is(t, ")") || is(t, "]") || is(t, "}")) nest = std::max(0, nest - 1);
                if (is(t, "=") && nest == 0) in_init = true;
                if (!in_init && nest == 0 && is(t, "<")) ++angle;
                if (!in_init && nest == 0 && is(t, ">") && angle > 0) --angle;
            }
        }

        std::string type;
        bool first = true;
        for (auto [b, e] : declarators) {
            // The part before any initializer.
            std::size_t init = e;
            bool has_init = false, reference = false, bitfield = false;
            int nest = 0;
            for (std::size_t j = b; j < e; ++j) {
                const Token& t = tokens[j];
                if (nest == 0 && (is(t, "=") || is(t, "{"))) {
                    init = std::min(init, j);
                    has_init = true;
                }
                if (is(t, "(") || is(t, "[") || is(t, "{")) ++nest;
                if (is(t, ")") || is(t, "]") || is(t, "}")) nest = std::max(0, nest - 1);
                if (j < init && (is(t, "&") || is(t, "&&"))) reference = true;
                if (j < init && nest == 0 && is(t, ":")) bitfield = true;
            }
            if (b >= init) break;  // malformed; leave the rest to the C++ compiler
            if (!has_init && !reference && !bitfield) inserts.push_back(tokens[e].offset);

            // Plain field: [type...] name, with no pointer, array or reference declarator.
            std::size_t id = init;
            while (id > b && tokens[id - 1].kind != Token::ident) --id;
            if (id == b) {
                first = false;
                continue;
            }
            --id;
            bool plain =
                tokens[id].kind == Token::ident && id + 1 == init && !reference && !bitfield;
            if (first) {
                if (id == b || is(tokens[id - 1], "*") || is(tokens[id - 1], "::")) plain = false;
                type = id > b ? join_type(tokens, b, id) : "";
                if (type.rfind("const ", 0) == 0) type = type.substr(6);
                if (type.rfind("mutable ", 0) == 0) type = type.substr(8);
                first = false;
            } else {
                plain = plain && id == b;
            }
            if (plain && std::find(kRecordedTypes.begin(), kRecordedTypes.end(), type) !=
                             kRecordedTypes.end()) {
                result.fields.push_back({std::string(tokens[id].text), type});
            }
        }
    }

    result.text.reserve(text.size() + 2 * inserts.size());
    std::size_t from = 0;
    for (std::size_t at : inserts) {
        result.text.append(text.substr(from, at - from));
        result.text += "{}";
        from = at;
    }
    result.text.append(text.substr(from));
    return result;
}

}  // namespace acanthus
