// Runs a batch's jobs: each rule file built once, jobs N at a time in separate processes, a
// failed job never stopping the others; progress on stderr.
#pragma once

#include <string>
#include <vector>

#include "batch/batch_report.hpp"
#include "batch/job_list.hpp"
#include "batch/reference_check.hpp"

namespace acanthus::batch {

struct RunSettings {
    std::string manifest_directory;  // jobs run there, so relative arguments resolve against it
    std::string output_directory;
    unsigned parallel_jobs = 1;
    bool force = false;
    bool show_progress = true;
    CheckSettings check;
};

struct BatchRun {
    std::vector<JobResult> results;  // in job order
    std::size_t programs_built = 0, programs_failed = 0;
    double build_seconds = 0, seconds = 0;
};

BatchRun run_jobs(const std::vector<Job>& jobs, const RunSettings& settings);

}  // namespace acanthus::batch
