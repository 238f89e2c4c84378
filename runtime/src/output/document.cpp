// Cairo surfaces for SVG, PDF, PS, EPS and PNG, written to memory and made reproducible.
#include "output/document.hpp"

#include <cairo-pdf.h>
#include <cairo-ps.h>
#include <cairo-svg.h>
#include <cairo.h>

#include <acanthus/error.hpp>
#include <cctype>
#include <map>
#include <new>
#include <string_view>

namespace acanthus::detail {

namespace {

// Every output claims the same creation date so that a re-render is byte-identical.
constexpr const char* fixed_pdf_date = "2000-01-01T00:00:00Z";
constexpr const char* fixed_ps_date = "Sat Jan  1 00:00:00 2000";

}  // namespace

struct OutputDocumentStream {
    static cairo_status_t write(void* closure, const unsigned char* data, unsigned int length) {
        auto* doc = static_cast<OutputDocument*>(closure);
        try {
            doc->bytes_.append(reinterpret_cast<const char*>(data), length);
            return CAIRO_STATUS_SUCCESS;
        } catch (const std::bad_alloc&) {
            doc->write_failed_ = true;
            return CAIRO_STATUS_WRITE_ERROR;
        }
    }
};

OutputDocument::OutputDocument(OutputFormat format, int width, int height, const std::string& title)
    : format_(format), width_(width), height_(height) {
    auto write = &OutputDocumentStream::write;
    switch (format) {
        case OutputFormat::svg:
            surface_ = cairo_svg_surface_create_for_stream(write, this, width, height);
            break;
        case OutputFormat::pdf:
            surface_ = cairo_pdf_surface_create_for_stream(write, this, width, height);
            cairo_pdf_surface_set_metadata(surface_, CAIRO_PDF_METADATA_CREATE_DATE,
                                           fixed_pdf_date);
            cairo_pdf_surface_set_metadata(surface_, CAIRO_PDF_METADATA_MOD_DATE, fixed_pdf_date);
            cairo_pdf_surface_set_metadata(surface_, CAIRO_PDF_METADATA_CREATOR, "Acanthus");
            if (!title.empty())
                cairo_pdf_surface_set_metadata(surface_, CAIRO_PDF_METADATA_TITLE, title.c_str());
            break;
        case OutputFormat::ps:
        case OutputFormat::eps:
            surface_ = cairo_ps_surface_create_for_stream(write, this, width, height);
            cairo_ps_surface_set_eps(surface_, format == OutputFormat::eps);
            break;
        case OutputFormat::png:
            surface_ = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height);
            break;
    }
    cr_ = cairo_create(surface_);
    if (cairo_status(cr_) != CAIRO_STATUS_SUCCESS) {
        std::string why = cairo_status_to_string(cairo_status(cr_));
        cairo_destroy(cr_);
        cairo_surface_destroy(surface_);
        throw InputError("cannot create a " + std::to_string(width) + "x" + std::to_string(height) +
                         " output page: " + why);
    }
}

OutputDocument::~OutputDocument() {
    cairo_destroy(cr_);
    cairo_surface_destroy(surface_);
}

std::string OutputDocument::finish() {
    cairo_status_t status = cairo_status(cr_);
    if (status == CAIRO_STATUS_SUCCESS) {
        if (format_ == OutputFormat::png) {
            cairo_surface_flush(surface_);
            status =
                cairo_surface_write_to_png_stream(surface_, &OutputDocumentStream::write, this);
        } else {
            cairo_surface_finish(surface_);
            status = cairo_surface_status(surface_);
        }
    }
    if (status != CAIRO_STATUS_SUCCESS || write_failed_)
        throw InputError(std::string("drawing the output failed: ") +
                         (write_failed_ ? "out of memory" : cairo_status_to_string(status)));
    switch (format_) {
        case OutputFormat::svg:
            return renumber_svg_surface_ids(bytes_);
        case OutputFormat::eps: {
            std::string box = "0 0 " + std::to_string(width_) + " " + std::to_string(height_);
            replace_dsc_comment(bytes_, "%%BoundingBox:", box);
            replace_dsc_comment(bytes_, "%%PageBoundingBox:", box);
            [[fallthrough]];
        }
        case OutputFormat::ps:
            replace_dsc_comment(bytes_, "%%CreationDate:", fixed_ps_date);
            return std::move(bytes_);
        default:
            return std::move(bytes_);
    }
}

std::string renumber_svg_surface_ids(const std::string& svg) {
    static constexpr std::string_view prefixes[] = {"\"surface", "#surface", "\"image", "#image"};
    std::map<std::string, int> numbers;  // "surface17" -> 1, in order of appearance
    std::map<std::string, int> used;     // "surface" -> numbers handed out so far
    std::string out;
    out.reserve(svg.size());
    std::size_t i = 0;
    while (i < svg.size()) {
        std::size_t matched = 0;
        if (svg[i] == '"' || svg[i] == '#')
            for (std::string_view prefix : prefixes)
                if (svg.compare(i, prefix.size(), prefix) == 0) matched = prefix.size();
        std::size_t digits = i + matched;
        while (matched && digits < svg.size() &&
               std::isdigit(static_cast<unsigned char>(svg[digits])))
            ++digits;
        if (!matched || digits == i + matched) {
            out += svg[i++];
            continue;
        }
        std::string word = svg.substr(i + 1, matched - 1);
        std::string key = word + svg.substr(i + matched, digits - i - matched);
        auto it = numbers.find(key);
        if (it == numbers.end()) it = numbers.emplace(key, ++used[word]).first;
        out += svg[i];
        out += word;
        out += std::to_string(it->second);
        i = digits;
    }
    return out;
}

void replace_dsc_comment(std::string& ps, const std::string& key, const std::string& value) {
    std::size_t at = 0;
    while ((at = ps.find(key, at)) != std::string::npos) {
        if (at == 0 || ps[at - 1] == '\n') break;
        at += key.size();
    }
    if (at == std::string::npos) return;
    std::size_t begin = at + key.size();
    std::size_t end = ps.find('\n', begin);
    if (end == std::string::npos) end = ps.size();
    ps.replace(begin, end - begin, " " + value);
}

}  // namespace acanthus::detail
