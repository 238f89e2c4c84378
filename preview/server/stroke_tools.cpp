#include "server/stroke_tools.hpp"

#include <algorithm>
#include <filesystem>

#include "server/diagnostics.hpp"

namespace acanthus {

namespace fs = std::filesystem;

namespace {

bool contains(const std::vector<std::string>& list, const std::string& item) {
    return std::find(list.begin(), list.end(), item) != list.end();
}

bool is_name(const nlohmann::json& value) {
    if (!value.is_string()) return false;
    const std::string text = value.get<std::string>();
    return !text.empty() && text.size() <= 64 &&
           text.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_") == std::string::npos;
}

bool names(const nlohmann::json& object, const char* field, std::vector<std::string>& out) {
    out.clear();
    if (!object.contains(field) || !object[field].is_array()) return false;
    for (const auto& item : object[field]) {
        if (!is_name(item)) return false;
        out.push_back(item.get<std::string>());
    }
    return true;
}

}  // namespace

bool StrokeTool::has_kind(const std::string& kind) const { return contains(kinds, kind); }

bool StrokeTool::has_width(const std::string& kind) const { return contains(width_kinds, kind); }

nlohmann::json StrokeTool::to_json() const {
    return {{"library", library},       {"kinds", kinds},           {"width_kinds", width_kinds},
            {"file_param", file_param}, {"mode_param", mode_param}, {"mode_kinds", mode_kinds}};
}

std::string StrokeTool::mode_for(const std::vector<std::string>& kinds_drawn) const {
    if (mode_param.empty()) return {};
    for (const std::string& kind : kinds_drawn)
        if (contains(mode_kinds, kind)) return kind;
    return {};
}

bool parse_stroke_tools(const std::string& text, std::vector<StrokeTool>& tools,
                        std::string& error) {
    tools.clear();
    const nlohmann::json all = nlohmann::json::parse(text, nullptr, false);
    if (!all.is_array()) return error = "the stroke tools are not a JSON array", false;
    for (std::size_t i = 0; i < all.size(); ++i) {
        const nlohmann::json& t = all[i];
        StrokeTool tool;
        const std::string where = "stroke tool " + std::to_string(i) + ": ";
        if (!t.is_object() || !is_name(t.value("library", nlohmann::json())) ||
            !is_name(t.value("file_param", nlohmann::json())))
            return error = where + "needs a library and a file_param", false;
        tool.library = t["library"].get<std::string>();
        tool.file_param = t["file_param"].get<std::string>();
        if (t.contains("mode_param") && t["mode_param"] != "") {
            if (!is_name(t["mode_param"])) return error = where + "bad mode_param", false;
            tool.mode_param = t["mode_param"].get<std::string>();
        }
        if (!names(t, "kinds", tool.kinds) || tool.kinds.empty() ||
            !names(t, "width_kinds", tool.width_kinds) || !names(t, "mode_kinds", tool.mode_kinds))
            return error = where + "kinds, width_kinds and mode_kinds are lists of names", false;
        for (const auto* list : {&tool.width_kinds, &tool.mode_kinds})
            for (const std::string& kind : *list)
                if (!tool.has_kind(kind))
                    return error = where + "'" + kind + "' is not one of its kinds", false;
        tools.push_back(std::move(tool));
    }
    return true;
}

std::vector<StrokeTool> stroke_tools_of(const std::vector<StrokeTool>& declared,
                                        const std::vector<std::string>& read_files,
                                        const std::vector<std::string>& stdlib_dirs,
                                        const std::vector<ParamSummary>& params) {
    std::vector<std::string> read;
    for (const std::string& file : read_files) read.push_back(same_file_key(file));
    std::vector<StrokeTool> used;
    for (const StrokeTool& tool : declared) {
        const bool has_param = std::any_of(
            params.begin(), params.end(), [&](const auto& p) { return p.name == tool.file_param; });
        const bool imported =
            std::any_of(stdlib_dirs.begin(), stdlib_dirs.end(), [&](const std::string& dir) {
                return contains(read,
                                same_file_key((fs::path(dir) / (tool.library + ".acr")).string()));
            });
        if (has_param && imported) used.push_back(tool);
    }
    return used;
}

}  // namespace acanthus
