// Cairo surfaces for SVG, PDF, PS, EPS and PNG, written to memory or a file, made reproducible.
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
#include <utility>
#include <vector>

#include "output/output_stream.hpp"
#include "output/uncompressed_png.hpp"

namespace acanthus::detail {

namespace {

// Every output claims the same creation date so that a re-render is byte-identical.
constexpr const char* fixed_pdf_date = "2000-01-01T00:00:00Z";
constexpr const char* fixed_ps_date = "Sat Jan  1 00:00:00 2000";

}  // namespace

struct OutputDocumentStream {
    static cairo_status_t write(void* closure, const unsigned char* data, unsigned int length) {
        auto* doc = static_cast<OutputDocument*>(closure);
        if (!doc->write_error_.empty()) return CAIRO_STATUS_WRITE_ERROR;
        try {
            const std::string_view bytes(reinterpret_cast<const char*>(data), length);
            if (doc->dsc_)
                doc->dsc_->write(bytes);
            else
                doc->emit(bytes);
            return CAIRO_STATUS_SUCCESS;
        } catch (const InputError& e) {
            doc->write_error_ = e.what();
        } catch (const std::bad_alloc&) {
            doc->write_error_ = "drawing the output failed: out of memory";
        }
        return CAIRO_STATUS_WRITE_ERROR;
    }
};

OutputDocument::OutputDocument(OutputFormat format, int width, int height, const std::string& title)
    : format_(format), width_(width), height_(height) {
    create(title);
}

OutputDocument::OutputDocument(OutputFormat format, int width, int height, const std::string& title,
                               OutputStream& out)
    : format_(format), width_(width), height_(height), out_(&out) {
    create(title);
}

void OutputDocument::emit(std::string_view bytes) {
    if (out_ && format_ != OutputFormat::svg)
        out_->write(bytes);
    else
        bytes_.append(bytes);
}

void OutputDocument::create(const std::string& title) {
    auto write = &OutputDocumentStream::write;
    const int width = width_, height = height_;
    if (format_ == OutputFormat::ps || format_ == OutputFormat::eps) {
        std::vector<std::pair<std::string, std::string>> fixes{{"%%CreationDate:", fixed_ps_date}};
        if (format_ == OutputFormat::eps) {
            const std::string box = "0 0 " + std::to_string(width) + " " + std::to_string(height);
            fixes.emplace_back("%%BoundingBox:", box);
            fixes.emplace_back("%%PageBoundingBox:", box);
        }
        dsc_ = std::make_unique<DscRewriter>(std::move(fixes),
                                             [this](std::string_view bytes) { emit(bytes); });
    }
    switch (format_) {
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
            cairo_ps_surface_set_eps(surface_, format_ == OutputFormat::eps);
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
    // Cairo finishes an unfinished surface when it is destroyed: after an error, write nothing.
    if (write_error_.empty()) write_error_ = "abandoned";
    cairo_destroy(cr_);
    cairo_surface_destroy(surface_);
}

std::string OutputDocument::finish() {
    cairo_status_t status = cairo_status(cr_);
    if (status == CAIRO_STATUS_SUCCESS) {
        if (format_ == OutputFormat::png) {
            cairo_surface_flush(surface_);
            if (stored_png_)
                emit(uncompressed_png(surface_));
            else
                status =
                    cairo_surface_write_to_png_stream(surface_, &OutputDocumentStream::write, this);
        } else {
            cairo_surface_finish(surface_);
            status = cairo_surface_status(surface_);
        }
    }
    if (!write_error_.empty()) throw InputError(write_error_);
    if (status != CAIRO_STATUS_SUCCESS)
        throw InputError(std::string("drawing the output failed: ") +
                         cairo_status_to_string(status));
    if (dsc_) dsc_->finish();
    if (format_ == OutputFormat::svg) {
        std::string svg = renumber_svg_surface_ids(bytes_);
        if (!out_) return svg;
        out_->write(svg);
        return {};
    }
    return std::move(bytes_);
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

}  // namespace acanthus::detail
