// What the preview page and scripts see: the state of the latest render, its diagnostics,
// metrics and parameters, the latest good SVG and its PNG at the page's size. Every change bumps a
// version that /events waits on.
#pragma once

#include <condition_variable>
#include <deque>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "compilation.hpp"
#include "server/diagnostics.hpp"
#include "server/stroke_tools.hpp"

namespace acanthus {

class PreviewStatus {
  public:
    using json = nlohmann::json;

    // A render began: compiling, then building, then growing.
    void begin(const std::string& phase);
    void progress(long iterations, long elements, double seconds);
    // A picture of the growth so far (the program's --partial, PNG), while it grows; `final`:
    // the finished picture (the program's --view, published before its run ends), which the
    // render's revision shows if the run ends well.
    void set_partial(std::string png, bool final = false);
    void set_params(std::vector<ParamSummary> params);
    // The stroke tools of the libraries the program imports (the page offers them).
    void set_stroke_tools(std::vector<StrokeTool> tools);
    std::vector<StrokeTool> stroke_tools() const;
    void set_command(std::string command);
    // Whether the units of the last build are being compiled after its picture (for the next
    // saves; a save stops it).
    void set_compiling_units(bool compiling);
    // Seconds one phase of the current render took (compile, build, grow): where time goes.
    void set_timing(const std::string& phase, double seconds);
    // The wall-clock steps of the current render (seconds since the epoch, so that a client can
    // set them beside its own clock): where a save waits. `start` begins a new timeline at `at`
    // (the save seen); `step` adds one at now, `step_at` at a time of the caller's.
    void start_timeline(const std::string& step, double at);
    void step(const std::string& step);
    void step_at(const std::string& step, double at);
    static double now_epoch();
    // A render finished well: the picture, as SVG and as the PNG the page shows (the program's
    // --view), and the program's --metrics.
    void succeed(std::string svg, std::string png, const json& metrics, double seconds,
                 const std::string& note = {});
    // A render failed: compiler output (with diagnostics) or the program's error.
    void fail(const std::string& kind, const std::string& output,
              std::vector<PreviewDiagnostic> diagnostics, double seconds);

    json to_json() const;
    std::string svg() const;
    std::string view_png() const;     // the latest good render at the page's size (PNG)
    std::string partial_png() const;  // empty when the render in progress has drawn none
    // An earlier good render still kept (the latest kKeptRevisions), or empty.
    std::string revision_svg(long revision) const;
    std::string revision_png(long revision) const;  // its PNG at the page's size
    static constexpr std::size_t kKeptRevisions = 8;
    long revision() const;
    // Waits until the version passes `seen` or `timeout_ms` ran out; returns the version.
    long wait_for_change(long seen, int timeout_ms) const;
    long version() const;
    void wake_all();

  private:
    void changed();  // holds mutex_

    mutable std::mutex mutex_;
    mutable std::condition_variable cv_;
    long version_ = 0;
    long revision_ = 0;
    std::string state_ = "running";
    std::string phase_ = "starting";
    std::string error_kind_;
    std::string output_;  // the compiler's or program's messages, exactly as printed
    std::vector<PreviewDiagnostic> diagnostics_;
    std::vector<ParamSummary> params_;
    std::vector<StrokeTool> stroke_tools_;
    json metrics_ = json::object();
    std::string svg_;
    std::string view_png_;
    json picture_ =
        json::object();  // the SVG's page and the PNG's pixels: {"width", "height", "png"}
    std::string partial_png_;
    struct Kept {
        long revision;
        std::string svg, png;
    };
    std::deque<Kept> kept_;  // good renders, oldest first
    long partial_ = 0;       // how many partial pictures the server has had, ever
    long final_ = 0;         // the number of the one that is the finished picture, or 0
    std::string command_;
    bool compiling_units_ = false;
    json timings_ = json::object();
    json timeline_ = json::array();  // [[step, seconds since the epoch], ...]
    long elements_ = 0;
    double seconds_ = 0;
    long progress_iterations_ = 0, progress_elements_ = 0;
    double progress_seconds_ = 0;
};

}  // namespace acanthus
