#include "batch/reference_check.hpp"

#include <cairo.h>
#include <unistd.h>

#include <acanthus/input_file.hpp>
#include <acanthus/output_file.hpp>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <memory>

#include "batch/child_process.hpp"

namespace acanthus::batch {

namespace fs = std::filesystem;

const char* verdict_name(Verdict verdict) {
    switch (verdict) {
        case Verdict::not_checked:
            return "not checked";
        case Verdict::same:
            return "same";
        case Verdict::differs:
            return "differs";
        case Verdict::no_reference:
            return "no reference";
        case Verdict::updated:
            return "updated";
        case Verdict::error:
            return "error";
    }
    return "?";
}

namespace {

using Surface = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;

// A PNG as 32-bit ARGB whatever its own format (grey, RGB, palette...).
Surface load_argb(const std::string& path, std::string& error) {
    Surface file(cairo_image_surface_create_from_png(path.c_str()), cairo_surface_destroy);
    if (cairo_surface_status(file.get()) != CAIRO_STATUS_SUCCESS) {
        error = path + ": cannot read the PNG: " +
                cairo_status_to_string(cairo_surface_status(file.get()));
        return Surface(nullptr, cairo_surface_destroy);
    }
    int width = cairo_image_surface_get_width(file.get());
    int height = cairo_image_surface_get_height(file.get());
    Surface argb(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height),
                 cairo_surface_destroy);
    cairo_t* cr = cairo_create(argb.get());
    cairo_set_source_surface(cr, file.get(), 0, 0);
    cairo_set_operator(cr, CAIRO_OPERATOR_SOURCE);
    cairo_paint(cr);
    cairo_destroy(cr);
    cairo_surface_flush(argb.get());
    return argb;
}

std::uint32_t pixel(cairo_surface_t* surface, int x, int y) {
    const unsigned char* row =
        cairo_image_surface_get_data(surface) + y * cairo_image_surface_get_stride(surface);
    return reinterpret_cast<const std::uint32_t*>(row)[x];
}

bool channels_close(std::uint32_t a, std::uint32_t b, int tolerance) {
    for (int shift = 0; shift < 32; shift += 8) {
        int da = static_cast<int>((a >> shift) & 0xff) - static_cast<int>((b >> shift) & 0xff);
        if (std::abs(da) > tolerance) return false;
    }
    return true;
}

bool write_png_atomically(cairo_surface_t* surface, const std::string& path, std::string& error) {
    std::error_code ec;
    fs::create_directories(fs::path(path).parent_path(), ec);
    std::string temporary = create_temporary_sibling(path, error);
    if (temporary.empty()) return false;
    if (cairo_surface_write_to_png(surface, temporary.c_str()) != CAIRO_STATUS_SUCCESS) {
        remove_if_present(temporary);
        error = "cannot write '" + path + "'";
        return false;
    }
    return replace_with_temporary(temporary, path, error);
}

bool same_bytes(const std::string& a, const std::string& b, std::string& error) {
    std::string left, right;
    if (std::string why = read_input_file(a, left); !why.empty()) {
        error = a + ": " + why;
        return false;
    }
    if (std::string why = read_input_file(b, right); !why.empty()) {
        error = b + ": " + why;
        return false;
    }
    return left == right;
}

// rsvg-convert (librsvg2-bin) when it is installed: SVG differences become a picture too.
bool rasterize_svg(const std::string& svg, const std::string& png) {
    ChildResult child =
        run_child({"rsvg-convert", "--background-color", "white", "-o", png, svg}, "");
    return child.exit_status == 0;
}

}  // namespace

PixelComparison compare_png(const std::string& reference, const std::string& candidate,
                            int tolerance, const std::string& diff_picture) {
    PixelComparison result;
    Surface ref = load_argb(reference, result.error);
    if (!ref) return result;
    Surface now = load_argb(candidate, result.error);
    if (!now) return result;
    result.readable = true;
    int rw = cairo_image_surface_get_width(ref.get()),
        rh = cairo_image_surface_get_height(ref.get());
    result.width = cairo_image_surface_get_width(now.get());
    result.height = cairo_image_surface_get_height(now.get());
    result.same_size = rw == result.width && rh == result.height;
    int width = std::max(rw, result.width), height = std::max(rh, result.height);
    result.total_pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);

    Surface diff(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height),
                 cairo_surface_destroy);
    cairo_t* cr = cairo_create(diff.get());
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_set_source_surface(cr, ref.get(), 0, 0);
    cairo_paint_with_alpha(cr, 0.25);
    cairo_destroy(cr);
    cairo_surface_flush(diff.get());
    unsigned char* data = cairo_image_surface_get_data(diff.get());
    int stride = cairo_image_surface_get_stride(diff.get());
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            bool inside = x < rw && y < rh && x < result.width && y < result.height;
            if (inside && channels_close(pixel(ref.get(), x, y), pixel(now.get(), x, y), tolerance))
                continue;
            ++result.differing_pixels;
            reinterpret_cast<std::uint32_t*>(data + y * stride)[x] = 0xffff0000u;
        }
    cairo_surface_mark_dirty(diff.get());
    if (result.differing_pixels > 0 && !diff_picture.empty()) {
        std::string error;
        if (!write_png_atomically(diff.get(), diff_picture, error)) result.error = error;
    }
    return result;
}

CheckOutcome check_output(const Job& job, const CheckSettings& settings) {
    CheckOutcome outcome;
    if (settings.reference_directory.empty()) return outcome;
    outcome.reference = (fs::absolute(settings.reference_directory) / job.output_relative)
                            .lexically_normal()
                            .string();
    std::error_code ec;
    if (settings.update) {
        std::string bytes, error;
        fs::create_directories(fs::path(outcome.reference).parent_path(), ec);
        if (std::string why = read_input_file(job.output, bytes); !why.empty()) {
            outcome.verdict = Verdict::error;
            outcome.message = job.output + ": " + why;
        } else if (!write_file_atomically(outcome.reference, bytes, error)) {
            outcome.verdict = Verdict::error;
            outcome.message = error;
        } else {
            outcome.verdict = Verdict::updated;
        }
        return outcome;
    }
    if (!fs::is_regular_file(outcome.reference, ec)) {
        outcome.verdict = Verdict::no_reference;
        outcome.message =
            "no reference '" + outcome.reference + "' (--update-references writes it)";
        return outcome;
    }
    const std::string diff_picture =
        settings.diff_directory.empty()
            ? std::string()
            : (fs::path(settings.diff_directory) / (job.output_relative + ".diff.png")).string();
    remove_if_present(diff_picture);  // a picture from an earlier mismatch would mislead
    if (job.format == "png") {
        PixelComparison cmp =
            compare_png(outcome.reference, job.output, settings.tolerance, diff_picture);
        if (!cmp.readable) {
            outcome.verdict = Verdict::error;
            outcome.message = cmp.error;
            return outcome;
        }
        double fraction = cmp.total_pixels ? static_cast<double>(cmp.differing_pixels) /
                                                 static_cast<double>(cmp.total_pixels)
                                           : 0.0;
        if (cmp.same_size && fraction <= settings.max_differing_fraction) {
            outcome.verdict = Verdict::same;
            remove_if_present(diff_picture);
            return outcome;
        }
        outcome.verdict = Verdict::differs;
        outcome.message =
            cmp.same_size ? std::to_string(cmp.differing_pixels) + " of " +
                                std::to_string(cmp.total_pixels) + " pixels differ by more than " +
                                std::to_string(settings.tolerance) + " in a channel"
                          : "the picture is " + std::to_string(cmp.width) + " x " +
                                std::to_string(cmp.height) + ", not the reference's size";
        if (cmp.differing_pixels > 0) outcome.diff_picture = diff_picture;
        return outcome;
    }
    std::string error;
    if (same_bytes(outcome.reference, job.output, error)) {
        outcome.verdict = Verdict::same;
        return outcome;
    }
    if (!error.empty()) {
        outcome.verdict = Verdict::error;
        outcome.message = error;
        return outcome;
    }
    outcome.verdict = Verdict::differs;
    outcome.message = "the " + job.format + " file differs from the reference";
    if (job.format == "svg" && !diff_picture.empty()) {
        // Both rasterized next to the diff picture, then compared exactly.
        fs::create_directories(fs::path(diff_picture).parent_path(), ec);
        std::string ref_png = diff_picture + ".reference.tmp.png";
        std::string new_png = diff_picture + ".new.tmp.png";
        if (rasterize_svg(outcome.reference, ref_png) && rasterize_svg(job.output, new_png)) {
            PixelComparison cmp = compare_png(ref_png, new_png, 0, diff_picture);
            if (cmp.readable && cmp.differing_pixels > 0) {
                outcome.diff_picture = diff_picture;
                outcome.message += " (" + std::to_string(cmp.differing_pixels) + " of " +
                                   std::to_string(cmp.total_pixels) + " pixels differ rasterized)";
            } else if (cmp.readable) {
                outcome.message += " (the same pixels once rasterized)";
            }
        }
        remove_if_present(ref_png);
        remove_if_present(new_png);
    }
    return outcome;
}

}  // namespace acanthus::batch
