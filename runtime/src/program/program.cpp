// run_program: the generated program's main(). Everything the command line names is checked
// before growth starts, so a bad argument never costs a long run and never leaves a file behind.
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <acanthus/error.hpp>
#include <acanthus/growth.hpp>
#include <acanthus/partial_picture.hpp>
#include <acanthus/program.hpp>
#include <acanthus/region.hpp>
#include <acanthus/render.hpp>
#include <acanthus/skeletal_stroke.hpp>
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <future>
#include <iomanip>
#include <iostream>
#include <new>
#include <optional>
#include <sstream>

#include "output/coverage.hpp"
#include "output/page_layout.hpp"
#include "output/transaction.hpp"
#include "pattern/body_watchdog.hpp"
#include "pattern/crash_handler.hpp"
#include "pattern/running_body.hpp"
#include "program/metrics_json.hpp"
#include "program/options.hpp"
#include "program/output_paths.hpp"
#include "program/progress_line.hpp"
#include "program/tree_json.hpp"
#include "region/band.hpp"
#include "symmetry/translation_groups.hpp"

namespace acanthus {

namespace {

using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;

double seconds_since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

std::string program_name(const Pattern& pattern, int argc, char** argv) {
    if (!pattern.name.empty()) return pattern.name;
    if (argc > 0 && argv[0] && *argv[0]) return fs::path(argv[0]).filename().string();
    return "acanthus";
}

std::string range_text(const ParamInfo& p) {
    return p.low.empty() ? std::string() : "[" + p.low + ", " + p.high + "]";
}

// A declared range `in [LO, HI]` holds on --param too (bounds included).
void check_range(const ParamInfo& p, const std::string& value) {
    if (p.low.empty() || p.high.empty() || !p.current) return;
    const long double v = std::strtold(p.current().c_str(), nullptr);
    const long double low = std::strtold(p.low.c_str(), nullptr);
    const long double high = std::strtold(p.high.c_str(), nullptr);
    if (v < low || v > high)
        throw InputError("bad value for parameter '" + p.name + "' (" + p.type + "): '" + value +
                         "' is outside the declared range " + range_text(p));
}

// Applies --param NAME=VALUE in order; a later value for the same name wins.
void apply_params(const Pattern& pattern, const std::vector<std::string>& assignments) {
    for (const std::string& a : assignments) {
        const auto eq = a.find('=');
        const std::string name = a.substr(0, eq);
        const std::string value = a.substr(eq + 1);
        const ParamInfo* param = nullptr;
        for (const ParamInfo& p : pattern.params)
            if (p.name == name) param = &p;
        if (!param) {
            std::string known;
            for (const ParamInfo& p : pattern.params) known += (known.empty() ? "" : ", ") + p.name;
            throw InputError("unknown parameter '" + name + "': " +
                             (known.empty() ? "this pattern declares no parameters"
                                            : "this pattern declares " + known));
        }
        std::string error;
        if (!param->assign || !param->assign(value, error))
            throw InputError("bad value for parameter '" + name + "' (" + param->type +
                             "): " + (error.empty() ? "'" + value + "' does not parse" : error));
        check_range(*param, value);
    }
}

void list_params(const Pattern& pattern, std::ostream& out) {
    if (pattern.params.empty()) {
        out << "'" << pattern.name << "' declares no parameters\n";
        return;
    }
    // A fifth column, `range`, only when some parameter declares one: the four-column table
    // of files without ranges stays as it was.
    bool ranges = false;
    for (const ParamInfo& p : pattern.params) ranges = ranges || !p.low.empty();
    const std::size_t columns = ranges ? 5 : 4;
    std::vector<std::vector<std::string>> rows{{"name", "type", "default", "current", "range"}};
    for (const ParamInfo& p : pattern.params) {
        const std::string range = range_text(p);
        rows.push_back({p.name, p.type, p.default_text, p.current ? p.current() : "?",
                        range.empty() ? "-" : range});
    }
    std::vector<std::size_t> widths(columns, 0);
    for (const auto& row : rows)
        for (std::size_t c = 0; c < columns; ++c) widths[c] = std::max(widths[c], row[c].size());
    for (const auto& row : rows) {
        for (std::size_t c = 0; c + 1 < columns; ++c)
            out << std::left << std::setw(widths[c] + 2) << row[c];
        out << row[columns - 1] << "\n";
    }
}

// The directory a file will be written into must exist before we spend time growing.
void check_writable_location(const std::string& path, const char* what) {
    const fs::path p(path);
    std::error_code ec;
    if (fs::is_directory(p, ec))
        throw InputError("cannot write " + std::string(what) + " '" + path +
                         "': it is a directory");
    const fs::path dir = p.parent_path().empty() ? fs::path(".") : p.parent_path();
    if (!fs::is_directory(dir, ec))
        throw InputError("cannot write " + std::string(what) + " '" + path + "': no directory '" +
                         dir.string() + "'");
}

std::string format_point(Point p) {
    std::ostringstream s;
    s << p.x << "," << p.y;
    return s.str();
}

// render_to_file resolves the stroke only after growth; resolve it once here to refuse a bad
// name (UsageError) or a bad stroke file (InputError) before spending time growing.
void check_stroke(const std::string& stroke) {
    const std::string ext = fs::path(stroke).extension().string();
    if (ext == ".svg" || ext == ".SVG")
        SkeletalStroke::from_svg_file(stroke);
    else
        SkeletalStroke::builtin(stroke);
}

// Everything that can be refused without growing.
void validate(const detail::ProgramOptions& o, const Region& region,
              detail::OutputTransaction& outputs) {
    if (o.output != "-") {
        format_for_path(o.output);  // UsageError on an unknown extension
        check_writable_location(o.output, "the output");
    }
    if (!o.json.empty()) check_writable_location(o.json, "the element tree");
    if (!o.debug_path.empty()) check_writable_location(o.debug_path, "the debug frame");
    if (!o.partial.empty()) {
        const OutputFormat format = format_for_path(o.partial);
        if (format != OutputFormat::svg && format != OutputFormat::png)
            throw UsageError("--partial '" + o.partial + "' must name an .svg or .png file");
        check_writable_location(o.partial, "the partial picture");
    }
    if (!o.view.empty()) {
        if (format_for_path(o.view) != OutputFormat::png)
            throw UsageError("--view '" + o.view + "' must name a .png file");
        check_writable_location(o.view, "the view picture");
    }
    if (!o.render.stroke.empty()) check_stroke(o.render.stroke);
    detail::page_layout(region.bounds(), o.render.width);  // UsageError on an impossible page
    for (Point seed : o.growth.seeds) {
        if (!region.contains(seed)) {
            const Rect b = region.bounds();
            throw InputError("seed " + format_point(seed) + " is outside the region '" +
                             region.name() + "' (bounds " + format_point({b.x0, b.y0}) + " to " +
                             format_point({b.x1, b.y1}) + ")");
        }
    }
    if (!o.frames_dir.empty()) {
        std::error_code ec;
        // A directory made for this run goes again if the run fails (while still empty).
        std::vector<fs::path> made;
        for (fs::path p = fs::path(o.frames_dir).lexically_normal();
             !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
            made.push_back(p);
            if (p == p.parent_path()) break;
        }
        for (auto it = made.rbegin(); it != made.rend(); ++it)
            outputs.add_created_directory(it->string());
        fs::create_directories(o.frames_dir, ec);
        if (!fs::is_directory(o.frames_dir))
            throw InputError("cannot write frames into '" + o.frames_dir +
                             "': " + (ec ? ec.message() : "not a directory"));
    }
}

// --partial: the growth so far, drawn every `every` seconds while it grows and published at
// once (outside the run's all-or-none outputs), so that a viewer sees it grow. The first comes
// after a fifth of the interval (a viewer's first look: a few elements, quick to draw). Each is
// drawn by a forked copy of the program while the growth goes on: drawing a large picture took
// tens of milliseconds each time, a third of spiral's processor time, on the growth's way. The
// next waits for the copy to end, at least as long again as it took, and a fifth of the time
// grown so far. The copy shares nothing the growth changes afterwards (copy-on-write memory).
// None is drawn while nothing was placed since the last one, nor once nothing was placed for an
// interval: a growth's last tenths of a second are often its failures alone (spiral's 0.2 to
// 0.4 s), and the picture drawn then was the finished one again, 5 MB of it, drawn and decoded
// by the page while the finished one came.
// What a copy that crashed or was stopped left of its picture (write_output_file's temporary
// name, `.NAME.tmp-XXXXXX` beside it).
void remove_copy_temporaries(const std::string& path) {
    const fs::path target(path);
    // Appended, not `"." + string`: GCC 12 warns falsely of it at -O3 (-Wrestrict).
    std::string prefix = ".";
    prefix += target.filename().string();
    prefix += ".tmp-";
    std::error_code ec;
    const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
        const std::string name = e.path().filename().string();
        if (name.size() == prefix.size() + 6 && name.rfind(prefix, 0) == 0)
            fs::remove(e.path(), ec);
    }
}

// The child's side of a picture drawn by a forked copy of the program: it writes `path` and
// exits, never returning into the parent's code. A crash here is the copy's alone: the default
// action, not the run's crash report (which would remove the run's temporary outputs, shared
// by name with the parent). Gone with the run, whatever ends it; and a drawing that never ends
// (the watchdog thread is not copied) is stopped like one body that runs too long.
// `nicer`: how much lower the copy's priority is than the run's (setpriority: the copy has
// one thread, the one that forked).
template <class Draw>
[[noreturn]] void draw_in_copy(Draw& draw, const std::string& path, pid_t parent,
                               double body_time_limit, int nicer = 0) {
    for (int signal : {SIGSEGV, SIGBUS, SIGFPE, SIGABRT}) std::signal(signal, SIG_DFL);
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent) std::_Exit(1);
    if (nicer > 0) {
        errno = 0;
        const int now = getpriority(PRIO_PROCESS, 0);
        if (errno == 0) setpriority(PRIO_PROCESS, 0, std::min(now + nicer, 19));
    }
    if (body_time_limit > 0) alarm(static_cast<unsigned>(std::ceil(body_time_limit)));
    int code = 0;
    try {
        const detail::OutputTransaction::Bypass outside;
        draw(path);
    } catch (...) {
        code = 1;
    }
    std::_Exit(code);  // no destructors, no atexit: they are the parent's
}

constexpr long kPartialCheckEvery = 8;  // iterations between two looks at the clock
// The copies drawing partial pictures after the first (the viewer's first look, at the run's
// priority) run this much nicer than the growth: on a busy machine they take the cores the
// growth and the viewer leave (a draft late by a few tens of milliseconds is still a draft;
// the growth late is the finished picture late).
constexpr int kPartialCopyNicer = 5;

// The output's copy and the coverage, made after the view, run this much nicer: a viewer
// fetches and shows the view meanwhile; on a busy machine they take what it leaves.
constexpr int kBesideViewNicer = 5;

// This thread's priority lowered by `nicer` (Linux: a thread's own niceness).
void lower_thread_priority(int nicer) {
    const auto tid = static_cast<id_t>(::syscall(SYS_gettid));
    errno = 0;
    const int now = getpriority(PRIO_PROCESS, tid);
    if (errno == 0) setpriority(PRIO_PROCESS, tid, std::min(now + nicer, 19));
}

class PartialPictures {
  public:
    PartialPictures(std::string path, double every, double body_time_limit)
        : path_(std::move(path)),
          every_(every),
          body_time_limit_(body_time_limit),
          start_(Clock::now()),
          next_(start_ + seconds(every / 5)) {}
    PartialPictures(const PartialPictures&) = delete;
    PartialPictures& operator=(const PartialPictures&) = delete;
    ~PartialPictures() { settle(); }

    // `placed`: how many successes the growth has had (what the picture shows changes with them).
    bool due(long placed) {
        if (path_.empty()) return false;
        const Clock::time_point now = Clock::now();
        if (placed != last_placed_) {
            last_placed_ = placed;
            placed_at_ = now;
        }
        if (placed == drawn_placed_ || now - placed_at_ > seconds(every_) ||
            (drawing_ > 0 && !reaped(false)))
            return false;
        return now >= next_;
    }

    template <class Draw>
    void write(long placed, Draw draw) {
        drawn_placed_ = placed;
        const Clock::time_point begin = Clock::now();
        std::fflush(nullptr);  // nothing buffered is written twice
        const pid_t parent = getpid();
        const pid_t pid = fork();
        if (pid == 0)
            draw_in_copy(draw, path_, parent, body_time_limit_, forks_ > 0 ? kPartialCopyNicer : 0);
        if (pid > 0) {
            ++forks_;
            drawing_ = pid;
            forked_ = begin;
            next_ = begin + std::max(seconds(every_), (begin - start_) / 5);
            return;
        }
        // No copy (out of processes): drawn here, with the growth waiting for it.
        {
            const detail::OutputTransaction::Bypass outside;
            draw(path_);
        }
        ++published_;
        const Clock::time_point end = Clock::now();
        next_ = end + std::max({seconds(every_), 4 * (end - begin), (end - start_) / 5});
    }

    // The growth is over: the picture being drawn is stopped (the finished one follows; drawn,
    // it would reach a viewer just before that one and hold it up), unless it would be the
    // first: that one may go on while the finished picture is drawn, and is settled then.
    void finish() {
        if (drawing_ > 0 && published_ > 0) settle();
    }

    // The finished picture is drawn: a copy still drawing is stopped now, whatever it does (a
    // %draw body that never returns in the copy alone, say, without --body-time-limit's alarm).
    void settle() {
        if (drawing_ <= 0 || reaped(false)) return;
        ::kill(drawing_, SIGKILL);
        reaped(true);
    }

  private:
    // Whether the copy drawing has ended (waited for with `block`); then the next picture
    // waits at least as long as it took.
    bool reaped(bool block) {
        int status = 0;
        pid_t r;
        do r = waitpid(drawing_, &status, block ? 0 : WNOHANG);
        while (r < 0 && errno == EINTR);
        if (r == 0) return false;
        drawing_ = 0;
        if (r > 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0)
            ++published_;
        else if (r > 0)
            remove_copy_temporaries(path_);
        const Clock::time_point now = Clock::now();
        next_ = std::max(next_, now + (now - forked_));
        return true;
    }

    static Clock::duration seconds(double s) {
        return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
    }
    std::string path_;
    double every_;
    double body_time_limit_;
    Clock::time_point start_, next_, forked_;
    pid_t drawing_ = 0;  // the copy drawing a picture now
    long forks_ = 0;     // copies made so far
    long published_ = 0;
    long drawn_placed_ = -1;  // the growth's successes when the last picture was taken
    long last_placed_ = -1;   // ... when due() last looked, first seen at placed_at_
    Clock::time_point placed_at_;
};

// A picture drawn by a forked copy of the program while this process does other work. It is
// written under a name of its own beside the target (renamed to it with the run's other
// outputs); a copy that fails or cannot be made leaves the drawing to this process, whose
// messages and crash reports are the run's.
class OutputCopy {
  public:
    OutputCopy(const std::string& target, double body_time_limit,
               detail::OutputTransaction& outputs)
        : body_time_limit_(body_time_limit) {
        const fs::path t(target);
        std::string name = ".";  // appended: see remove_copy_temporaries
        name += t.stem().string();
        name += ".drawn-";
        name += std::to_string(getpid());
        name += t.extension().string();
        path_ = (t.parent_path() / name).string();
        outputs.add_file(path_, target);  // (removed with the run's temporaries if it fails)
    }
    OutputCopy(const OutputCopy&) = delete;
    OutputCopy& operator=(const OutputCopy&) = delete;
    ~OutputCopy() {
        if (pid_ <= 0) return;
        ::kill(pid_, SIGKILL);  // the run failed first
        reap();
    }

    template <class Draw>
    void start(Draw draw) {
        std::fflush(nullptr);  // nothing buffered is written twice
        const pid_t parent = getpid();
        const pid_t pid = fork();
        if (pid != 0) {
            pid_ = pid;  // (-1: no copy; drawn by finish)
            return;
        }
        draw_in_copy(draw, path_, parent, body_time_limit_, kBesideViewNicer);
    }

    // Waits for the copy; draws the picture here when the copy did not.
    template <class Draw>
    void finish(Draw draw) {
        if (pid_ > 0 && reap()) return;
        const detail::OutputTransaction::Bypass outside;  // under the name the run renames
        draw(path_);
    }

  private:
    // Whether the copy ended having drawn the picture. One that did not may have left its
    // picture half written (write_output_file's temporary, `.NAME.tmp-XXXXXX` beside it).
    bool reap() {
        int status = 0;
        pid_t r;
        do r = waitpid(pid_, &status, 0);
        while (r < 0 && errno == EINTR);
        pid_ = 0;
        if (r > 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0) return true;
        remove_copy_temporaries(path_);
        return false;
    }

    double body_time_limit_;
    std::string path_;
    pid_t pid_ = 0;
};

std::string frame_path(const std::string& dir, long number) {
    char name[32];
    std::snprintf(name, sizeof name, "frame-%06ld.png", number);
    return (fs::path(dir) / name).string();
}

int run(const Pattern& pattern, const std::string& program, int argc, char** argv,
        Clock::time_point start) {
    std::optional<detail::ProgramOptions> parsed =
        detail::parse_program_options(pattern, program, argc, argv);
    if (!parsed) return 0;  // --help or --version
    detail::ProgramOptions& o = *parsed;

    apply_params(pattern, o.params);
    if (o.list_params) {
        list_params(pattern, std::cout);
        return 0;
    }

    detail::check_output_paths(o);
    if (!o.band.empty())  // grown straight, drawn bent (docs/symmetry.md)
        o.render.band =
            std::make_shared<const detail::Band>(detail::Band::from_svg_file(o.band, o.band_width));
    if (o.render.band && o.render.band->closed() && o.growth.frieze) {
        // A closed band's frieze wraps, with no seam where the centre line closes; the
        // translates across its ends are clipped to the band.
        o.growth.wrap_x = o.render.band->length();
        o.render.clip_to_region = true;
    }
    const Region region = o.render.band        ? o.render.band->straight_region()
                          : o.growth.wallpaper ? detail::tile_region(*o.growth.wallpaper)
                          : o.region.empty()   ? Region::default_panel()
                                               : Region::from_argument(o.region);
    // Every file of the run is renamed into place at the end, all or none.
    detail::OutputTransaction outputs;
    validate(o, region, outputs);

    GrowthEngine engine(pattern, region, o.growth);
    detail::ProgressLine progress(program, o.progress);
    engine.on_progress(
        [&](long iteration, long elements) { progress.update(iteration, elements); });

    bool debug_written = false;
    if (o.debug_iteration > 0) {
        // Drawn when iteration N happens; published with the run's other outputs at the end.
        engine.on_debug_frame(o.debug_iteration, [&](const DebugFrame& frame) {
            render_debug_frame(o.debug_path, region, frame, o.render);
            debug_written = true;
        });
    }
    RenderOptions frame_options = o.render;
    // --view and a PNG --partial: the SVG's page drawn at the size a viewer shows it.
    RenderOptions view_options = o.render;
    view_options.fit_width = o.view_width;
    view_options.fit_height = o.view_height;
    view_options.stored_png = true;
    // The growth so far, replaced within a tenth of a second: drawn in draft and at half the
    // size, scaled up by the viewer (a quarter of the pixels to draw, write, send and decode),
    // so that the copies drawing it take less of the cores the growth and the viewer need.
    // At the view's size, chinese_vase's took 15% of its run's processor time.
    RenderOptions partial_options = view_options;
    partial_options.draft = true;
    if (o.view_width > 0 && o.view_height > 0) {
        partial_options.fit_width = std::max(16, o.view_width / 2);
        partial_options.fit_height = std::max(16, o.view_height / 2);
    }
    long frames_written = 0, last_frame_iteration = -1;
    PartialPictures partials(o.partial, o.partial_every, o.body_time_limit);
    if (!o.frames_dir.empty())
        engine.on_frame(o.frames_every,
                        [&](long iteration, const std::vector<const Element*>& elements) {
                            render_to_file(frame_path(o.frames_dir, ++frames_written), pattern,
                                           region, elements, frame_options);
                            last_frame_iteration = iteration;
                        });
    if (!o.partial.empty()) {
        // --partial looks at the clock every few iterations; the list of the elements is made
        // only for a picture.
        engine.on_iteration(kPartialCheckEvery, [&](long) {
            long placed = 0;
            for (const RuleStats& r : engine.stats().rules) placed += r.successes;
            if (!partials.due(placed)) return;
            const std::vector<const Element*> elements = engine.elements();
            partials.write(placed, [&](const std::string& path) {
                render_to_file(path, pattern, region, elements, partial_options);
            });
        });
    }

    // A library's placements inside one long body (report_partial): drawn with the elements
    // placed before it, by the same copies.
    struct BodyPartials {
        PartialPictures& partials;
        GrowthEngine& engine;
        const std::function<void(const std::string&, const std::vector<const Element*>&)> draw;
    } body_partials{partials, engine,
                    [&](const std::string& path, const std::vector<const Element*>& elements) {
                        render_to_file(path, pattern, region, elements, partial_options);
                    }};
    const auto body_partial = [](void* context, long placed, const PartialElements& extra) {
        BodyPartials& b = *static_cast<BodyPartials*>(context);
        long total = placed;
        for (const RuleStats& r : b.engine.stats().rules) total += r.successes;
        if (!b.partials.due(total)) return;
        b.partials.write(total, [&](const std::string& path) {
            std::vector<const Element*> elements = b.engine.elements();
            extra(elements);
            b.draw(path, elements);
        });
    };
    struct HandlerScope {
        ~HandlerScope() { detail::set_partial_handler(nullptr, nullptr); }
    } handler_scope;
    if (!o.partial.empty()) detail::set_partial_handler(body_partial, &body_partials);

    detail::install_crash_handler();
    {
        const detail::BodyWatchdog watchdog(o.body_time_limit, o.growth.time_limit);
        engine.run();
    }
    detail::set_partial_handler(nullptr, nullptr);
    partials.finish();
    progress.finish();
    // Growth is over: its field and buffers make room for the drawing (Cairo's vector pages keep
    // every operation of the page until it ends).
    engine.release_growth_state();
    // %draw bodies: the per-call limit only (--time-limit bounds growth, not rendering).
    const detail::BodyWatchdog watchdog(o.body_time_limit, 0);
    const GrowthStats& stats = engine.stats();
    const std::vector<const Element*> elements = engine.elements();

    // The last state always ends an animation, even between two K-th iterations.
    if (!o.frames_dir.empty() && last_frame_iteration != stats.iterations)
        render_to_file(frame_path(o.frames_dir, ++frames_written), pattern, region, elements,
                       frame_options);

    const Clock::time_point render_start = Clock::now();
    const auto measure_coverage = [&] {
        return detail::coverage(region, elements,
                                detail::rendered_line_width(region, o.render.width));
    };
    std::future<double> cover;
    if (!o.view.empty()) {
        // The view first, alone: a viewer waits for it and nothing else. The output, the
        // coverage and the metrics come after it; drawn beside it they took a share of the
        // processor it needed (spiral: coverage 0.39 and SVG 0.25 G instructions beside the
        // view's 0.32 G).
        render_to_file(o.view, pattern, region, elements, view_options);
        // Published now, not with the others at the end. No partial picture comes after it
        // (a first one still drawing is stopped).
        partials.settle();
        outputs.publish(o.view);
        // The output drawn by a forked copy while this process measures the coverage; both
        // nicer than a viewer fetching and showing the view meanwhile.
        std::optional<OutputCopy> output_copy;
        if (o.output != "-") {
            output_copy.emplace(o.output, o.body_time_limit, outputs);
            output_copy->start([&](const std::string& path) {
                render_to_file(path, pattern, region, elements, o.render);
            });
        }
        lower_thread_priority(kBesideViewNicer);
        if (o.metrics) {
            std::promise<double> measured;
            measured.set_value(measure_coverage());
            cover = measured.get_future();
        }
        if (output_copy)
            output_copy->finish([&](const std::string& path) {
                render_to_file(path, pattern, region, elements, o.render);
            });
        else
            render_to_file(o.output, pattern, region, elements, o.render);
    } else {
        // The coverage (a raster of its own, the proxies alone: no rule code runs in it) on a
        // second thread while the output is drawn.
        if (o.metrics) cover = std::async(std::launch::async, measure_coverage);
        render_to_file(o.output, pattern, region, elements, o.render);
    }
    const double render_seconds = seconds_since(render_start);
    partials.settle();

    if (!o.json.empty()) detail::write_tree_json(o.json, region, elements);
    if (o.debug_iteration > 0 && !debug_written)
        std::cerr << program << ": warning: no debug frame written: growth stopped after "
                  << stats.iterations << " iterations, before iteration " << o.debug_iteration
                  << "\n";
    if (o.metrics) {
        std::cout << detail::metrics_json(pattern, stats, static_cast<long>(elements.size()),
                                          cover.get(), seconds_since(start), render_seconds,
                                          o.growth.reference_engine, &region)
                  << std::endl;
        if (!std::cout) throw InputError("cannot write the metrics to stdout");
    }
    outputs.commit();
    return 0;
}

void report(const std::string& program, const char* kind, const std::string& message) {
    std::cout.flush();
    std::cerr << program << ": " << kind << ": " << message << std::endl;
}

}  // namespace

int run_program(const Pattern& pattern, int argc, char** argv) {
    const Clock::time_point start = Clock::now();
    const std::string program = program_name(pattern, argc, argv);
    detail::set_program_name_for_fatal_exit(program);
    detail::set_fatal_exit_cleanup(&detail::OutputTransaction::abandon_from_signal);
    try {
        return run(pattern, program, argc, argv, start);
    } catch (const UsageError& e) {
        report(program, "error", e.what());
        std::cerr << "Run '" << program << " --help' for the options and examples." << std::endl;
        return 2;
    } catch (const InputError& e) {
        report(program, "error", e.what());
        return 1;
    } catch (const RuleFailure& e) {
        report(program, "error", e.what());
        return 3;
    } catch (const std::bad_alloc&) {
        report(program, "error", "out of memory");
        return 1;
    } catch (const fs::filesystem_error& e) {
        report(program, "error", e.what());
        return 1;
    } catch (const std::exception& e) {
        // Anything else escaped user code (%exhausted, %draw, %source) or the engine.
        report(program, "error", std::string("failed at run time: ") + e.what());
        return 3;
    }
}

}  // namespace acanthus
