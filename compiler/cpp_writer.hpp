// Accumulates generated C++ and knows its own line number, for #line directives back to it.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace acanthus {

// `text` as the body of a C++ string literal (quotes included).
std::string cpp_string(std::string_view text);

class CppWriter {
  public:
    CppWriter(std::string self_name, bool line_directives)
        : self_name_(std::move(self_name)), line_directives_(line_directives) {}

    CppWriter& operator<<(std::string_view text);
    CppWriter& operator<<(long value) { return *this << std::string_view(std::to_string(value)); }

    // The following lines come from `file` starting at `line`.
    void line_to(std::uint32_t line, const std::string& file);
    // The following lines are the generated file's own again.
    void line_back();

    const std::string& text() const { return out_; }
    std::string take() { return std::move(out_); }

  private:
    std::string out_;
    std::uint32_t line_ = 1;  // the line the next character goes on
    std::string self_name_;
    bool line_directives_;
};

}  // namespace acanthus
