// The results of a batch: report.json (what `acanthus batch report` merges), junit.xml for CI
// servers and index.html (reference, new and diff side by side, failures first).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "batch/job_list.hpp"
#include "batch/reference_check.hpp"

namespace acanthus::batch {

enum class RunStatus { rendered, skipped, failed };

const char* run_status_name(RunStatus status);

struct JobResult {
    Job job;
    RunStatus status = RunStatus::failed;
    std::string message;  // why the job failed: the program's or the compiler's messages
    double seconds = 0;
    CheckOutcome check;
};

// Rendered or skipped, and matching its reference when checked.
bool job_passed(const JobResult& result);

// One result as report.json holds it; pictures are copied into `report_directory` and named
// relative to it.
nlohmann::json result_json(const JobResult& result, const std::string& report_directory);

// Writes report.json, junit.xml and index.html into `directory` from the results'
// JSON (result_json), sorted by job index. False with `error` set.
bool write_report_files(const std::string& directory, const std::string& title,
                        std::vector<nlohmann::json> results, double seconds, std::string& error);

// `acanthus batch report OUT DIR...`: the report.json of each DIR (shards of one manifest)
// merged into OUT, pictures copied. False with `error` set (a missing or bad report.json).
bool merge_reports(const std::string& output_directory, const std::vector<std::string>& inputs,
                   std::string& error);

}  // namespace acanthus::batch
