// The public API: modes, Reference accessors, and synthesize() over a region or the running
// ornament.
#include <acanthus/environment.hpp>
#include <acanthus/error.hpp>
#include <acanthus/metrics.hpp>
#include <acanthus/stdlib/growth.hpp>
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <future>
#include <stdexcept>
#include <system_error>

#include "fidelity.hpp"
#include "geometry/coordinate_range.hpp"
#include "guided_panel.hpp"
#include "panel.hpp"
#include "reference.hpp"
#include "synthesis.hpp"

namespace acanthus::growth {

Mode parse_mode(std::string_view text) {
    if (text == "none" || text == "non-rotation") return Mode::none;
    if (text == "rotation") return Mode::rotation;
    if (text == "flow") return Mode::flow;
    throw InputError("growth: unknown mode '" + std::string(text) +
                     "' (expected none, rotation or flow)");
}

std::string_view to_string(Mode mode) {
    switch (mode) {
        case Mode::none:
            return "none";
        case Mode::rotation:
            return "rotation";
        case Mode::flow:
            return "flow";
    }
    return "?";
}

std::map<std::string, int> parse_priority(std::string_view text) {
    std::map<std::string, int> priority;
    auto trim = [](std::string_view v) {
        while (!v.empty() && std::isspace(static_cast<unsigned char>(v.front())))
            v.remove_prefix(1);
        while (!v.empty() && std::isspace(static_cast<unsigned char>(v.back()))) v.remove_suffix(1);
        return v;
    };
    while (!trim(text).empty()) {
        std::size_t comma = text.find(',');
        std::string_view item = trim(text.substr(0, comma));
        text = comma == std::string_view::npos ? std::string_view() : text.substr(comma + 1);
        std::size_t eq = item.find('=');
        std::string_view name = trim(item.substr(0, eq == std::string_view::npos ? 0 : eq));
        std::string_view value = eq == std::string_view::npos ? "" : trim(item.substr(eq + 1));
        int level = 0;
        auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), level);
        if (name.empty() || value.empty() || ec != std::errc() ||
            end != value.data() + value.size())
            throw InputError("growth: priority '" + std::string(item) +
                             "' is not symbol=integer (e.g. \"flower=2,leaf=1\")");
        priority[std::string(name)] = level;
    }
    return priority;
}

Reference::Reference(std::shared_ptr<const detail::ReferenceData> data) : data_(std::move(data)) {}

Reference Reference::from_elements(std::vector<ReferenceElement> elements,
                                   std::vector<std::pair<int, int>> flips,
                                   const std::string& name) {
    return Reference(detail::analyse_reference(name, std::move(elements), std::move(flips)));
}

std::size_t Reference::size() const { return data_->elements.size(); }
const ReferenceElement& Reference::element(std::size_t i) const { return data_->elements.at(i); }
double Reference::radius(std::size_t i) const { return data_->radius.at(i); }
const std::vector<std::pair<int, int>>& Reference::edges() const {
    return data_->connectivity.edges;
}
const std::vector<int>& Reference::ring(std::size_t i) const {
    return data_->connectivity.rings.at(i);
}
bool Reference::boundary(std::size_t i) const { return data_->connectivity.boundary.at(i); }
double Reference::mean_edge_length() const { return data_->mean_edge; }
double Reference::shortest_edge_length() const { return data_->shortest_edge; }
const std::string& Reference::name() const { return data_->name; }
const std::vector<Outline>& Reference::outlines(std::size_t i) const {
    return data_->outlines.at(i);
}
std::size_t Reference::symbol_count() const { return data_->symbols.size(); }
int Reference::symbol_index(std::size_t i) const { return data_->symbol.at(i); }

namespace {

// From this many elements, the first synthesis from a reference works out its side of the
// fidelity report (also the crowding rule's limit) on a second thread while it finds the
// reference's spacing, lattice and jitter: a hundred thousand elements take a fifth of a second
// each way. Smaller ones are not worth a thread.
constexpr std::size_t kHugeReference = 20000;

void check_options(const Options& o) {
    auto bad = [](const std::string& why) { throw InputError("growth: " + why); };
    for (double w : {o.w1, o.w2, o.w3, o.w4})
        if (!std::isfinite(w) || w < 0) bad("weights w1, w2, w3, w4 must be finite and >= 0");
    if (!(o.scale_min > 0) || !(o.scale_max >= o.scale_min) || !std::isfinite(o.scale_max))
        bad("scale range must satisfy 0 < scale_min <= scale_max");
    if (!std::isfinite(o.angle_jitter) || o.angle_jitter < 0) bad("angle_jitter must be >= 0");
    if (!(o.short_factor >= 0) || !(o.angle_factor >= 0) || !(o.long_factor > 0) ||
        !std::isfinite(o.short_factor + o.angle_factor + o.long_factor))
        bad("short_factor, angle_factor and long_factor must be finite, >= 0");
    if (!(o.gap_factor >= 0 && o.gap_factor <= 1.5)) bad("gap_factor must be in [0, 1.5]");
    if (!(o.relax_radius > 0) || !std::isfinite(o.relax_radius)) bad("relax_radius must be > 0");
    if (!(o.relax_slack >= 0) || !std::isfinite(o.relax_slack))
        bad("relax_slack must be finite and >= 0");
    if (!(o.priority_radius >= 0) || !std::isfinite(o.priority_radius))
        bad("priority_radius must be >= 0");
    if (o.max_elements < 0) bad("max_elements must be >= 0");
    if (o.max_motifs < 1) bad("max_motifs must be >= 1");
    if (o.mode == Mode::flow && o.flow_strokes.empty())
        bad(o.guides_name.empty()
                ? "flow mode needs at least one flow stroke (Options::flow_strokes, or a guides "
                  "file with class=\"flow\" paths)"
                : "flow mode needs at least one flow stroke, and " + o.guides_name +
                      " has none (paths with class=\"flow\")");
    if (!(o.color_variation >= 0 && o.color_variation <= 1))
        bad("color_variation must be in [0, 1]");
    auto finite_line = [](const std::vector<Point>& line) {
        return !line.empty() && std::all_of(line.begin(), line.end(), [](Point p) {
            return p.finite() && acanthus::detail::in_coordinate_range(p.x) &&
                   acanthus::detail::in_coordinate_range(p.y);
        });
    };
    for (const auto& line : o.boundary_strokes)
        if (!finite_line(line)) bad("a boundary stroke has no points or a coordinate beyond ±1e9");
    for (const Options::Spray& s : o.spray_strokes)
        if (!finite_line(s.points) || !(s.width > 0) ||
            !acanthus::detail::in_coordinate_range(s.width))
            bad("a spray stroke needs points within ±1e9 and a width in (0, 1e9]");
}

// Spray strokes start growth at their first points (section 3: the brush plants seeds).
std::vector<Point> with_spray_starts(std::vector<Point> starts, const Options& options) {
    for (const Options::Spray& s : options.spray_strokes) starts.push_back(s.points.front());
    return starts;
}

SynthesisResult run(const Reference& reference, const detail::Panel& panel, const Options& options,
                    const std::vector<Point>& starts, Random& random) {
    check_options(options);
    detail::GuidedPanel guided(panel, options);
    const bool tools = !options.boundary_strokes.empty() || !options.spray_strokes.empty();
    const detail::Panel& room = tools ? guided : panel;
    detail::Synthesis synthesis(reference.data(), room, options, random);
    synthesis.plant(with_spray_starts(starts, options));
    synthesis.run();
    SynthesisResult result = synthesis.result();
    result.fidelity =
        detail::measure_fidelity(reference.data(), result.motifs, room, synthesis.largest_hole());
    return result;
}

}  // namespace

SynthesisResult synthesize(const Reference& reference, const Region& region, const Options& options,
                           const std::vector<Point>& starts, std::uint64_t seed) {
    // Before anything that costs in proportion to the panel; a bad max_motifs is said as such.
    check_options(options);
    // Made once per reference (call_once): a later call, or the synthesis asking for it while
    // the thread is at it, waits for the one result. What the thread throws is thrown again
    // where the synthesis asks.
    std::future<void> profile;
    if (reference.data().elements.size() >= kHugeReference) {
        try {
            profile = std::async(std::launch::async, [&reference] {
                try {
                    detail::profile_of(reference.data());
                } catch (...) {
                }
            });
        } catch (const std::system_error&) {
            // No thread to be had (a process limit): the synthesis works it out itself.
        }
    }
    detail::check_motif_count(reference.data(), region.area(), options);
    std::vector<Point> points = starts;
    if (points.empty() && options.spray_strokes.empty())
        points.push_back(
            region.largest_inscribed_circle(reference.mean_edge_length() / 100).center);
    for (Point p : points)
        if (!p.finite() || !region.contains(p))
            throw InputError("growth: start point (" + std::to_string(p.x) + ", " +
                             std::to_string(p.y) + ") lies outside the panel " + region.name());
    detail::RegionPanel panel(region);
    Random random(seed);
    return run(reference, panel, options, points, random);
}

SynthesisResult synthesize(const Reference& reference, const Options& options, Point start) {
    Environment* env = Environment::current();
    if (!env) throw std::logic_error("growth::synthesize(reference, options) needs a rule body");
    detail::EnvironmentPanel panel(*env);
    SynthesisResult result = run(reference, panel, options, {start}, env->random());
    // The program's --metrics shows the last synthesis of the run.
    set_metrics_section("growth", fidelity_json(result));
    return result;
}

SynthesisResult synthesize(const Reference& reference, const Options& options) {
    Environment* env = Environment::current();
    if (!env) throw std::logic_error("growth::synthesize(reference, options) needs a rule body");
    return synthesize(reference, options, env->goal().center);
}

}  // namespace acanthus::growth
