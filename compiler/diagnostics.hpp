// GCC-style diagnostics: collected during a run, then printed sorted by location.
#pragma once

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "source_files.hpp"
#include "source_range.hpp"

namespace acanthus {

struct Note {
    SourceRange where;
    std::string message;
};

struct Diagnostic {
    std::optional<SourceRange> where;  // none: the message is about a whole file
    std::uint32_t file = 0;            // used when `where` is empty
    std::string message;
    std::vector<Note> notes;   // printed right after the error, in order
    std::size_t sequence = 0;  // report order; keeps sorting stable
};

class Diagnostics {
  public:
    explicit Diagnostics(const SourceFiles& files) : files_(files) {}

    void error(const SourceRange& where, std::string message, std::vector<Note> notes = {});
    void file_error(std::uint32_t file, std::string message);
    std::size_t error_count() const { return errors_.size(); }
    // Stops collecting beyond this many (a 50 MB file of garbage must not use gigabytes).
    bool saturated() const { return errors_.size() >= kMaxCollected; }

    // Prints every error sorted by (file, line, column), each followed by its notes.
    // Prints at most `limit` errors and says how many more there were.
    void print(std::ostream& out, std::size_t limit = 50) const;

  private:
    static constexpr std::size_t kMaxCollected = 10000;
    void print_one(std::ostream& out, const SourceRange& where, const char* severity,
                   const std::string& message) const;

    const SourceFiles& files_;
    std::vector<Diagnostic> errors_;
};

}  // namespace acanthus
