#include "cpp_writer.hpp"

#include <algorithm>

namespace acanthus {

std::string cpp_string(std::string_view text) {
    std::string out = "\"";
    for (char c : text) {
        unsigned char u = static_cast<unsigned char>(c);
        switch (c) {
            case '"':
                out += "\\\"";
                break;
            case '\\':
                out += "\\\\";
                break;
            case '\n':
                out += "\\n";
                break;
            case '\t':
                out += "\\t";
                break;
            default:
                if (u < 0x20 || u == 0x7f) {
                    static const char octal[] = "01234567";
                    out += '\\';
                    out += octal[(u >> 6) & 7];
                    out += octal[(u >> 3) & 7];
                    out += octal[u & 7];
                } else {
                    out += c;
                }
        }
    }
    out += '"';
    return out;
}

CppWriter& CppWriter::operator<<(std::string_view text) {
    out_.append(text);
    line_ += static_cast<std::uint32_t>(std::count(text.begin(), text.end(), '\n'));
    return *this;
}

void CppWriter::line_to(std::uint32_t line, const std::string& file) {
    if (!line_directives_) return;
    if (!out_.empty() && out_.back() != '\n') *this << "\n";
    *this << "#line " << static_cast<long>(line) << " " << cpp_string(file) << "\n";
}

void CppWriter::line_back() {
    if (!line_directives_) return;
    if (!out_.empty() && out_.back() != '\n') *this << "\n";
    // The directive names the line after itself.
    *this << "#line " << static_cast<long>(line_ + 1) << " " << cpp_string(self_name_) << "\n";
}

}  // namespace acanthus
