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
            // The program names the rule file and line of a failing rule: `x.acr:31: rule ...`.
            static const std::regex rule(R"(^(.+?\.acr):(\d+): (.*)$)");
            std::smatch r;
            const std::string message = m[2];
            if (std::regex_match(message, r, rule))
                out.push_back({r[1], std::stoi(r[2]), 0, r[3]});
            else
                out.push_back({m[1], 0, 0, message});
        }
    }
    return out;
}

}  // namespace acanthus
