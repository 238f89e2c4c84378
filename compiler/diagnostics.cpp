#include "diagnostics.hpp"

#include <algorithm>
#include <ostream>
#include <tuple>

namespace acanthus {

namespace {

// Longest source line echoed; keeps output readable for minified or binary input.
constexpr std::size_t kMaxEcho = 512;

std::string printable(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        unsigned char u = static_cast<unsigned char>(c);
        out += (u < 0x20 && c != '\t') || u == 0x7f ? ' ' : c;
    }
    return out;
}

}  // namespace

void Diagnostics::error(const SourceRange& where, std::string message, std::vector<Note> notes) {
    if (saturated()) return;
    Diagnostic d;
    d.where = where;
    d.file = where.begin.file;
    d.message = std::move(message);
    d.notes = std::move(notes);
    d.sequence = errors_.size();
    errors_.push_back(std::move(d));
}

void Diagnostics::file_error(std::uint32_t file, std::string message) {
    if (saturated()) return;
    Diagnostic d;
    d.file = file;
    d.message = std::move(message);
    d.sequence = errors_.size();
    errors_.push_back(std::move(d));
}

void Diagnostics::print_one(std::ostream& out, const SourceRange& where, const char* severity,
                            const std::string& message) const {
    const SourceFile& file = files_[where.begin.file];
    out << file.path() << ':' << where.begin.line << ':' << where.begin.column << ": " << severity
        << ": " << message << '\n';
    std::string_view line = file.line_text(where.begin.line);
    if (line.size() > kMaxEcho) line = line.substr(0, kMaxEcho);
    std::string gutter = std::to_string(where.begin.line);
    if (gutter.size() < 5) gutter.insert(0, 5 - gutter.size(), ' ');
    out << gutter << " | " << printable(line) << '\n';
    std::string margin(gutter.size(), ' ');
    std::size_t column = where.begin.column - 1;
    if (column > line.size()) column = line.size();
    std::string caret;
    for (std::size_t i = 0; i < column; ++i) caret += line[i] == '\t' ? '\t' : ' ';
    caret += '^';
    // Underline the rest of the range while it stays on this line.
    std::size_t last = where.end.line == where.begin.line ? where.end.column - 1 : column + 1;
    last = std::min(last, line.size());
    for (std::size_t i = column + 1; i < last; ++i) caret += '~';
    out << margin << " | " << caret << '\n';
}

void Diagnostics::print(std::ostream& out, std::size_t limit) const {
    std::vector<const Diagnostic*> sorted;
    for (const Diagnostic& d : errors_) sorted.push_back(&d);
    auto key = [](const Diagnostic* d) {
        std::uint32_t line = d->where ? d->where->begin.line : 0;
        std::uint32_t column = d->where ? d->where->begin.column : 0;
        return std::make_tuple(d->file, line, column, d->sequence);
    };
    std::sort(sorted.begin(), sorted.end(),
              [&](const Diagnostic* a, const Diagnostic* b) { return key(a) < key(b); });
    std::size_t shown = 0;
    for (const Diagnostic* d : sorted) {
        if (shown == limit) break;
        ++shown;
        if (d->where) {
            print_one(out, *d->where, "error", d->message);
        } else {
            out << files_[d->file].path() << ": error: " << d->message << '\n';
        }
        for (const Note& n : d->notes) print_one(out, n.where, "note", n.message);
    }
    if (sorted.size() > shown) {
        out << "acanthus: " << sorted.size() - shown << " more error"
            << (sorted.size() - shown == 1 ? "" : "s") << " not shown";
        if (saturated()) out << " (stopped counting at " << kMaxCollected << ")";
        out << '\n';
    }
}

}  // namespace acanthus
