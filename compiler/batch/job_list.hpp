// The manifest multiplied out: one job per rule x panel x seed x parameter values x format, in
// manifest order, each with its output path; and the slice of it one shard runs.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "batch/manifest.hpp"

namespace acanthus::batch {

struct Job {
    std::size_t index = 0;   // position in the whole list (before sharding)
    std::string rule;        // absolute path of the rule file
    std::string rule_name;   // its stem, {rule}
    std::string panel;       // --region argument: absolute path or built-in shape
    std::string panel_name;  // {panel}: file stem, or the shape's file-safe spelling
    std::uint64_t seed = 1;  // --rng-seed
    std::vector<std::pair<std::string, std::string>> params;  // --param NAME=VALUE
    std::vector<std::string> args;
    std::string format;           // {ext}
    std::string output_relative;  // the template filled in, relative to the output directory
    std::string output;           // absolute
};

// `rect:200,150` -> `rect-200x150`; any character but letters, digits, '.', '_', '-' -> '_'.
std::string file_safe(const std::string& text);

// {params}: `max_radius-2_rim-0.1` (file-safe), empty without parameters.
std::string params_name(const std::vector<std::pair<std::string, std::string>>& params);

// Expands every [[job]] of `manifest` with outputs under `output_directory`. Throws
// ManifestError for an unknown {placeholder}, an output leaving the output directory, or two
// jobs writing one file.
std::vector<Job> expand_jobs(const Manifest& manifest, const std::string& output_directory);

// Shard K of N: jobs whose index is K modulo N (round robin, so neighbouring jobs, often the
// same rule file, spread over the shards).
struct Shard {
    std::size_t index = 0;
    std::size_t count = 1;
};

// "K/N" with 0 <= K < N; false with `error` set otherwise.
bool parse_shard(const std::string& text, Shard& shard, std::string& error);

// --shard auto: K and N from SLURM_ARRAY_TASK_ID (minus SLURM_ARRAY_TASK_MIN) and
// SLURM_ARRAY_TASK_COUNT, or JOB_COMPLETION_INDEX (Kubernetes Indexed Jobs); `shards`, when not
// 0, gives N. `getenv` is a parameter so tests need not change the environment.
using Environment = std::function<const char*(const char*)>;
bool shard_from_environment(const Environment& getenv, std::size_t shards, Shard& shard,
                            std::string& error);

std::vector<Job> select_shard(const std::vector<Job>& jobs, Shard shard);

// --only GLOB...: keeps the jobs whose output (relative to the output directory) matches one of
// `patterns` (shell globs, `*` not crossing a `/`). False with `error` set, `jobs` unchanged,
// when a pattern matches no job: a typo must not pass as an empty, successful run.
bool select_outputs(std::vector<Job>& jobs, const std::vector<std::string>& patterns,
                    std::string& error);

}  // namespace acanthus::batch
