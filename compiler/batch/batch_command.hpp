// `acanthus batch MANIFEST` and `acanthus batch report`: the options and the entry points
// main.cpp wires (docs/batch.md).
#pragma once

#include <CLI/CLI.hpp>
#include <cstddef>
#include <string>
#include <vector>

namespace acanthus::batch {

struct BatchOptions {
    std::string manifest;
    unsigned jobs = 0;             // 0: one per core
    bool force = false;            // redo jobs whose inputs are unchanged
    bool quiet = false;            // no progress lines
    std::string output_directory;  // default: the manifest's directory
    std::string reference_directory;
    bool update_references = false;
    std::string report_directory;  // default with --check: <output dir>/batch-report
    int tolerance = 8;
    double max_differing_fraction = 0.001;
    std::string shard;              // "K/N" or "auto"
    std::size_t shards = 0;         // N for --shard auto
    std::vector<std::string> only;  // output globs: run just these jobs
    // `batch report`
    std::vector<std::string> report_inputs;
    std::string merged_report;
    CLI::App* report_command = nullptr;
};

// Adds `batch` (and `batch report`) to `app`; returns the `batch` subcommand.
CLI::App* add_batch_command(CLI::App& app, BatchOptions& options);

// Exit status: 0 every job succeeded (and matched), 1 some job failed or differs, 2 a bad
// manifest or usage.
int run_batch_command(const BatchOptions& options);

}  // namespace acanthus::batch
