#include "driver/preview_diagnostics.hpp"

#include <regex>
#include <sstream>

namespace acanthus {

std::vector<PreviewDiagnostic> parse_diagnostics(const std::string& output) {
    static const std::regex located(R"(^(.+?):(\d+):(\d+): (?:fatal )?error: (.*)$)");
    static const std::regex unlocated(R"(^([^ :][^:]*): (?:fatal )?error: (.*)$)");
    std::vector<PreviewDiagnostic> out;
    std::istringstream in(output);
    std::string line;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::smatch m;
        if (std::regex_match(line, m, located)) {
            try {
                out.push_back({m[1], std::stoi(m[2]), std::stoi(m[3]), m[4]});
            } catch (const std::exception&) {
                out.push_back({m[1], 0, 0, m[4]});
            }
        } else if (std::regex_match(line, m, unlocated)) {
            out.push_back({m[1], 0, 0, m[2]});
        }
    }
    return out;
}

}  // namespace acanthus
