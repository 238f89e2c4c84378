// One page of output in any of the formats, drawn through a Cairo context.
#pragma once

#include <acanthus/render.hpp>
#include <memory>
#include <string>

#include "output/dsc_rewriter.hpp"

typedef struct _cairo_surface cairo_surface_t;

namespace acanthus::detail {

class OutputStream;

// Creates the Cairo surface for `format` (page `width` x `height` in points, or pixels for PNG),
// made byte-reproducible: fixed PDF and PostScript dates, SVG surface ids numbered per document,
// the EPS bounding box set to the page.
class OutputDocument {
  public:
    // Kept in memory: finish() returns the complete file.
    OutputDocument(OutputFormat format, int width, int height, const std::string& title);
    // Written into `out` as Cairo produces it (PDF, PostScript and EPS while the page is
    // replayed, PNG at the end; SVG at the end, its ids renumbered over the whole document), so
    // no copy of the file is held in memory. finish() returns an empty string; the caller
    // commits `out`.
    OutputDocument(OutputFormat format, int width, int height, const std::string& title,
                   OutputStream& out);
    ~OutputDocument();
    OutputDocument(const OutputDocument&) = delete;
    OutputDocument& operator=(const OutputDocument&) = delete;

    cairo_t* context() { return cr_; }
    // PNG: written with its pixels stored, not deflated.
    void store_png_uncompressed() { stored_png_ = true; }
    // Ends drawing. Throws InputError if Cairo or the output reports an error.
    std::string finish();

  private:
    void create(const std::string& title);
    void emit(std::string_view bytes);

    OutputFormat format_;
    int width_, height_;
    OutputStream* out_ = nullptr;
    std::unique_ptr<DscRewriter> dsc_;  // PS and EPS: the header's dates and boxes
    std::string bytes_;
    std::string write_error_;
    bool stored_png_ = false;
    cairo_surface_t* surface_ = nullptr;
    cairo_t* cr_ = nullptr;

    friend struct OutputDocumentStream;
};

// Cairo's SVG surface names groups after process-wide surface counters; renumber them in order
// of appearance so the same drawing gives the same bytes however many documents came before.
std::string renumber_svg_surface_ids(const std::string& svg);

}  // namespace acanthus::detail
