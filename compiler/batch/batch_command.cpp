#include "batch/batch_command.hpp"

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <thread>

#include "batch/batch_runner.hpp"
#include "batch/manifest.hpp"

namespace acanthus::batch {

namespace fs = std::filesystem;

namespace {

constexpr int kFailed = 1;
constexpr int kBadUsage = 2;

int usage_error(const std::string& message) {
    std::cerr << "acanthus batch: error: " << message << '\n';
    return kBadUsage;
}

// The first lines of a long message (a compiler's errors): the summary stays readable.
std::string first_lines(const std::string& text, int lines) {
    std::size_t end = 0;
    for (int i = 0; i < lines && end != std::string::npos; ++i) {
        end = text.find('\n', end == 0 && i == 0 ? 0 : end + 1);
    }
    if (end == std::string::npos) return text;
    return text.substr(0, end) + "\n    ...";
}

std::string indented(const std::string& text) {
    std::string out = "    ";
    for (char c : text) {
        out += c;
        if (c == '\n') out += "    ";
    }
    return out;
}

std::string one_decimal(double seconds) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.1f", seconds);
    return buffer;
}

}  // namespace

CLI::App* add_batch_command(CLI::App& app, BatchOptions& o) {
    auto* batch = app.add_subcommand(
        "batch",
        "Render rule files x panels x seeds x parameters from a TOML manifest, in parallel; "
        "skip what is up to date; compare with references (docs/batch.md)");
    batch->add_option("manifest", o.manifest, "Manifest (TOML) of [[job]] tables");
    batch->add_option("-j,--jobs", o.jobs, "Jobs run at once (default: one per core)")
        ->check(CLI::Range(1u, 1024u));
    batch->add_flag("--force", o.force, "Redo jobs whose inputs are unchanged");
    batch->add_flag("-q,--quiet", o.quiet, "No progress lines, only the summary");
    batch->add_option("--output-dir", o.output_directory,
                      "Where the output templates start (default: the manifest's directory)");
    batch->add_option(
        "--check", o.reference_directory,
        "Compare each output with REFDIR/<output> (SVG byte for byte, PNG per pixel)");
    batch->add_flag("--update-references", o.update_references,
                    "With --check: write the outputs as the references");
    batch->add_option("--report", o.report_directory,
                      "Write index.html, junit.xml, report.json and *.diff.png there (default "
                      "with --check: <output dir>/batch-report)");
    batch
        ->add_option("--tolerance", o.tolerance, "PNG: largest difference in a channel (default 8)")
        ->check(CLI::Range(0, 255));
    batch
        ->add_option("--max-differing", o.max_differing_fraction,
                     "PNG: fraction of pixels allowed beyond the tolerance (default 0.001)")
        ->check(CLI::Range(0.0, 1.0));
    batch->add_option("--shard", o.shard,
                      "Run shard K/N of the job list (jobs K, K+N, ...), or 'auto' from "
                      "SLURM_ARRAY_TASK_ID / JOB_COMPLETION_INDEX");
    batch->add_option("--shards", o.shards, "N for --shard auto")
        ->check(CLI::Range(1ul, 1000000ul));
    batch
        ->add_option("--only", o.only,
                     "Run only the jobs whose output matches GLOB (relative to the output "
                     "directory, e.g. 'out/dots/*'; repeatable)")
        ->allow_extra_args(false);

    o.report_command = batch->add_subcommand(
        "report", "Merge the reports of shards (their --report directories) into one");
    o.report_command->add_option("directories", o.report_inputs, "Shard report directories")
        ->required();
    o.report_command->add_option("-o,--output", o.merged_report, "Merged report directory")
        ->required();
    batch->footer(
        "Usage: acanthus batch MANIFEST [--jobs N] [--force] [--check REFDIR "
        "[--update-references]] [--report DIR] [--shard K/N | --shard auto [--shards N]] "
        "[--only GLOB]...\n"
        "       acanthus batch report SHARD_REPORT... -o DIR");
    return batch;
}

int run_batch_command(const BatchOptions& o) {
    if (o.report_command && o.report_command->parsed()) {
        std::string error;
        if (!merge_reports(o.merged_report, o.report_inputs, error)) {
            std::cerr << "acanthus batch report: error: " << error << '\n';
            return kBadUsage;
        }
        std::cerr << "batch: report " << (fs::path(o.merged_report) / "index.html").string()
                  << '\n';
        return 0;
    }
    if (o.manifest.empty()) return usage_error("a manifest is required (acanthus batch MANIFEST)");
    if (o.update_references && o.reference_directory.empty())
        return usage_error("--update-references needs --check REFDIR");
    if (o.shards && o.shard != "auto") return usage_error("--shards N goes with --shard auto");

    Shard shard;
    std::string error;
    if (o.shard == "auto") {
        if (!shard_from_environment(
                [](const char* name) -> const char* { return std::getenv(name); }, o.shards, shard,
                error))
            return usage_error(error);
    } else if (!o.shard.empty() && !parse_shard(o.shard, shard, error)) {
        return usage_error(error);
    }

    Manifest manifest;
    std::vector<Job> all_jobs;
    RunSettings settings;
    try {
        manifest = load_manifest(o.manifest);
        settings.manifest_directory = manifest.directory;
        settings.output_directory =
            o.output_directory.empty()
                ? manifest.directory
                : fs::absolute(o.output_directory).lexically_normal().string();
        all_jobs = expand_jobs(manifest, settings.output_directory);
    } catch (const ManifestError& e) {
        std::cerr << e.what() << '\n';
        return kBadUsage;
    }
    // Before sharding: a glob is checked against every job, not only this shard's.
    if (!select_outputs(all_jobs, o.only, error)) return usage_error(error);
    std::vector<Job> jobs = select_shard(all_jobs, shard);

    settings.parallel_jobs = o.jobs ? o.jobs : std::max(1u, std::thread::hardware_concurrency());
    settings.force = o.force;
    settings.show_progress = !o.quiet;
    std::string report_directory = o.report_directory;
    if (report_directory.empty() && !o.reference_directory.empty())
        report_directory = (fs::path(settings.output_directory) / "batch-report").string();
    if (!report_directory.empty())
        report_directory = fs::absolute(report_directory).lexically_normal().string();
    settings.check.reference_directory = o.reference_directory;
    settings.check.diff_directory = report_directory;
    settings.check.tolerance = o.tolerance;
    settings.check.max_differing_fraction = o.max_differing_fraction;
    settings.check.update = o.update_references;

    BatchRun run = run_jobs(jobs, settings);

    std::size_t rendered = 0, skipped = 0, failed = 0, differ = 0, updated = 0;
    for (const JobResult& r : run.results) {
        if (r.status == RunStatus::rendered) ++rendered;
        if (r.status == RunStatus::skipped) ++skipped;
        if (r.status == RunStatus::failed) ++failed;
        if (r.status != RunStatus::failed && !job_passed(r)) ++differ;
        if (r.check.verdict == Verdict::updated) ++updated;
    }
    for (const JobResult& r : run.results) {
        if (job_passed(r)) continue;
        if (r.status == RunStatus::failed) {
            std::cerr << "FAILED " << r.job.output_relative << " (" << r.job.rule_name << ", "
                      << r.job.panel_name << ", seed " << r.job.seed << "):\n"
                      << indented(first_lines(r.message, 12)) << '\n';
        } else {
            std::cerr << "DIFFERS " << r.job.output_relative << ": " << r.check.message
                      << "; new render " << r.job.output;
            if (!r.check.diff_picture.empty())
                std::cerr << "; diff picture " << r.check.diff_picture;
            std::cerr << '\n';
        }
    }

    std::cerr << "batch: " << jobs.size() << " jobs";
    if (shard.count > 1)
        std::cerr << " (shard " << shard.index << "/" << shard.count << " of " << all_jobs.size()
                  << ")";
    std::cerr << ": " << rendered << " rendered, " << skipped << " up to date, " << failed
              << " failed";
    if (!o.reference_directory.empty()) {
        if (o.update_references)
            std::cerr << "; " << updated << " references written";
        else
            std::cerr << "; " << differ << " differ from the references";
    }
    std::cerr << "; " << one_decimal(run.seconds) << " s";
    if (run.programs_built + run.programs_failed > 0)
        std::cerr << " (rule files built: " << run.programs_built + run.programs_failed << " in "
                  << one_decimal(run.build_seconds) << " s, " << run.programs_failed << " failed)";
    std::cerr << '\n';

    if (!report_directory.empty()) {
        std::vector<nlohmann::json> results;
        for (const JobResult& r : run.results) results.push_back(result_json(r, report_directory));
        if (!write_report_files(report_directory, "acanthus batch " + manifest.path,
                                std::move(results), run.seconds, error)) {
            std::cerr << "acanthus batch: error: " << error << '\n';
            return kFailed;
        }
        std::cerr << "batch: report " << (fs::path(report_directory) / "index.html").string()
                  << '\n';
    }
    return failed + differ > 0 ? kFailed : 0;
}

}  // namespace acanthus::batch
