#include "driver/preview_command.hpp"

#include <unistd.h>

#include <cstdlib>
#include <iostream>

#include "server/serve.hpp"
#include "server/settings.hpp"

namespace acanthus {

namespace {

constexpr int kBadUsage = 2;
constexpr int kDefaultPort = 8765;

int usage(const std::string& message) {
    std::cerr << "acanthus: error: " << message
              << "\nUsage: acanthus preview [-I DIR]... [-O LEVEL] FILE.acr [program options] "
                 "[--port N] [--host ADDR] [--memory-limit SIZE] [--editor CMD]\n";
    return kBadUsage;
}

// A quarter of the machine's memory: the live render, two downloads and a compiler can run at
// once without one runaway body taking the machine down.
unsigned long long default_memory_limit() {
    const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
    if (pages <= 0 || page <= 0) return 0;
    return static_cast<unsigned long long>(pages) * static_cast<unsigned long long>(page) / 4;
}

// "2048" or "2048M" (MiB), "2G" (GiB), "0" (no limit) -> bytes.
bool parse_memory_limit(const std::string& value, unsigned long long& bytes) {
    std::string digits = value;
    unsigned shift = 20;
    if (!digits.empty() && (digits.back() == 'G' || digits.back() == 'g')) {
        shift = 30;
        digits.pop_back();
    } else if (!digits.empty() && (digits.back() == 'M' || digits.back() == 'm')) {
        digits.pop_back();
    }
    if (digits.empty() || digits.size() > 9 ||
        digits.find_first_not_of("0123456789") != std::string::npos)
        return false;
    const unsigned long long n = std::stoull(digits);
    if (n > 0 && (n << shift) < (64ull << 20)) return false;  // too little to start a program
    bytes = n << shift;
    return true;
}

// Takes --port, --host, --memory-limit and --editor out of `args`.
bool take_server_options(std::vector<std::string>& args, int& port, std::string& host,
                         unsigned long long& memory_limit, std::string& editor,
                         std::string& error) {
    std::vector<std::string> rest;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        std::string name = a.substr(0, a.find('=')), value;
        if (name != "--port" && name != "--host" && name != "--memory-limit" &&
            name != "--editor") {
            rest.push_back(a);
            continue;
        }
        if (a.find('=') != std::string::npos) {
            value = a.substr(a.find('=') + 1);
        } else if (i + 1 < args.size()) {
            value = args[++i];
        } else {
            error = "'" + name + "' needs a value";
            return false;
        }
        if (name == "--memory-limit") {
            if (!parse_memory_limit(value, memory_limit))
                return error = "bad --memory-limit '" + value +
                               "' (MiB, or with M or G: 2048, 512M, 2G; at least 64M; 0 for none)",
                       false;
            continue;
        }
        if (name == "--editor") {
            if (value.empty()) return error = "'--editor' needs a command", false;
            editor = value;
            continue;
        }
        if (name == "--host") {
            if (value.empty()) return error = "'--host' needs an address", false;
            host = value;
            continue;
        }
        if (value.empty() || value.size() > 5 ||
            value.find_first_not_of("0123456789") != std::string::npos || std::stoi(value) > 65535)
            return error = "bad port '" + value + "' (0 to 65535; 0 picks a free one)", false;
        port = std::stoi(value);
    }
    args = rest;
    return true;
}

}  // namespace

int run_preview(const std::string& input, const std::vector<std::string>& includes,
                const Toolchain& toolchain, const BuildOptions& build,
                const std::vector<std::string>& program_args) {
    std::vector<std::string> args = program_args;
    PreviewServerOptions server;
    server.port = kDefaultPort;
    server.memory_limit = default_memory_limit();
    const char* visual = std::getenv("VISUAL");
    server.editor = visual ? visual : "";
    std::string error;
    if (!take_server_options(args, server.port, server.host, server.memory_limit, server.editor,
                             error))
        return usage(error);
    PreviewSettings settings;
    if (!settings.take(args, error)) return usage(error);
    return serve_preview(input, includes, toolchain, build, settings, server);
}

}  // namespace acanthus
