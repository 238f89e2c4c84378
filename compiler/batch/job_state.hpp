// What a job's output was made from, kept so a second run skips jobs whose inputs are unchanged.
// One small file per job in <output dir>/.acanthus-batch/ (shards never write the same one).
#pragma once

#include <string>

#include "batch/job_list.hpp"

namespace acanthus::batch {

// The job's inputs: `program_key` (rule file, imports, compiler, runtime, version), the panel
// file's contents, seed, parameters, args (and the contents of any file a parameter or an
// argument names, relative to `manifest_directory`), format and output path.
std::string job_input_key(const Job& job, const std::string& program_key,
                          const std::string& manifest_directory);

// True when the last run of the job had these inputs and its output is still the file it wrote.
bool job_up_to_date(const Job& job, const std::string& output_directory,
                    const std::string& input_key);

// Records a successful run; false with `error` set when the state cannot be written.
bool record_job(const Job& job, const std::string& output_directory, const std::string& input_key,
                std::string& error);

// Forgets a job (it failed, or is about to be redone).
void forget_job(const Job& job, const std::string& output_directory);

// Hash of a file's contents, "" when it cannot be read.
std::string content_key(const std::string& path);

}  // namespace acanthus::batch
