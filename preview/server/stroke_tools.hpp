// Strokes a stdlib library lets the user draw on the picture (its guides), as the library
// declares them in its registration (acanthus_stdlib_preview_strokes in
// cmake/AcanthusStdlib.cmake). The server and the page know no library's parameters: they
// offer the tools of the libraries the program imports.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "compilation.hpp"

namespace acanthus {

struct StrokeTool {
    std::string library;                   // "growth": its rule file is growth.acr
    std::vector<std::string> kinds;        // "flow", "boundary", "spray"
    std::vector<std::string> width_kinds;  // strokes whose width is their brush diameter
    std::string file_param;                // the parameter naming the strokes' SVG
    std::string mode_param;                // empty: none
    std::vector<std::string> mode_kinds;   // while one is drawn, mode_param is its kind

    bool has_kind(const std::string& kind) const;
    bool has_width(const std::string& kind) const;
    nlohmann::json to_json() const;
    // The kind mode_param takes for `kinds_drawn`: the first drawn of mode_kinds, else empty
    // (the rule file's own default).
    std::string mode_for(const std::vector<std::string>& kinds_drawn) const;
};

// The declarations: a JSON array of {"library", "kinds", "width_kinds", "file_param",
// "mode_param", "mode_kinds"}. False with `error` on anything else.
bool parse_stroke_tools(const std::string& text, std::vector<StrokeTool>& tools,
                        std::string& error);

// The tools of the libraries a program uses: whose rule file (LIBRARY.acr in one of
// `stdlib_dirs`) the compiler read, and whose file parameter the program has.
std::vector<StrokeTool> stroke_tools_of(const std::vector<StrokeTool>& declared,
                                        const std::vector<std::string>& read_files,
                                        const std::vector<std::string>& stdlib_dirs,
                                        const std::vector<ParamSummary>& params);

}  // namespace acanthus
