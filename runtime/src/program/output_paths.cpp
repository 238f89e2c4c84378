// Distinct outputs, no input overwritten (see output_paths.hpp).
#include "program/output_paths.hpp"

#include <acanthus/error.hpp>
#include <filesystem>
#include <string>
#include <vector>

namespace acanthus::detail {

namespace {

namespace fs = std::filesystem;

struct NamedPath {
    std::string option;  // "-o", "--json", ...
    std::string path;
};

std::string canonical(const std::string& path) {
    std::error_code ec;
    fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
    return ec ? fs::path(path).lexically_normal().string() : p.string();
}

bool is_shape_argument(const std::string& region) {
    for (const char* prefix : {"rect:", "circle:", "ellipse:"})
        if (region.rfind(prefix, 0) == 0) return true;
    return false;
}

}  // namespace

void check_output_paths(const ProgramOptions& o) {
    std::vector<NamedPath> outputs;
    if (o.output != "-") outputs.push_back({"-o", o.output});
    if (!o.json.empty()) outputs.push_back({"--json", o.json});
    if (!o.debug_path.empty()) outputs.push_back({"--debug-frame", o.debug_path});
    if (!o.frames_dir.empty()) outputs.push_back({"--frames", o.frames_dir});
    if (!o.partial.empty()) outputs.push_back({"--partial", o.partial});
    if (!o.view.empty()) outputs.push_back({"--view", o.view});

    std::vector<NamedPath> inputs;
    if (!o.region.empty() && !is_shape_argument(o.region)) inputs.push_back({"--region", o.region});
    if (!o.render.stroke.empty()) inputs.push_back({"--stroke", o.render.stroke});

    for (std::size_t i = 0; i < outputs.size(); ++i) {
        const std::string a = canonical(outputs[i].path);
        for (std::size_t j = i + 1; j < outputs.size(); ++j)
            if (canonical(outputs[j].path) == a)
                throw UsageError(outputs[i].option + " and " + outputs[j].option +
                                 " name the same file '" + outputs[i].path +
                                 "'; give each output its own file");
        for (const NamedPath& in : inputs)
            if (canonical(in.path) == a)
                throw UsageError(outputs[i].option + " '" + outputs[i].path +
                                 "' would overwrite the " + in.option + " input '" + in.path +
                                 "'; write the output elsewhere");
    }
}

}  // namespace acanthus::detail
