#include "server/render_job.hpp"

#include <sys/eventfd.h>
#include <sys/inotify.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "compilation.hpp"
#include "server/child.hpp"
#include "server/host.hpp"
#include "toolchain/precompiled_prelude.hpp"
#include "toolchain/process.hpp"

namespace acanthus {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

// Sized by the file, not by the limit: a string of the limit's 64 MiB, zeroed then shrunk, cost
// 40 to 180 ms a read (each partial picture, then the metrics, the PNG and the SVG of every save).
std::string read_text(const std::string& path, std::size_t limit = 64u << 20) {
    std::ifstream in(path, std::ios::binary);
    std::string s;
    if (!in) return s;
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    in.seekg(0, std::ios::beg);
    // (a file that grows meanwhile is read up to the size seen)
    const std::size_t wanted = size >= 0 ? std::min(limit, static_cast<std::size_t>(size)) : limit;
    s.resize(wanted);
    in.read(s.data(), static_cast<std::streamsize>(wanted));
    s.resize(static_cast<std::size_t>(in.gcount()));
    return s;
}

double seconds_since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

// The last `name: iteration N, M elements, S s` line of --progress.
bool last_progress(const std::string& text, long& iterations, long& elements, double& seconds) {
    static const std::regex line(R"(iteration (\d+), (\d+) elements, ([0-9.]+) s)");
    auto end = std::sregex_iterator();
    bool found = false;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), line); it != end; ++it) {
        iterations = std::stol((*it)[1]);
        elements = std::stol((*it)[2]);
        seconds = std::stod((*it)[3]);
        found = true;
    }
    return found;
}

// What a program stopped by RLIMIT_AS shows: an allocation that threw (the runtime reports
// std::bad_alloc), or a crash or abort where memory could not be had.
bool out_of_memory(const ChildEnd& end, const std::string& messages) {
    if (messages.find("bad_alloc") != std::string::npos ||
        messages.find("out of memory") != std::string::npos ||
        messages.find("Cannot allocate memory") != std::string::npos)
        return true;
    return end.how == ChildEnd::How::signaled && (end.code == SIGSEGV || end.code == SIGABRT) &&
           messages.find("memory") != std::string::npos;
}

// The program stops growing at --time-limit and still draws what grew, exiting 0; only its
// growth seconds tell (a growth that finishes by itself within 5% of the limit is rare).
std::string cut_by_time_limit(const PreviewStatus::json& metrics, double time_limit) {
    if (time_limit <= 0 || !metrics.contains("seconds") || !metrics["seconds"].is_object())
        return {};
    const double growth = metrics["seconds"].value("growth", 0.0);
    if (growth < 0.95 * time_limit) return {};
    std::ostringstream text;
    text << "cut by --time-limit " << time_limit << " s: the growth did not finish";
    return text.str();
}

// Whether a file the program replaces (by rename) is there anew since the last look.
class PartialWatch {
  public:
    bool changed(const std::string& path) {
        struct stat st {};
        if (::stat(path.c_str(), &st) != 0 || st.st_size == 0) return false;
        const bool fresh = st.st_ino != inode_ || st.st_mtim.tv_sec != mtime_.tv_sec ||
                           st.st_mtim.tv_nsec != mtime_.tv_nsec;
        inode_ = st.st_ino;
        mtime_ = st.st_mtim;
        return fresh;
    }

  private:
    ino_t inode_ = 0;
    timespec mtime_{};
};

std::string stem_of(const std::string& path) {
    std::string stem = fs::path(path).stem().string();
    return stem.empty() ? "pattern" : stem;
}

}  // namespace

RenderJob::RenderJob(PreviewConfig config, PreviewSettings settings, PreviewStatus& status)
    : config_(std::move(config)),
      status_(status),
      settings_(std::move(settings)),
      watcher_([this] { request(); }) {
    watcher_.watch({config_.input});
    thread_ = std::thread([this] { loop(); });
}

RenderJob::~RenderJob() {
    stop();
    if (cancel_event_ >= 0) ::close(cancel_event_);
}

void RenderJob::stop() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    cancel_ = true;
    wake_cancelled();
    stop_extras_ = true;
    cv_.notify_all();
    watcher_.stop();
    if (thread_.joinable()) thread_.join();
}

void RenderJob::request() {
    std::lock_guard lock(mutex_);
    requested_at_ = PreviewStatus::now_epoch();
    ++wanted_;
    cancel_ = true;
    wake_cancelled();
    cv_.notify_all();
}

void RenderJob::wake_cancelled() {
    // A child being waited for is stopped now, not at the wait's next tick (10 to 25 ms).
    const std::uint64_t one = 1;
    if (cancel_event_ >= 0 && ::write(cancel_event_, &one, sizeof one) < 0) {
        // (full or closed: the wait's next tick sees the cancel)
    }
}

PreviewSettings RenderJob::settings() const {
    std::lock_guard lock(mutex_);
    return settings_;
}

void RenderJob::set_settings(PreviewSettings settings) {
    {
        std::lock_guard lock(mutex_);
        settings_ = std::move(settings);
    }
    request();
}

void RenderJob::set_view_size(int width, int height) {
    std::lock_guard lock(mutex_);
    view_width_ = width;
    view_height_ = height;
}

void RenderJob::loop() {
    for (;;) {
        long generation = 0;
        {
            std::unique_lock lock(mutex_);
            cv_.wait(lock, [&] { return stopping_ || wanted_ != done_; });
            if (stopping_) return;
            generation = wanted_;
            cancel_ = false;
            std::uint64_t count = 0;  // (the wake of the cancels just taken back)
            if (cancel_event_ >= 0 && ::read(cancel_event_, &count, sizeof count) < 0) count = 0;
        }
        render(generation);
        std::lock_guard lock(mutex_);
        done_ = generation;
    }
}

std::string RenderJob::command_line(const PreviewSettings& s) const {
    std::vector<std::string> cmd{"acanthus", "run"};
    for (const std::string& dir : config_.includes) cmd.insert(cmd.end(), {"-I", dir});
    cmd.push_back(config_.input);
    std::vector<std::string> args = s.arguments(true);
    cmd.insert(cmd.end(), args.begin(), args.end());
    cmd.insert(cmd.end(), {"-o", stem_of(config_.input) + ".svg"});
    return quote_command(cmd);
}

namespace {

// A build command's name in the timeline: the program and the file it compiles, or "link".
std::string command_label(const std::vector<std::string>& argv) {
    std::string label = fs::path(argv.front()).filename().string();
    const auto c = std::find(argv.begin(), argv.end(), "-c");
    return label + " " +
           (c != argv.end() && c + 1 != argv.end() ? fs::path(*(c + 1)).filename().string()
                                                   : std::string("link"));
}

}  // namespace

CommandRunner RenderJob::runner(const std::string& log, bool& cancelled) {
    return [this, log, &cancelled](const std::vector<std::string>& argv, std::string& error) {
        ChildRun run;
        run.argv = argv;
        run.stdout_path = log + ".out";
        run.stderr_path = log;
        run.cancel = &cancel_;
        run.cancel_fd = cancel_event_;
        run.deadline_seconds = 600;
        const std::string label = argv.empty() ? std::string() : command_label(argv);
        status_.step("start " + label);
        ChildEnd end = run_child(run);
        status_.step("end " + label);
        std::lock_guard lock(runner_mutex_);
        build_cpu_ += end.cpu_seconds;
        if (end.how == ChildEnd::How::exited) return end.code;
        cancelled = cancelled || end.how == ChildEnd::How::cancelled;
        error = describe(end, run.deadline_seconds);
        return -1;
    };
}

bool RenderJob::prepare_host() {
    if (!host_.empty() || host_failed_) return true;
    status_.begin("preparing");
    const std::string log = (fs::path(config_.work_dir) / "host.log").string();
    bool cancelled = false;
    BuildOptions options = config_.build;
    options.runner = runner(log, cancelled);
    std::string error;
    if (!preview_host(config_.toolchain, options, host_, error)) {
        host_.clear();
        if (cancelled) return false;
        host_failed_ = true;  // programs of their own from now on: only slower
    }
    return true;
}

bool RenderJob::build(const std::string& stem, const std::string& cpp, const GeneratedUnits& units,
                      std::vector<std::string>& program) {
    const std::string log = (fs::path(config_.work_dir) / "build.log").string();
    BuildOptions options = config_.build;
    bool cancelled = false;
    options.runner = runner(log, cancelled);
    options.shared_library = !host_.empty();
    std::error_code ec;
    fs::remove(log, ec);
    std::string error;
    if (!prelude_failed_ && !use_precompiled_prelude(config_.toolchain, options, error, cpp)) {
        if (cancelled) return false;
        prelude_failed_ = true;  // build without it from now on; only slower
        options.precompiled_header.clear();
    }
    error.clear();
    std::string built;
    // Units compiled apart and linked: a save that edits one rule body compiles only it. A
    // program that cannot be split, or does not build so, is built whole (whose messages are
    // the ones shown).
    if (options.shared_library && !options.link_command.empty()) {
        std::vector<std::string> parts{units.tables, units.code};
        parts.insert(parts.end(), units.rules.begin(), units.rules.end());
        bool splittable = true, deferred = false, code_deferred = false;
        // A first build, or one after the %source or the element types changed, compiles every
        // unit: more than the whole file. The whole file then, and the units after the picture.
        // The code unit (the %draw bodies) is optimised after the picture too when it changed.
        options.code_unit_later = true;
        options.unit_header = units.header;
        if (cached_split_library(config_.toolchain, options, stem, parts, built, splittable, error,
                                 2, &deferred, &code_deferred)) {
            program = {host_, built};
            if (code_deferred) {
                units_to_fill_ = std::move(parts);
                fill_options_ = options;
                fill_options_.runner = nullptr;
                fill_options_.code_unit_later = false;
                fill_stem_ = stem;
            }
            return true;
        }
        if (cancelled) return false;
        if (deferred) {
            units_to_fill_ = std::move(parts);
            fill_options_ = options;
            fill_options_.runner = nullptr;  // (this build's, given again by fill_units)
            fill_options_.code_unit_later = false;
            fill_stem_ = stem;
        }
        fs::remove(log, ec);
        error.clear();
    }
    if (cached_executable(config_.toolchain, options, stem, cpp, built, error)) {
        program = host_.empty() ? std::vector<std::string>{built}
                                : std::vector<std::string>{host_, built};
        return true;
    }
    if (cancelled) return false;
    std::string output = in_rule_source(read_text(log, 1u << 20));
    if (output.empty()) output = "acanthus: error: " + error + "\n";
    status_.fail("build", output, diagnose(output), 0);
    return false;
}

void RenderJob::render(long generation) {
    const auto start = Clock::now();
    const PreviewSettings settings = this->settings();
    std::string view_size;
    {
        std::lock_guard lock(mutex_);
        view_size = std::to_string(view_width_) + "x" + std::to_string(view_height_);
        status_.start_timeline("asked", requested_at_);
    }
    status_.step("render start");
    if (!prepare_host()) return;
    status_.begin("compiling");
    status_.set_command(command_line(settings));

    CompileRequest request;
    request.input = config_.input;
    request.include_dirs = config_.includes;
    request.stdlib_dirs = config_.toolchain.stdlib_dirs;
    const std::string stem = stem_of(config_.input);
    request.generate.output_name = stem + ".cpp";
    request.generate.emit_main = host_.empty();  // the host has main()
    std::string cpp;
    std::ostringstream diagnostics;
    std::vector<std::string> files;
    std::vector<ParamSummary> params;
    GeneratedUnits units;
    bool compiled = compile_rule_file(request, true, cpp, diagnostics, &files, &params,
                                      host_.empty() ? nullptr : &units);
    files.push_back(config_.input);
    watcher_.watch(files);
    {
        std::lock_guard lock(mutex_);
        source_files_ = files;
    }
    if (!compiled) {
        status_.fail("compile", diagnostics.str(), diagnose(diagnostics.str()),
                     seconds_since(start));
        return;
    }
    status_.set_stroke_tools(
        stroke_tools_of(config_.stroke_tools, files, config_.toolchain.stdlib_dirs, params));
    status_.set_params(params);
    status_.set_timing("compile", seconds_since(start));
    status_.step("compiled");

    status_.begin("building");
    const auto build_start = Clock::now();
    std::vector<std::string> program;
    build_cpu_ = 0;
    units_to_fill_.clear();
    if (!build(stem, cpp, units, program)) return;
    if (cancel_) return;
    status_.set_timing("build", seconds_since(build_start));
    status_.set_timing("build_cpu", build_cpu_);
    status_.step("built");
    const auto grow_start = Clock::now();

    status_.begin("growing");
    const fs::path dir(config_.work_dir);
    const std::string tag = std::to_string(generation);
    const std::string svg = (dir / ("render-" + tag + ".svg")).string();
    const std::string out = (dir / ("metrics-" + tag + ".json")).string();
    const std::string err = (dir / ("messages-" + tag + ".txt")).string();
    // The page shows PNGs at its size (the SVG, 1 to 5 MB, took Chromium 0.1 to 1.4 s to
    // parse); the SVG is fetched only to zoom in past them or to download.
    const std::string png = (dir / ("view-" + tag + ".png")).string();
    const std::string partial = (dir / ("partial-" + tag + ".png")).string();
    ChildRun run;
    run.argv = program;
    std::vector<std::string> arguments = settings.arguments();
    run.argv.insert(run.argv.end(), arguments.begin(), arguments.end());
    run.argv.insert(run.argv.end(), {"-o", svg, "--view", png, "--view-size", view_size,
                                     "--metrics", "--progress", "--partial", partial});
    run.stdout_path = out;
    run.stderr_path = err;
    run.cancel = &cancel_;
    run.cancel_fd = cancel_event_;
    run.memory_limit = config_.memory_limit;
    // The program stops itself at --time-limit (and a runaway body a second later); the
    // deadline is for a program that does not.
    run.deadline_seconds = settings.time_limit + 10;
    PartialWatch partial_seen, view_seen;
    // The finished view, published by the program as soon as it is drawn (before its output,
    // coverage and metrics): the page shows it at once; the revision is made when the run ends.
    std::string final_png;
    // A partial picture is renamed into place: seen when it happens, not at the next tick.
    const int renamed = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
    if (renamed >= 0 && inotify_add_watch(renamed, config_.work_dir.c_str(), IN_MOVED_TO) >= 0)
        run.wake_fd = renamed;
    run.on_poll = [&] {
        if (run.wake_fd >= 0) {
            alignas(inotify_event) char events[4096];
            while (::read(run.wake_fd, events, sizeof events) > 0) {
            }
        }
        long iterations = 0, elements = 0;
        double seconds = 0;
        if (last_progress(read_text(err, 1u << 20), iterations, elements, seconds))
            status_.progress(iterations, elements, seconds);
        if (!final_png.empty()) return;
        if (view_seen.changed(png)) {
            final_png = read_text(png);
            status_.set_partial(final_png, true);
            return;
        }
        // The program replaces the file by a rename: a new one is a new inode or time.
        if (partial_seen.changed(partial)) status_.set_partial(read_text(partial));
    };
    status_.step("program start");
    ChildEnd end = run_child(run);
    status_.step("program end");
    if (renamed >= 0) ::close(renamed);
    std::error_code ec;
    if (end.how == ChildEnd::How::cancelled) {
        for (const std::string& f : {svg, png, out, err, partial}) fs::remove(f, ec);
        return;
    }
    std::string messages = read_text(err, 1u << 20);
    if (end.how == ChildEnd::How::exited && end.code == 0) {
        PreviewStatus::json metrics = PreviewStatus::json::object();
        try {
            // (with the region's bounds, where the page places seeds and strokes)
            metrics = PreviewStatus::json::parse(read_text(out));
        } catch (const std::exception&) {
        }
        {
            std::lock_guard lock(mutex_);
            good_program_ = program;
            good_arguments_ = arguments;
        }
        status_.set_timing("grow", seconds_since(grow_start));
        status_.set_timing("grow_cpu", end.cpu_seconds);
        status_.succeed(read_text(svg), final_png.empty() ? read_text(png) : std::move(final_png),
                        metrics, seconds_since(start),
                        cut_by_time_limit(metrics, settings.time_limit));
        fill_units();
    } else {
        // Only the program's error lines: the progress lines are noise here.
        std::string shown;
        std::istringstream lines(messages);
        for (std::string line; std::getline(lines, line);)
            if (line.find(": iteration ") == std::string::npos) shown += line + "\n";
        // The limit is named only when it is what stopped the program.
        if (end.how == ChildEnd::How::timed_out)
            shown += "acanthus: error: the program was " + describe(end, run.deadline_seconds) +
                     " (--time-limit " + std::to_string(static_cast<long>(settings.time_limit)) +
                     " s and 10 s more)\n";
        else if (end.how != ChildEnd::How::exited)
            shown += "acanthus: error: the program was " + describe(end, 0) + "\n";
        if (config_.memory_limit > 0 && out_of_memory(end, messages))
            shown += "acanthus: error: the program ran out of memory under --memory-limit " +
                     std::to_string(config_.memory_limit >> 20) + " MiB\n";
        else if (shown.empty())
            shown = "acanthus: error: the program ended with " + describe(end, 0) + "\n";
        status_.fail("run", shown, diagnose(shown), seconds_since(start));
    }
    for (const std::string& f : {svg, png, out, err, partial}) fs::remove(f, ec);
}

void RenderJob::fill_units() {
    if (units_to_fill_.empty()) return;
    {
        // The page fetches, decodes and paints the picture just published (about 0.1 s): the
        // units are compiled after that, not on the two cores it needs then.
        std::unique_lock lock(mutex_);
        cv_.wait_for(lock, std::chrono::milliseconds(150), [&] { return stopping_ || cancel_; });
        if (stopping_ || cancel_) {
            units_to_fill_.clear();
            return;
        }
    }
    // Cancelled by the next save (run_child watches cancel_); its objects are kept.
    status_.set_compiling_units(true);
    struct Done {
        PreviewStatus& status;
        ~Done() { status.set_compiling_units(false); }
    } done{status_};
    const std::string log = (fs::path(config_.work_dir) / "units.log").string();
    bool cancelled = false;
    BuildOptions options = fill_options_;
    options.runner = runner(log, cancelled);
    // The units' shared header precompiled first when missing: the units after it compile
    // faster, and so does every later save's unit.
    options.precompile_unit_header = true;
    std::string library, error;
    bool splittable = true;
    // The units a save's build needs first (the code unit at the ordinary level among them),
    // then the optimised code unit: a save that cancels this early still builds only its unit.
    options.code_unit_later = true;
    if (cached_split_library(config_.toolchain, options, fill_stem_, units_to_fill_, library,
                             splittable, error) &&
        !cancel_ && !options.code_unit_optimization.empty()) {
        options.code_unit_later = false;
        // Then the rule units optimised too, for the saves after (the rules they do not edit
        // run at that level: chinese_vase's growth took 14% more instructions at -O0).
        if (cached_split_library(config_.toolchain, options, fill_stem_, units_to_fill_, library,
                                 splittable, error) &&
            !cancel_) {
            options.optimise_rules = true;
            cached_split_library(config_.toolchain, options, fill_stem_, units_to_fill_, library,
                                 splittable, error);
        }
    }
    units_to_fill_.clear();
}

std::vector<std::string> RenderJob::source_files() const {
    std::lock_guard lock(mutex_);
    return source_files_.empty() ? std::vector<std::string>{config_.input} : source_files_;
}

std::vector<PreviewDiagnostic> RenderJob::diagnose(const std::string& output) const {
    std::vector<PreviewDiagnostic> diagnostics = parse_diagnostics(output);
    add_source_context(diagnostics, source_files());
    return diagnostics;
}

ExtraRun RenderJob::run_again(const std::vector<std::string>& extra, double deadline_seconds,
                              const std::string& rng_seed) {
    ExtraRun result;
    ChildRun run;
    {
        std::lock_guard lock(mutex_);
        if (good_program_.empty()) {
            result.message = "there is no good render yet";
            return result;
        }
        run.argv = good_program_;
        // The program takes an option once: a seed or a width given here replaces the
        // render's.
        const auto replaced = [&](const std::string& a) {
            return (a == "--rng-seed" && !rng_seed.empty()) ||
                   (a == "--width" && std::find(extra.begin(), extra.end(), a) != extra.end());
        };
        for (std::size_t i = 0; i < good_arguments_.size(); ++i) {
            if (replaced(good_arguments_[i])) {
                ++i;  // and its value
                continue;
            }
            run.argv.push_back(good_arguments_[i]);
        }
    }
    if (!rng_seed.empty()) run.argv.insert(run.argv.end(), {"--rng-seed", rng_seed});
    run.argv.insert(run.argv.end(), extra.begin(), extra.end());
    static std::atomic<long> counter{0};
    const std::string err =
        (fs::path(config_.work_dir) / ("extra-" + std::to_string(++counter) + ".txt")).string();
    run.stderr_path = err;
    run.cancel = &stop_extras_;
    run.memory_limit = config_.memory_limit;
    run.deadline_seconds = deadline_seconds;
    ChildEnd end = run_child(run);
    result.ok = end.how == ChildEnd::How::exited && end.code == 0;
    if (!result.ok) result.message = read_text(err, 1u << 16) + describe(end, deadline_seconds);
    std::error_code ec;
    fs::remove(err, ec);
    return result;
}

}  // namespace acanthus
