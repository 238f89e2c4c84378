#include "server/status.hpp"

#include <chrono>
#include <regex>

namespace acanthus {

namespace {

// The width and height of an SVG's root element (the page, in points), from its first bytes.
bool svg_size(const std::string& svg, double& width, double& height) {
    static const std::regex root(
        R"(<svg\b[^>]*?\bwidth="([0-9.]+)(?:pt|px)?"[^>]*?\bheight="([0-9.]+)(?:pt|px)?")");
    std::smatch m;
    const std::string head = svg.substr(0, 4096);
    if (!std::regex_search(head, m, root)) return false;
    width = std::stod(m[1]);
    height = std::stod(m[2]);
    return width > 0 && height > 0;
}

// A PNG's pixels, from its header (IHDR).
bool png_size(const std::string& png, long& width, long& height) {
    if (png.size() < 24 || png.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0 ||
        png.compare(12, 4, "IHDR") != 0)
        return false;
    const auto word = [&](std::size_t at) {
        long v = 0;
        for (std::size_t i = 0; i < 4; ++i) v = v << 8 | static_cast<unsigned char>(png[at + i]);
        return v;
    };
    width = word(16);
    height = word(20);
    return width > 0 && height > 0;
}

}  // namespace

void PreviewStatus::changed() {
    ++version_;
    cv_.notify_all();
}

void PreviewStatus::begin(const std::string& phase) {
    std::lock_guard lock(mutex_);
    state_ = "running";
    phase_ = phase;
    if (phase == "compiling") progress_iterations_ = progress_elements_ = 0, progress_seconds_ = 0;
    partial_png_.clear();
    final_ = 0;
    changed();
}

void PreviewStatus::progress(long iterations, long elements, double seconds) {
    std::lock_guard lock(mutex_);
    if (iterations == progress_iterations_ && elements == progress_elements_) return;
    progress_iterations_ = iterations;
    progress_elements_ = elements;
    progress_seconds_ = seconds;
    changed();
}

void PreviewStatus::set_partial(std::string png, bool final) {
    std::lock_guard lock(mutex_);
    if (final)
        timeline_.push_back(json::array({"final", now_epoch()}));
    else if (timeline_.size() < 48)
        timeline_.push_back(json::array({"partial", now_epoch()}));
    partial_png_ = std::move(png);
    ++partial_;
    if (final) final_ = partial_;
    changed();
}

void PreviewStatus::set_params(std::vector<ParamSummary> params) {
    std::lock_guard lock(mutex_);
    params_ = std::move(params);
}

void PreviewStatus::set_stroke_tools(std::vector<StrokeTool> tools) {
    std::lock_guard lock(mutex_);
    stroke_tools_ = std::move(tools);
}

std::vector<StrokeTool> PreviewStatus::stroke_tools() const {
    std::lock_guard lock(mutex_);
    return stroke_tools_;
}

void PreviewStatus::set_timing(const std::string& phase, double seconds) {
    std::lock_guard lock(mutex_);
    if (phase == "compile") timings_ = json::object();
    timings_[phase] = seconds;
}

double PreviewStatus::now_epoch() {
    return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch())
        .count();
}

void PreviewStatus::start_timeline(const std::string& step, double at) {
    std::lock_guard lock(mutex_);
    timeline_ = json::array({json::array({step, at})});
}

void PreviewStatus::step(const std::string& step) { step_at(step, now_epoch()); }

void PreviewStatus::step_at(const std::string& step, double at) {
    std::lock_guard lock(mutex_);
    if (timeline_.size() < 64) timeline_.push_back(json::array({step, at}));
}

void PreviewStatus::set_compiling_units(bool compiling) {
    std::lock_guard lock(mutex_);
    if (compiling_units_ == compiling) return;
    compiling_units_ = compiling;
    changed();
}

void PreviewStatus::set_command(std::string command) {
    std::lock_guard lock(mutex_);
    command_ = std::move(command);
}

void PreviewStatus::succeed(std::string svg, std::string png, const json& metrics, double seconds,
                            const std::string& note) {
    std::lock_guard lock(mutex_);
    ++revision_;
    state_ = "ok";
    phase_ = note.empty() ? "done" : note;
    error_kind_.clear();
    output_ = note.empty() ? "" : note + "\n";
    diagnostics_.clear();
    svg_ = std::move(svg);
    view_png_ = std::move(png);
    // The page shows the PNG at the SVG's page size (its strokes and seeds are in its units).
    double width = 0, height = 0;
    long png_width = 0, png_height = 0;
    picture_ = json::object();
    if (svg_size(svg_, width, height)) picture_ = {{"width", width}, {"height", height}};
    if (png_size(view_png_, png_width, png_height)) picture_["png"] = {png_width, png_height};
    // Kept beside: a render that draws the same as the one before is not kept twice.
    if (kept_.empty() || kept_.back().svg != svg_) kept_.push_back({revision_, svg_, view_png_});
    while (kept_.size() > kKeptRevisions) kept_.pop_front();
    partial_png_.clear();
    timeline_.push_back(json::array({"published", now_epoch()}));
    metrics_ = metrics;
    elements_ = metrics.value("elements", 0L);
    seconds_ = seconds;
    changed();
}

void PreviewStatus::fail(const std::string& kind, const std::string& output,
                         std::vector<PreviewDiagnostic> diagnostics, double seconds) {
    std::lock_guard lock(mutex_);
    ++revision_;
    state_ = "error";
    phase_ = "done";
    error_kind_ = kind;
    output_ = output;
    diagnostics_ = std::move(diagnostics);
    partial_png_.clear();
    final_ = 0;
    seconds_ = seconds;
    changed();
}

PreviewStatus::json PreviewStatus::to_json() const {
    std::lock_guard lock(mutex_);
    json diagnostics = json::array();
    for (const PreviewDiagnostic& d : diagnostics_) {
        json entry = {
            {"file", d.file}, {"line", d.line}, {"column", d.column}, {"message", d.message}};
        if (!d.context.empty())
            entry["source"] = {{"first", d.context_first}, {"lines", d.context}};
        diagnostics.push_back(entry);
    }
    json params = json::array();
    for (const ParamSummary& p : params_) {
        json entry = {{"name", p.name}, {"type", p.type}, {"default", p.default_text}};
        if (!p.low.empty()) entry["range"] = {p.low, p.high};
        params.push_back(entry);
    }
    json tools = json::array();
    for (const StrokeTool& t : stroke_tools_) tools.push_back(t.to_json());
    json kept = json::array();
    for (const Kept& entry : kept_) kept.push_back(entry.revision);
    return {{"revision", revision_},
            {"state", state_},
            {"phase", phase_},
            {"elements", elements_},
            {"seconds", seconds_},
            {"diagnostics", diagnostics},
            {"error_kind", error_kind_},
            {"output", output_},
            {"params", params},
            {"stroke_tools", tools},
            {"metrics", metrics_},
            {"command", command_},
            {"timings", timings_},
            {"timeline", timeline_},
            {"progress",
             {{"iterations", progress_iterations_},
              {"elements", progress_elements_},
              {"seconds", progress_seconds_}}},
            {"revisions", kept},
            // The number of the partial picture /partial.png has now; 0 when it has none.
            {"partial", partial_png_.empty() ? 0 : partial_},
            // The partial picture that is the finished one (while it grows, and in the render
            // it became): a page showing it has the render's picture already.
            {"final", final_},
            {"compiling_units", compiling_units_},
            {"picture", picture_},
            {"version", version_}};
}

std::string PreviewStatus::svg() const {
    std::lock_guard lock(mutex_);
    return svg_;
}

std::string PreviewStatus::revision_svg(long revision) const {
    std::lock_guard lock(mutex_);
    for (const Kept& entry : kept_)
        if (entry.revision == revision) return entry.svg;
    return {};
}

std::string PreviewStatus::revision_png(long revision) const {
    std::lock_guard lock(mutex_);
    for (const Kept& entry : kept_)
        if (entry.revision == revision) return entry.png;
    return {};
}

std::string PreviewStatus::view_png() const {
    std::lock_guard lock(mutex_);
    return view_png_;
}

std::string PreviewStatus::partial_png() const {
    std::lock_guard lock(mutex_);
    return partial_png_;
}

long PreviewStatus::revision() const {
    std::lock_guard lock(mutex_);
    return revision_;
}

long PreviewStatus::version() const {
    std::lock_guard lock(mutex_);
    return version_;
}

long PreviewStatus::wait_for_change(long seen, int timeout_ms) const {
    std::unique_lock lock(mutex_);
    cv_.wait_for(lock, std::chrono::milliseconds(timeout_ms), [&] { return version_ != seen; });
    return version_;
}

void PreviewStatus::wake_all() {
    std::lock_guard lock(mutex_);
    cv_.notify_all();
}

}  // namespace acanthus
