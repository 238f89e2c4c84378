#include "batch/job_state.hpp"

#include <acanthus/input_file.hpp>
#include <acanthus/output_file.hpp>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "toolchain/program_build.hpp"

namespace acanthus::batch {

namespace fs = std::filesystem;

namespace {

fs::path state_path(const Job& job, const std::string& output_directory) {
    return fs::path(output_directory) / ".acanthus-batch" /
           (cache_key({job.output_relative}) + ".json");
}

// A parameter value or an argument that names a file: its contents count, not just its name.
void add_named_file(std::vector<std::string>& parts, const std::string& text,
                    const std::string& manifest_directory) {
    if (text.empty() || text.size() > 4096) return;
    std::error_code ec;
    fs::path path = fs::path(manifest_directory) / text;
    if (fs::is_regular_file(path, ec)) parts.push_back("file " + text + " " + content_key(path));
}

}  // namespace

std::string content_key(const std::string& path) {
    std::string bytes;
    if (!read_input_file(path, bytes).empty()) return {};
    return cache_key({bytes});
}

std::string job_input_key(const Job& job, const std::string& program_key,
                          const std::string& manifest_directory) {
    std::vector<std::string> parts{"program", program_key, "panel", job.panel};
    if (!is_builtin_panel(job.panel)) parts.push_back(content_key(job.panel));
    parts.insert(parts.end(), {"seed", std::to_string(job.seed), "format", job.format, "output",
                               job.output_relative});
    for (const auto& [name, value] : job.params) {
        parts.insert(parts.end(), {"param", name, value});
        add_named_file(parts, value, manifest_directory);
    }
    for (const std::string& arg : job.args) {
        parts.insert(parts.end(), {"arg", arg});
        add_named_file(parts, arg, manifest_directory);
    }
    return cache_key(parts);
}

bool job_up_to_date(const Job& job, const std::string& output_directory,
                    const std::string& input_key) {
    std::string text;
    if (!read_input_file(state_path(job, output_directory).string(), text).empty()) return false;
    nlohmann::json state = nlohmann::json::parse(text, nullptr, false);
    if (!state.is_object()) return false;
    const std::string output_key = content_key(job.output);
    return state.value("output", "") == job.output_relative &&
           state.value("inputs", "") == input_key && !output_key.empty() &&
           state.value("output_contents", "") == output_key;
}

bool record_job(const Job& job, const std::string& output_directory, const std::string& input_key,
                std::string& error) {
    fs::path path = state_path(job, output_directory);
    std::error_code ec;
    fs::create_directories(path.parent_path(), ec);
    nlohmann::json state{{"output", job.output_relative},
                         {"inputs", input_key},
                         {"output_contents", content_key(job.output)}};
    return write_file_atomically(path.string(), state.dump(1) + "\n", error);
}

void forget_job(const Job& job, const std::string& output_directory) {
    remove_if_present(state_path(job, output_directory).string());
}

}  // namespace acanthus::batch
