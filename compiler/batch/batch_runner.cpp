#include "batch/batch_runner.hpp"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <map>
#include <mutex>
#include <thread>

#include "batch/child_process.hpp"
#include "batch/job_state.hpp"
#include "batch/rule_programs.hpp"
#include "toolchain/toolchain.hpp"

namespace acanthus::batch {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// Calls `work(i)` for i in [0, count) on up to `threads` threads.
template <typename Work>
void for_each_parallel(std::size_t count, unsigned threads, Work work) {
    std::atomic<std::size_t> next{0};
    auto loop = [&] {
        for (std::size_t i = next++; i < count; i = next++) work(i);
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < std::min<std::size_t>(threads, count); ++t) pool.emplace_back(loop);
    loop();
    for (std::thread& thread : pool) thread.join();
}

// One line rewritten in place on a terminal; one line per finished job elsewhere (CI logs).
class Progress {
  public:
    Progress(std::size_t total, bool enabled)
        : total_(total), enabled_(enabled), terminal_(isatty(2) != 0) {}

    void started() {
        std::lock_guard lock(mutex_);
        ++running_;
        if (terminal_) draw();
    }

    void finished(const JobResult& result) {
        std::lock_guard lock(mutex_);
        --running_;
        ++done_;
        if (result.status == RunStatus::failed || !job_passed(result)) ++failed_;
        if (!enabled_) return;
        if (terminal_) {
            draw();
            return;
        }
        std::cerr << "batch: [" << done_ << "/" << total_ << "] " << run_status_name(result.status);
        if (result.check.verdict != Verdict::not_checked)
            std::cerr << ", " << verdict_name(result.check.verdict);
        std::cerr << " " << result.job.output_relative;
        if (result.status == RunStatus::rendered)
            std::cerr << " (" << static_cast<int>(result.seconds * 1000) << " ms)";
        std::cerr << '\n';
    }

    void end() {
        std::lock_guard lock(mutex_);
        if (enabled_ && terminal_) std::cerr << "\r\033[K" << std::flush;
    }

  private:
    void draw() {
        if (!enabled_) return;
        const int width = 30;
        int filled = total_ ? static_cast<int>(width * done_ / total_) : width;
        std::cerr << "\r\033[Kbatch: [" << std::string(filled, '#')
                  << std::string(width - filled, '.') << "] " << done_ << "/" << total_ << ", "
                  << running_ << " running";
        if (failed_) std::cerr << ", " << failed_ << " failed or differ";
        std::cerr << std::flush;
    }

    std::mutex mutex_;
    std::size_t total_, done_ = 0, running_ = 0, failed_ = 0;
    bool enabled_, terminal_;
};

std::vector<std::string> program_command(const Job& job, const std::string& executable) {
    std::vector<std::string> cmd{executable, "--region", job.panel, "--rng-seed",
                                 std::to_string(job.seed)};
    for (const auto& [name, value] : job.params)
        cmd.insert(cmd.end(), {"--param", name + "=" + value});
    cmd.insert(cmd.end(), job.args.begin(), job.args.end());
    cmd.insert(cmd.end(), {"--quiet", "-o", job.output});
    return cmd;
}

std::string trimmed(std::string text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
    return text;
}

}  // namespace

BatchRun run_jobs(const std::vector<Job>& jobs, const RunSettings& settings) {
    BatchRun run;
    const auto start = Clock::now();
    const Toolchain toolchain = find_toolchain();
    const BuildOptions build_options;  // what `acanthus run` uses, so the cache is shared

    // The front end once per rule file (quick): it gives each job's input key.
    std::map<std::string, RuleProgram> programs;
    for (const Job& job : jobs)
        if (!programs.count(job.rule))
            programs.emplace(job.rule, prepare_rule_program(job.rule, toolchain, build_options));

    run.results.resize(jobs.size());
    std::vector<std::string> keys(jobs.size());
    std::vector<bool> pending(jobs.size());
    std::map<std::string, bool> needed;  // rule -> some job must run
    for (std::size_t i = 0; i < jobs.size(); ++i) {
        const RuleProgram& program = programs.at(jobs[i].rule);
        run.results[i].job = jobs[i];
        if (program.error.empty())
            keys[i] = job_input_key(jobs[i], program.key, settings.manifest_directory);
        pending[i] = !program.error.empty() || settings.force ||
                     !job_up_to_date(jobs[i], settings.output_directory, keys[i]);
        if (pending[i]) needed[jobs[i].rule] = true;
    }

    // The C++ compiler once per rule file a job needs, in the content-hash cache.
    std::vector<RuleProgram*> to_build;
    for (auto& [rule, program] : programs)
        if (needed.count(rule) && program.error.empty()) to_build.push_back(&program);
    const auto build_start = Clock::now();
    if (!to_build.empty() && settings.show_progress)
        std::cerr << "batch: building " << to_build.size() << " rule file"
                  << (to_build.size() == 1 ? "" : "s") << "\n";
    for_each_parallel(to_build.size(), settings.parallel_jobs, [&](std::size_t i) {
        build_rule_program(*to_build[i], toolchain, build_options);
    });
    run.build_seconds = seconds_since(build_start);
    for (const auto& [rule, program] : programs) {
        if (!needed.count(rule)) continue;
        if (program.error.empty())
            ++run.programs_built;
        else
            ++run.programs_failed;
    }

    Progress progress(jobs.size(), settings.show_progress);
    for_each_parallel(jobs.size(), settings.parallel_jobs, [&](std::size_t i) {
        JobResult& result = run.results[i];
        const Job& job = jobs[i];
        progress.started();
        const auto job_start = Clock::now();
        if (!pending[i]) {
            result.status = RunStatus::skipped;
        } else if (const RuleProgram& program = programs.at(job.rule); !program.error.empty()) {
            result.status = RunStatus::failed;
            result.message = trimmed(program.error);
        } else {
            forget_job(job, settings.output_directory);
            std::error_code ec;
            fs::create_directories(fs::path(job.output).parent_path(), ec);
            ChildResult child =
                run_child(program_command(job, program.executable), settings.manifest_directory);
            if (child.exit_status == 0) {
                result.status = RunStatus::rendered;
                std::string error;
                if (!record_job(job, settings.output_directory, keys[i], error))
                    std::cerr << "batch: warning: " << error << '\n';
            } else {
                result.status = RunStatus::failed;
                result.message = trimmed(child.output);
                std::string status = child.exit_status < 0
                                         ? child.error
                                         : "exit status " + std::to_string(child.exit_status);
                result.message =
                    result.message.empty() ? status : result.message + " (" + status + ")";
            }
        }
        result.seconds = seconds_since(job_start);
        if (result.status != RunStatus::failed) result.check = check_output(job, settings.check);
        progress.finished(result);
    });
    progress.end();
    run.seconds = seconds_since(start);
    return run;
}

}  // namespace acanthus::batch
