// The preview server's routes: the page and its assets, /status.json, /render.svg and the
// downloads, /events (server-sent events), the panels, the page's controls (POST). Nothing else
// is served: every path is a fixed route, so no request names a file of its own choosing.
#pragma once

#include <atomic>
#include <string>
#include <vector>

namespace httplib {
class Server;
}

namespace acanthus {

class RenderJob;
class PreviewStatus;

struct PreviewSite {
    RenderJob& job;
    PreviewStatus& status;
    std::string assets_dir;           // preview/: index.html, preview.js, preview.css
    std::string panels_dir;           // examples/panels/
    std::vector<std::string> panels;  // the *.svg names in panels_dir, read once at start
    std::string work_dir;             // the server's temporary directory
    std::string file;                 // the rule file, as given
    std::string stem;                 // the rule file's stem: names downloads
    std::string listen_host;          // --host: a name requests may use besides an address
    std::string guides_file;          // beside the rule file: NAME.guides.svg
    std::string editor;               // --editor, else $VISUAL; empty: none
    const std::atomic<bool>& stopping;
};

// Largest request body accepted (an uploaded panel, guide strokes).
constexpr std::size_t kMaxRequestBody = 4u << 20;

void add_routes(httplib::Server& server, PreviewSite& site);

}  // namespace acanthus
