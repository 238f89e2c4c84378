// Where the runtime headers, libraries and stdlib rule files are: the install layout next to
// the running executable when it is there, else the build tree baked in at configure time.
#pragma once

#include <string>
#include <vector>

namespace acanthus {

struct Toolchain {
    bool installed = false;
    std::vector<std::string> include_dirs;  // -I for the generated C++
    std::string runtime_library;            // libacanthus.a
    std::string stdlib_library;             // libacanthus_stdlib.a, or empty
    std::vector<std::string> link_flags;    // -lcairo ...
    // The runtime's sanitizer flags (-DACANTHUS_SANITIZE=ON): a generated program compiled and
    // linked without them cannot link against a sanitized libacanthus.a.
    std::vector<std::string> sanitize_flags;
    std::vector<std::string> stdlib_dirs;  // where %import looks after -I
    std::string default_cxx;
    std::string preview_dir;  // the preview page (index.html, preview.js, preview.css)
    std::string panels_dir;   // the panels the preview offers
    // The stroke tools stdlib libraries declare for the preview page: a JSON array, one object
    // per library (cmake/AcanthusStdlib.cmake, acanthus_stdlib_preview_strokes).
    std::string preview_strokes = "[]";
};

Toolchain find_toolchain();

}  // namespace acanthus
