#include "server/serve.hpp"

#include <httplib.h>
#include <pthread.h>
#include <stdlib.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <thread>

#include "server/limits.hpp"
#include "server/render_job.hpp"
#include "server/routes.hpp"
#include "server/status.hpp"
#include "server/stroke_tools.hpp"

namespace acanthus {

namespace fs = std::filesystem;

namespace {

constexpr int kBadInput = 1;
constexpr std::size_t kKeptIdleThreads = 8;  // a browser keeps about six connections open

bool on_path(const std::string& program) {
    const char* path = std::getenv("PATH");
    std::string dirs = path ? path : "/usr/bin:/bin";
    std::size_t start = 0;
    while (start <= dirs.size()) {
        std::size_t end = dirs.find(':', start);
        if (end == std::string::npos) end = dirs.size();
        const fs::path candidate = fs::path(dirs.substr(start, end - start)) / program;
        if (access(candidate.c_str(), X_OK) == 0) return true;
        start = end + 1;
    }
    return false;
}

std::vector<std::string> list_panels(const std::string& dir) {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
        const std::string name = entry.path().filename().string();
        if (entry.is_regular_file() && entry.path().extension() == ".svg" && name.size() <= 64 &&
            name.find_first_not_of(
                "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_.-") ==
                std::string::npos)
            names.push_back(name);
    }
    std::sort(names.begin(), names.end());
    return names;
}

}  // namespace

int serve_preview(const std::string& input, const std::vector<std::string>& includes,
                  const Toolchain& toolchain, const BuildOptions& build,
                  const PreviewSettings& settings, const PreviewServerOptions& options) {
    const int port = options.port;
    const std::string& host = options.host;
    const unsigned long long memory_limit = options.memory_limit;
    const std::string& editor = options.editor;
    std::error_code ec;
    if (!fs::is_regular_file(input, ec)) {
        std::cerr << "acanthus: error: cannot read '" << input << "': not a regular file\n";
        return kBadInput;
    }
    if (!fs::is_regular_file(fs::path(toolchain.preview_dir) / "index.html", ec)) {
        std::cerr << "acanthus: error: the preview page is missing from '" << toolchain.preview_dir
                  << "'\n";
        return kBadInput;
    }
    std::vector<StrokeTool> stroke_tools;
    std::string error;
    if (!parse_stroke_tools(toolchain.preview_strokes, stroke_tools, error)) {
        std::cerr << "acanthus: error: " << error << " (the stdlib's registration)\n";
        return kBadInput;
    }
    std::string work = (fs::temp_directory_path(ec) / "acanthus-preview.XXXXXX").string();
    if (!mkdtemp(work.data())) {
        std::cerr << "acanthus: error: cannot create a temporary directory\n";
        return kBadInput;
    }

    // Ctrl-C and SIGTERM are taken by one thread (sigwait); every other thread, and so the
    // server's, runs with them blocked. Children get them back (server/child.cpp).
    sigset_t stop_signals;
    sigemptyset(&stop_signals);
    sigaddset(&stop_signals, SIGINT);
    sigaddset(&stop_signals, SIGTERM);
    sigaddset(&stop_signals, SIGHUP);
    pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);
    std::signal(SIGPIPE, SIG_IGN);

    // Unless a compiler was chosen: clang++ builds rule code (at -O0, with a precompiled
    // prelude) in about two thirds of g++'s time, and lld links in about half of ld's
    // (bench/preview.sh). Both use the same libstdc++ as the runtime.
    BuildOptions fast = build;
    const bool chosen = !fast.cxx.empty() || std::getenv("CXX");
    // (Not for a sanitized runtime: its sanitizer runtime is g++'s.)
    if (!chosen && toolchain.sanitize_flags.empty() && on_path("clang++")) {
        fast.cxx = "clang++";
        // The compiler proper in the driver's process, not a second one started for it: 7% less
        // processor time for a rule file's code, one process fewer to wait for on a busy
        // machine (docs/performance-log.md, 2026-11-26).
        fast.extra_flags.push_back("-fintegrated-cc1");
    }
    // gold, else lld: started directly (below), gold links rule code against the C++ library
    // in about 35 ms of processor time, lld in 45 (it loads LLVM), ld in 150.
    if (!chosen && on_path("ld.gold"))
        fast.extra_flags.push_back("-fuse-ld=gold");
    else if (!chosen && on_path("ld.lld"))
        fast.extra_flags.push_back("-fuse-ld=lld");
    // The rule code compiled to an object, then linked by the linker itself: one compiler
    // process (clang runs its compiler in the driver's process only when there is no link
    // step), and no driver started for the link (50 ms of processor time per save).
    {
        BuildOptions shared = fast;
        shared.shared_library = true;
        std::string ignored;
        direct_link_command(toolchain, shared, fast.link_command, ignored);
    }

    // A save that changes several units (the tables' and a rule's when lines moved) compiles
    // them at once, on two cores.
    fast.jobs = std::thread::hardware_concurrency() > 1 ? 2 : 1;
    // The %draw bodies run for every picture (the partial ones, the view, the SVG): their unit
    // is compiled optimised, after the picture of the save that changed it. Spiral's pictures
    // took 0.84 s at -O0 and 0.39 to 0.50 s at -O2 (docs/performance-log.md, 2026-11-28).
    if (fast.optimization == "0") fast.code_unit_optimization = "2";

    int code = 0;
    {
        PreviewStatus status;
        PreviewConfig config{input, includes, toolchain, fast, work, memory_limit, stroke_tools};
        std::atomic<bool> stopping{false};
        httplib::Server server;
        server.set_payload_max_length(kMaxRequestBody);
        server.new_task_queue = [] {
            return new ConnectionThreads(kMaxConnectionThreads, kKeptIdleThreads);
        };
        // A client that sends half a request, or stops reading, is dropped after 5 s without
        // progress; an idle keep-alive connection after 5 s.
        server.set_read_timeout(5);
        server.set_write_timeout(5);
        server.set_keep_alive_timeout(5);
        // The library's default sets SO_REUSEPORT, with which a second preview on the same
        // port shares it silently (requests split between two rule files). SO_REUSEADDR only
        // lets a stopped preview's port be taken again at once.
        socket_t listening = -1;
        server.set_socket_options([&listening](socket_t sock) {
            int yes = 1;
            setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
            listening = sock;  // the last one given is the one bound
        });
        // Bound before anything is compiled: a port in use costs nothing.
        errno = 0;
        const int bound = port == 0 ? server.bind_to_any_port(host)
                                    : (server.bind_to_port(host, port) ? port : -1);
        if (bound < 0) {
            const int why = errno;
            std::cerr << "acanthus: error: cannot listen on " << host << ":" << port << ": "
                      << (why == EADDRINUSE ? "the port is in use (another acanthus preview?)"
                          : why != 0        ? std::strerror(why)
                                            : "cannot bind")
                      << "; --port N takes another port, --port 0 any free one\n";
            code = kBadInput;
        } else {
            // The library listens with a backlog of 5: a page opening its connections while
            // a few others connect found the queue full, and its connection waited for a
            // retransmission (1 s). Listening again only makes the queue longer.
            if (listening >= 0) ::listen(listening, SOMAXCONN);
            RenderJob job(config, settings, status);
            const std::string stem = fs::path(input).stem().string();
            PreviewSite site{job,
                             status,
                             toolchain.preview_dir,
                             toolchain.panels_dir,
                             list_panels(toolchain.panels_dir),
                             work,
                             input,
                             stem,
                             host,
                             (fs::path(input).parent_path() / (stem + ".guides.svg")).string(),
                             editor,
                             stopping};
            add_routes(server, site);
            std::thread signals([&] {
                timespec tick{0, 200'000'000};
                while (!stopping) {
                    if (sigtimedwait(&stop_signals, nullptr, &tick) > 0) break;
                }
                stopping = true;
                status.wake_all();
                server.stop();
            });
            const std::string shown = host.find(':') != std::string::npos ? "[" + host + "]" : host;
            std::cout << "acanthus preview: " << input << " at http://" << shown << ":" << bound
                      << "/  (Ctrl-C stops)" << std::endl;
            server.listen_after_bind();
            stopping = true;
            status.wake_all();
            signals.join();
            job.stop();
            std::cout << "acanthus preview: stopped" << std::endl;
        }
    }
    fs::remove_all(work, ec);
    return code;
}

}  // namespace acanthus
