// The render job of the preview: on each request, compile the rule file (in process), build the
// program (cached by content hash, in a child process) and run it (a child process with a
// deadline). A newer request cancels the one in progress: its compiler or program is killed.
#pragma once

#include <sys/eventfd.h>

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "code_generator.hpp"
#include "server/settings.hpp"
#include "server/status.hpp"
#include "server/stroke_tools.hpp"
#include "server/watcher.hpp"
#include "toolchain/program_build.hpp"
#include "toolchain/toolchain.hpp"

namespace acanthus {

struct PreviewConfig {
    std::string input;                  // the rule file
    std::vector<std::string> includes;  // -I
    Toolchain toolchain;
    BuildOptions build;
    std::string work_dir;                  // the server's own temporary directory
    unsigned long long memory_limit = 0;   // bytes of address space for each program run; 0: none
    std::vector<StrokeTool> stroke_tools;  // declared by the stdlib libraries
};

// A program run besides the live render: a download, frames, a debug frame.
struct ExtraRun {
    bool ok = false;
    std::string message;  // the program's messages when not ok
};

class RenderJob {
  public:
    RenderJob(PreviewConfig config, PreviewSettings settings, PreviewStatus& status);
    ~RenderJob();
    RenderJob(const RenderJob&) = delete;
    RenderJob& operator=(const RenderJob&) = delete;

    void request();  // render again (cancels a render in progress)
    void stop();

    PreviewSettings settings() const;
    void set_settings(PreviewSettings settings);  // and render again

    // The picture's room on the page in device pixels (the page's /status.json?view=WxH): the
    // PNG the page shows is drawn to fit it, from the next render on.
    void set_view_size(int width, int height);

    // The rule file and the files it imports, as the latest compile read them.
    std::vector<std::string> source_files() const;

    // Runs the program of the latest good render again with `extra` arguments (outputs).
    // With `rng_seed` set: that seed in place of the render's (a variation).
    ExtraRun run_again(const std::vector<std::string>& extra, double deadline_seconds,
                       const std::string& rng_seed = {});

  private:
    void loop();
    void render(long generation);
    CommandRunner runner(const std::string& log, bool& cancelled);
    bool prepare_host();  // false when cancelled
    // The program to run (the host and the rule library, or an executable); false on failure
    // (the status says why) or when cancelled.
    bool build(const std::string& stem, const std::string& cpp, const GeneratedUnits& units,
               std::vector<std::string>& program);
    // Compiles the units a whole build stood in for, so that the next save compiles one.
    void fill_units();
    std::string command_line(const PreviewSettings& s) const;
    // The errors of `output`, each with the source around it.
    std::vector<PreviewDiagnostic> diagnose(const std::string& output) const;

    PreviewConfig config_;
    PreviewStatus& status_;
    mutable std::mutex mutex_;
    std::condition_variable cv_;
    PreviewSettings settings_;
    long wanted_ = 1, done_ = 0;
    double requested_at_ = 0;  // when the latest render was asked for (seconds since the epoch)
    int view_width_ = 1200, view_height_ = 900;
    bool stopping_ = false;
    std::atomic<bool> cancel_{false};
    // Readable while a cancel is pending: wakes the wait for a child (ChildRun::cancel_fd).
    int cancel_event_ = eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
    void wake_cancelled();
    std::atomic<bool> stop_extras_{false};
    std::mutex runner_mutex_;  // the build's commands may run two at a time
    double build_cpu_ = 0;     // processor time of the build's commands (under runner_mutex_)
    bool prelude_failed_ = false;
    std::string host_;  // empty: not built yet, or failed
    bool host_failed_ = false;
    std::vector<std::string> units_to_fill_;  // (render thread only)
    BuildOptions fill_options_;
    std::string fill_stem_;
    std::vector<std::string> good_program_;
    std::vector<std::string> good_arguments_;
    std::vector<std::string> source_files_;
    FileWatcher watcher_;
    std::thread thread_;
};

}  // namespace acanthus
