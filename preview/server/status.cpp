#include "server/status.hpp"

#include <chrono>

namespace acanthus {

void PreviewStatus::changed() {
    ++version_;
    cv_.notify_all();
}

void PreviewStatus::begin(const std::string& phase) {
    std::lock_guard lock(mutex_);
    state_ = "running";
    phase_ = phase;
    if (phase == "compiling") progress_iterations_ = progress_elements_ = 0, progress_seconds_ = 0;
    partial_svg_.clear();
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

void PreviewStatus::set_partial(std::string svg) {
    std::lock_guard lock(mutex_);
    partial_svg_ = std::move(svg);
    ++partial_;
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

void PreviewStatus::set_command(std::string command) {
    std::lock_guard lock(mutex_);
    command_ = std::move(command);
}

void PreviewStatus::succeed(std::string svg, const json& metrics, double seconds,
                            const std::string& note) {
    std::lock_guard lock(mutex_);
    ++revision_;
    state_ = "ok";
    phase_ = note.empty() ? "done" : note;
    error_kind_.clear();
    output_ = note.empty() ? "" : note + "\n";
    diagnostics_.clear();
    svg_ = std::move(svg);
    // Kept beside: a render that draws the same as the one before is not kept twice.
    if (kept_.empty() || kept_.back().second != svg_) kept_.emplace_back(revision_, svg_);
    while (kept_.size() > kKeptRevisions) kept_.pop_front();
    partial_svg_.clear();
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
    partial_svg_.clear();
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
    for (const auto& entry : kept_) kept.push_back(entry.first);
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
            {"progress",
             {{"iterations", progress_iterations_},
              {"elements", progress_elements_},
              {"seconds", progress_seconds_}}},
            {"revisions", kept},
            // The number of the partial picture /partial.svg has now; 0 when it has none.
            {"partial", partial_svg_.empty() ? 0 : partial_},
            {"version", version_}};
}

std::string PreviewStatus::svg() const {
    std::lock_guard lock(mutex_);
    return svg_;
}

std::string PreviewStatus::revision_svg(long revision) const {
    std::lock_guard lock(mutex_);
    for (const auto& [n, svg] : kept_)
        if (n == revision) return svg;
    return {};
}

std::string PreviewStatus::partial_svg() const {
    std::lock_guard lock(mutex_);
    return partial_svg_;
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
