// An output against its reference: SVG (and the other vector formats) byte for byte, PNG pixel
// by pixel within a per-channel tolerance; a diff picture for each mismatch.
#pragma once

#include <cstddef>
#include <string>

#include "batch/job_list.hpp"

namespace acanthus::batch {

enum class Verdict { not_checked, same, differs, no_reference, updated, error };

const char* verdict_name(Verdict verdict);

struct CheckOutcome {
    Verdict verdict = Verdict::not_checked;
    std::string reference;     // absolute path
    std::string message;       // why it differs, or what went wrong
    std::string diff_picture;  // absolute path, empty when none was written
};

struct CheckSettings {
    std::string reference_directory;  // empty: no check
    std::string diff_directory;       // diff pictures: <dir>/<output>.diff.png
    int tolerance = 8;                // per channel, 0..255
    double max_differing_fraction = 0.001;
    bool update = false;  // write the references instead of comparing
};

struct PixelComparison {
    bool readable = false;
    std::string error;
    int width = 0, height = 0;  // of the new picture
    bool same_size = false;
    std::size_t differing_pixels = 0;
    std::size_t total_pixels = 0;
};

// Compares two PNG files (decoded by Cairo); with `diff_picture` set, writes the differing
// pixels in red over a faint copy of the reference there, atomically, when any differ.
PixelComparison compare_png(const std::string& reference, const std::string& candidate,
                            int tolerance, const std::string& diff_picture);

// Checks (or with `update`, writes) the reference of `job`'s output.
CheckOutcome check_output(const Job& job, const CheckSettings& settings);

}  // namespace acanthus::batch
