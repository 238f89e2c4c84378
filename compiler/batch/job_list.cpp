#include "batch/job_list.hpp"

#include <fnmatch.h>

#include <charconv>
#include <filesystem>
#include <map>

namespace acanthus::batch {

namespace fs = std::filesystem;

std::string file_safe(const std::string& text) {
    std::string out;
    for (char c : text) {
        bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                     c == '.' || c == '_' || c == '-';
        if (plain)
            out += c;
        else if (c == ':' || c == '=')
            out += '-';
        else if (c == ',')
            out += 'x';
        else
            out += '_';
    }
    // "." and ".." would name directories.
    if (out.find_first_not_of('.') == std::string::npos) out = "_" + out;
    return out;
}

std::string params_name(const std::vector<std::pair<std::string, std::string>>& params) {
    std::string out;
    for (const auto& [name, value] : params) {
        if (!out.empty()) out += '_';
        out += name + "=" + value;
    }
    return out.empty() ? out : file_safe(out);
}

namespace {

std::string panel_name(const std::string& panel) {
    if (is_builtin_panel(panel)) return file_safe(panel);
    return file_safe(fs::path(panel).stem().string());
}

std::string fill_template(const Manifest& manifest, const Placed<std::string>& output,
                          const Job& job) {
    std::string out;
    const std::string& text = output.value;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '{') {
            out += text[i];
            continue;
        }
        std::size_t close = text.find('}', i);
        if (close == std::string::npos)
            throw ManifestError(manifest.path, output.where, "'output' has a '{' without its '}'");
        std::string name = text.substr(i + 1, close - i - 1);
        if (name == "rule")
            out += job.rule_name;
        else if (name == "panel")
            out += job.panel_name;
        else if (name == "seed")
            out += std::to_string(job.seed);
        else if (name == "ext")
            out += job.format;
        else if (name == "params")
            out += params_name(job.params);
        else
            throw ManifestError(manifest.path, output.where,
                                "unknown placeholder '{" + name +
                                    "}' in 'output' (use {rule}, {panel}, {seed}, {params}, "
                                    "{ext})");
        i = close;
    }
    return out;
}

// Every combination of parameter values, the last parameter changing fastest.
std::vector<std::vector<std::pair<std::string, std::string>>> param_product(
    const std::vector<ParamValues>& params) {
    std::vector<std::vector<std::pair<std::string, std::string>>> out{{}};
    for (const ParamValues& param : params) {
        std::vector<std::vector<std::pair<std::string, std::string>>> next;
        for (const auto& partial : out)
            for (const std::string& value : param.values) {
                next.push_back(partial);
                next.back().emplace_back(param.name, value);
            }
        out = std::move(next);
    }
    return out;
}

}  // namespace

std::vector<Job> expand_jobs(const Manifest& manifest, const std::string& output_directory) {
    std::vector<Job> jobs;
    std::map<std::string, std::pair<std::size_t, ManifestPosition>> writers;  // output -> job
    for (const JobSpec& spec : manifest.jobs) {
        auto combinations = param_product(spec.params);
        for (const auto& rule : spec.rules)
            for (const auto& panel : spec.panels)
                for (const auto& params : combinations)
                    for (const auto& seed : spec.seeds)
                        for (const auto& format : spec.formats) {
                            Job job;
                            job.index = jobs.size();
                            job.rule = rule.value;
                            job.rule_name = fs::path(rule.value).stem().string();
                            job.panel = panel.value;
                            job.panel_name = panel_name(panel.value);
                            job.seed = seed.value;
                            job.params = params;
                            job.args = spec.args;
                            job.format = format.value;
                            fs::path relative = fs::path(fill_template(manifest, spec.output, job))
                                                    .lexically_normal();
                            if (relative.empty() || relative.is_absolute() ||
                                *relative.begin() == ".." || !relative.has_filename())
                                throw ManifestError(manifest.path, spec.output.where,
                                                    "'output' gives '" + relative.string() +
                                                        "', which is not below the output "
                                                        "directory");
                            job.output_relative = relative.string();
                            job.output = (fs::path(output_directory) / relative).string();
                            auto [it, fresh] = writers.emplace(
                                job.output_relative, std::make_pair(job.index, spec.output.where));
                            if (!fresh)
                                throw ManifestError(
                                    manifest.path, spec.output.where,
                                    "two jobs write '" + job.output_relative +
                                        "' (the 'output' at line " +
                                        std::to_string(it->second.second.line) +
                                        " too); add {params}, {seed}, {panel} or {ext} to it");
                            jobs.push_back(std::move(job));
                        }
    }
    if (jobs.empty()) throw ManifestError(manifest.path, {1, 1}, "empty product: no jobs");
    return jobs;
}

namespace {

bool parse_count(std::string_view text, std::size_t& value) {
    if (text.empty()) return false;
    auto result = std::from_chars(text.data(), text.data() + text.size(), value);
    return result.ec == std::errc() && result.ptr == text.data() + text.size();
}

}  // namespace

bool parse_shard(const std::string& text, Shard& shard, std::string& error) {
    std::size_t slash = text.find('/');
    if (slash == std::string::npos ||
        !parse_count(std::string_view(text).substr(0, slash), shard.index) ||
        !parse_count(std::string_view(text).substr(slash + 1), shard.count) || shard.count == 0 ||
        shard.index >= shard.count) {
        error = "bad --shard '" + text + "' (use K/N with 0 <= K < N, or auto)";
        return false;
    }
    return true;
}

bool shard_from_environment(const Environment& getenv, std::size_t shards, Shard& shard,
                            std::string& error) {
    auto number = [&](const char* name, std::size_t& value) {
        const char* text = getenv(name);
        return text && parse_count(text, value);
    };
    std::size_t id = 0, minimum = 0, count = 0;
    if (number("SLURM_ARRAY_TASK_ID", id)) {
        number("SLURM_ARRAY_TASK_MIN", minimum);
        if (shards == 0 && !number("SLURM_ARRAY_TASK_COUNT", count)) {
            error = "--shard auto: SLURM_ARRAY_TASK_COUNT is not set; give --shards N";
            return false;
        }
        shard.index = id - std::min(minimum, id);
        shard.count = shards ? shards : count;
    } else if (number("JOB_COMPLETION_INDEX", id)) {
        if (shards == 0) {
            error =
                "--shard auto with JOB_COMPLETION_INDEX needs --shards N (the Job's completions)";
            return false;
        }
        shard.index = id;
        shard.count = shards;
    } else {
        error =
            "--shard auto: neither SLURM_ARRAY_TASK_ID nor JOB_COMPLETION_INDEX is set to a number";
        return false;
    }
    if (shard.count == 0 || shard.index >= shard.count) {
        error = "--shard auto: task " + std::to_string(shard.index) + " is not below the " +
                std::to_string(shard.count) + " shards";
        return false;
    }
    return true;
}

std::vector<Job> select_shard(const std::vector<Job>& jobs, Shard shard) {
    std::vector<Job> out;
    for (const Job& job : jobs)
        if (job.index % shard.count == shard.index) out.push_back(job);
    return out;
}

bool select_outputs(std::vector<Job>& jobs, const std::vector<std::string>& patterns,
                    std::string& error) {
    if (patterns.empty()) return true;
    std::vector<bool> used(patterns.size());
    std::vector<Job> out;
    for (Job& job : jobs) {
        bool selected = false;
        for (std::size_t i = 0; i < patterns.size(); ++i) {
            if (fnmatch(patterns[i].c_str(), job.output_relative.c_str(), FNM_PATHNAME) == 0) {
                used[i] = true;
                selected = true;
            }
        }
        if (selected) out.push_back(std::move(job));
    }
    for (std::size_t i = 0; i < patterns.size(); ++i) {
        if (!used[i]) {
            error = "--only '" + patterns[i] + "' matches no job's output";
            return false;
        }
    }
    jobs = std::move(out);
    return true;
}

}  // namespace acanthus::batch
