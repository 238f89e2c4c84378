// The reference arrangement as JSON (issue 10): {"elements": [{"symbol": "a", "label": "1",
// "x": 0, "y": 0, "angle": 0, "size": 3}], "flips": [[i, j]]}. "sub" is the label's old name.
#include <acanthus/error.hpp>
#include <acanthus/input_file.hpp>
#include <acanthus/stdlib/growth.hpp>
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "reference.hpp"

namespace acanthus::growth {
namespace {

using Json = nlohmann::json;

double number(const Json& e, const char* key, const std::string& where) {
    const Json& v = e.at(key);
    if (!v.is_number()) throw InputError(where + ": \"" + key + "\" is not a number");
    double d = v.get<double>();
    // JSON has no NaN or infinity: a non-finite value is a literal beyond the range of a double.
    if (!std::isfinite(d))
        throw InputError(where + ": \"" + key + "\" is out of range (beyond ±1.8e308)");
    return d;
}

std::string text(const Json& e, const char* key, const std::string& where) {
    const Json& v = e.at(key);
    if (!v.is_string()) throw InputError(where + ": \"" + key + "\" is not a string");
    return v.get<std::string>();
}

// Deepest nesting of arrays and objects outside strings: parsed JSON is freed recursively, so a
// file of a million '[' must be refused before it is parsed.
std::size_t nesting_depth(std::string_view text) {
    std::size_t depth = 0, deepest = 0;
    bool in_string = false, escaped = false;
    for (char ch : text) {
        if (in_string) {
            if (escaped)
                escaped = false;
            else if (ch == '\\')
                escaped = true;
            else if (ch == '"')
                in_string = false;
        } else if (ch == '"') {
            in_string = true;
        } else if (ch == '[' || ch == '{') {
            deepest = std::max(deepest, ++depth);
        } else if ((ch == ']' || ch == '}') && depth > 0) {
            --depth;
        }
    }
    return deepest;
}

// "LINE:COLUMN" of the byte the parser stopped at (nlohmann counts from 1, past the last read).
std::string line_and_column(std::string_view text, std::size_t byte) {
    std::size_t end = std::min(byte > 0 ? byte - 1 : 0, text.size());
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < end; ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return std::to_string(line) + ":" + std::to_string(column);
}

// The parser's own words without its prefix ("[json.exception.parse_error.101] parse error at
// line 1, column 5: "): what was wrong, its position given once by the caller.
std::string parser_reason(std::string_view what) {
    std::size_t colon = what.find(": ");
    return std::string(colon == std::string_view::npos ? what : what.substr(colon + 2));
}

}  // namespace

Reference Reference::from_json_string(std::string_view input, const std::string& name) {
    if (nesting_depth(input) > 64) throw InputError(name + ": malformed JSON (nested too deeply)");
    // Literal NaN and Infinity are not JSON; the parser rejects them as malformed.
    Json doc;
    try {
        doc = Json::parse(input);
    } catch (const Json::parse_error& e) {
        throw InputError(name + ":" + line_and_column(input, e.byte) +
                         ": malformed JSON: " + parser_reason(e.what()));
    } catch (const Json::out_of_range& e) {
        // A number literal beyond a double ("1e999"): the parser names it, not where it is.
        std::string what = e.what();
        std::size_t open = what.find('\''), close = what.rfind('\'');
        std::string literal =
            open < close ? what.substr(open + 1, close - open - 1) : std::string("a number");
        std::size_t at = input.find(literal);
        throw InputError(
            name + (at == std::string_view::npos ? "" : ":" + line_and_column(input, at + 1)) +
            ": number out of range: " + literal + " (beyond ±1.8e308)");
    }
    if (!doc.is_object() || !doc.contains("elements") || !doc["elements"].is_array())
        throw InputError(name + ": expected an object with an \"elements\" array");
    std::vector<ReferenceElement> elements;
    const Json& list = doc["elements"];
    for (std::size_t i = 0; i < list.size(); ++i) {
        const Json& e = list[i];
        std::string where = name + ": element " + std::to_string(i);
        if (!e.is_object()) throw InputError(where + ": not an object");
        for (const char* key : {"symbol", "x", "y"})
            if (!e.contains(key)) throw InputError(where + ": missing \"" + key + "\"");
        ReferenceElement r;
        r.symbol = text(e, "symbol", where);
        if (r.symbol.empty()) throw InputError(where + ": empty \"symbol\"");
        r.position = {number(e, "x", where), number(e, "y", where)};
        if (e.contains("label") && e.contains("sub"))
            throw InputError(where + ": \"label\" and its old name \"sub\" both given");
        for (const char* key : {"label", "sub"})
            if (e.contains(key)) r.label = text(e, key, where);
        if (e.contains("angle")) r.angle = number(e, "angle", where);
        if (e.contains("size")) {
            r.size = number(e, "size", where);
            if (!(r.size > 0)) throw InputError(where + ": \"size\" must be positive");
        }
        elements.push_back(std::move(r));
    }
    std::vector<std::pair<int, int>> flips;
    if (doc.contains("flips")) {
        const Json& f = doc["flips"];
        if (!f.is_array()) throw InputError(name + ": \"flips\" is not an array");
        for (std::size_t k = 0; k < f.size(); ++k) {
            const Json& pair = f[k];
            auto index = [&](const Json& v) {
                if (!v.is_number_integer())
                    throw InputError(name + ": flip " + std::to_string(k) +
                                     ": expected two element indices");
                return v.get<long long>();
            };
            if (!pair.is_array() || pair.size() != 2)
                throw InputError(name + ": flip " + std::to_string(k) + ": expected a pair [i, j]");
            long long i = index(pair[0]), j = index(pair[1]);
            auto n = static_cast<long long>(elements.size());
            if (i < 0 || j < 0 || i >= n || j >= n)
                throw InputError(name + ": flip " + std::to_string(k) + " [" + std::to_string(i) +
                                 ", " + std::to_string(j) + "] names no edge (no such element)");
            flips.emplace_back(static_cast<int>(i), static_cast<int>(j));
        }
    }
    return from_elements(std::move(elements), std::move(flips), name);
}

Reference Reference::from_json_file(const std::string& path) {
    std::string content = read_input_file_or_throw(path, "reference arrangement");
    return from_json_string(content, path);
}

}  // namespace acanthus::growth
