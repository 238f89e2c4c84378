// The preview server: binds its port, renders the rule file on every save and serves the page
// until Ctrl-C or SIGTERM (docs/preview.md).
#pragma once

#include <string>
#include <vector>

#include "server/settings.hpp"
#include "toolchain/program_build.hpp"
#include "toolchain/toolchain.hpp"

namespace acanthus {

struct PreviewServerOptions {
    int port = 0;  // 0: any free port, printed
    std::string host = "127.0.0.1";
    unsigned long long memory_limit = 0;  // bytes of address space per program run; 0: none
    std::string editor;                   // opens file:line links; empty: none
};

// Exit status 1 when the rule file or the page is missing or the port cannot be taken.
int serve_preview(const std::string& input, const std::vector<std::string>& includes,
                  const Toolchain& toolchain, const BuildOptions& build,
                  const PreviewSettings& settings, const PreviewServerOptions& options);

}  // namespace acanthus
