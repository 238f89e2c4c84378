// An output written piece by piece (the structured SVG), still published atomically: a hidden
// temporary file next to the target, renamed over it by commit() (or with the run's other
// outputs while an OutputTransaction is open). "-" streams to standard output.
#pragma once

#include <cstdio>
#include <string>
#include <string_view>

namespace acanthus::detail {

class OutputStream {
  public:
    // Creates the temporary file; throws InputError if it cannot.
    explicit OutputStream(const std::string& path);
    // Without commit(): removes the temporary file, leaving the target as it was.
    ~OutputStream();
    OutputStream(const OutputStream&) = delete;
    OutputStream& operator=(const OutputStream&) = delete;

    // Throws InputError on a write error.
    void write(std::string_view bytes);
    // Flushes and publishes the file. Throws InputError on failure (nothing is left behind).
    void commit();

  private:
    [[noreturn]] void fail(int error);

    std::string path_, temporary_;
    std::FILE* file_ = nullptr;
    bool in_transaction_ = false, committed_ = false;
};

}  // namespace acanthus::detail
