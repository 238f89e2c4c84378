// One page of output in any of the formats, drawn through a Cairo context and kept in memory.
#pragma once

#include <acanthus/render.hpp>
#include <string>

typedef struct _cairo_surface cairo_surface_t;

namespace acanthus::detail {

// Creates the Cairo surface for `format` (page `width` x `height` in points, or pixels for PNG)
// writing into memory. finish() returns the complete file, made byte-reproducible: fixed PDF and
// PostScript dates, SVG surface ids numbered per document, the EPS bounding box set to the page.
class OutputDocument {
  public:
    OutputDocument(OutputFormat format, int width, int height, const std::string& title);
    ~OutputDocument();
    OutputDocument(const OutputDocument&) = delete;
    OutputDocument& operator=(const OutputDocument&) = delete;

    cairo_t* context() { return cr_; }
    // Ends drawing and returns the file's bytes. Throws InputError if Cairo reports an error.
    std::string finish();

  private:
    OutputFormat format_;
    int width_, height_;
    std::string bytes_;
    bool write_failed_ = false;
    cairo_surface_t* surface_ = nullptr;
    cairo_t* cr_ = nullptr;

    friend struct OutputDocumentStream;
};

// Cairo's SVG surface names groups after process-wide surface counters; renumber them in order
// of appearance so the same drawing gives the same bytes however many documents came before.
std::string renumber_svg_surface_ids(const std::string& svg);
// Replaces the value of the DSC comment `key` (e.g. "%%CreationDate:") on its first line.
void replace_dsc_comment(std::string& ps, const std::string& key, const std::string& value);

}  // namespace acanthus::detail
