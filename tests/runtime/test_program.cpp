// run_program: the generated program's command line, exit codes, and "no partial output".
// The pattern is written by hand the way the compiler generates one (dots of Appendix A).
#include <cairo.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <acanthus/body.hpp>
#include <acanthus/param.hpp>
#include <acanthus/program.hpp>
#include <acanthus/rule_call.hpp>
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "program/options.hpp"

namespace {

namespace fs = std::filesystem;
using namespace acanthus;
using namespace acanthus::detail;

// %param double dot_radius = 3.0;  %param bool explode = false;  %param int limit = 1000;
double dot_radius = 3.0;
bool explode = false;
int limit = 1000;
int dot_count = 0;

template <class T>
bool assign(T& target, std::string_view text, std::string& error) {
    T value{};
    if (!parse_param(text, value, error)) return false;
    target = value;
    return true;
}

struct seed final : Element {
    PointProxy p0;
    const ElementType& type() const override;
    std::size_t proxy_count() const override { return 1; }
    Proxy& proxy(std::size_t) override { return p0; }
};

struct dot final : Element {
    CircleProxy p0;
    int order = 0;
    const ElementType& type() const override;
    std::size_t proxy_count() const override { return 1; }
    Proxy& proxy(std::size_t) override { return p0; }
    void write_fields(FieldWriter& out) const override { out.field("order", order); }
};

Element* create_seed() { return new seed; }
Element* create_dot() { return new dot; }
const ElementType seed_type{"seed", {ProxyKind::point}, &create_seed, nullptr, 1};
// Its draw is set by the test that needs one.
ElementType dot_type{"dot", {ProxyKind::circle}, &create_dot, nullptr, 5};

// A %draw body that crashes in any process but the test's own: in the copies that draw
// --partial pictures.
pid_t test_process = ::getpid();
void crash_in_copies(Canvas&, const Element&) {
    if (::getpid() != test_process) std::abort();
}
// ... and one that never returns there (with --body-time-limit 0, no alarm stops it).
void hang_in_copies(Canvas&, const Element&) {
    if (::getpid() != test_process)
        for (;;) ::pause();
}
// ... and one that writes, in each copy, the copy's niceness to a file named by its pid.
std::string niceness_dir;
void record_niceness_in_copies(Canvas&, const Element&) {
    if (::getpid() == test_process) return;
    errno = 0;
    const int nice = ::getpriority(PRIO_PROCESS, 0);
    const auto now = std::chrono::steady_clock::now().time_since_epoch();
    const std::string name = niceness_dir + "/nice-" + std::to_string(::getpid());
    // (renamed into place: a copy stopped while writing leaves only its temporary)
    std::ofstream(name + ".tmp")
        << std::chrono::duration_cast<std::chrono::nanoseconds>(now).count() << " " << nice;
    std::rename((name + ".tmp").c_str(), name.c_str());
}
// ... and one that writes, in each copy, the size of a pixel it draws at.
void record_pixel_in_copies(Canvas& canvas, const Element&) {
    static bool written = false;
    if (::getpid() == test_process || written) return;
    written = true;
    const auto now = std::chrono::steady_clock::now().time_since_epoch();
    const std::string name = niceness_dir + "/pixel-" + std::to_string(::getpid());
    std::ofstream(name + ".tmp")
        << std::chrono::duration_cast<std::chrono::nanoseconds>(now).count() << " "
        << canvas.pixel();
    std::rename((name + ".tmp").c_str(), name.c_str());
}
// ... and one that fails in every process.
void throw_in_draw(Canvas&, const Element&) { throw std::runtime_error("drawn badly"); }
// ... and one that, in a copy (the one drawing the output beside the view), waits up to 20 s
// for the file `view_to_wait_for` and writes down whether it came.
std::string view_to_wait_for;
void wait_for_view_in_copies(Canvas&, const Element&) {
    static bool waited = false;
    if (::getpid() == test_process || waited) return;
    waited = true;
    bool seen = false;
    for (int i = 0; i < 2000 && !seen; ++i) {
        seen = fs::exists(view_to_wait_for);
        if (!seen) ::usleep(10000);
    }
    std::ofstream(view_to_wait_for + ".seen") << (seen ? "seen" : "not seen");
}
// ... and one that writes down, in a copy, whether `view_to_wait_for` was there when it began.
void note_view_in_copies(Canvas&, const Element&) {
    static bool noted = false;
    if (::getpid() == test_process || noted) return;
    noted = true;
    std::ofstream(view_to_wait_for + ".seen")
        << (fs::exists(view_to_wait_for) ? "seen" : "not seen");
}
// ... and one that crashes in copies and fails in the run after its first picture (one call a
// dot): the view is drawn, the output (its copy crashed) is not.
int draws_here = 0;
void fail_after_first_picture(Canvas&, const Element&) {
    if (::getpid() != test_process) std::abort();
    if (++draws_here > dot_count) throw std::runtime_error("second picture refused");
}
const ElementType& seed::type() const { return seed_type; }
const ElementType& dot::type() const { return dot_type; }

Result seed_rule(RuleCall& call_) {
    seed& parent = call_.parent<seed>();
    dot* c0 = call_.make_static<dot>();
    c0->p0.set(parent.p0, dot_radius);
    c0->order = dot_count++;
    parent.sterile = true;
    return SUCCESS;
}

Result dot_rule(RuleCall& call_) {
    using namespace acanthus::body;
    dot& parent = call_.parent<dot>();
    dot* c0 = call_.make_static<dot>();
    if (explode) throw std::runtime_error("exploded on purpose");
    if (goal().radius < 0.5 || dot_count >= limit) return FAILURE;
    double r = min(dot_radius, goal().radius);
    c0->p0.set(parent.p0.center.offset(goal().center - parent.p0.center, parent.p0.radius + r), r);
    c0->order = dot_count++;
    return SUCCESS;
}

Pattern make_pattern() {
    Pattern p;
    p.name = "testdots";
    p.file = "testdots.acr";
    p.types = {&seed_type, &dot_type};
    p.seed = &seed_type;
    p.rules.push_back(
        RuleInfo{"seed --> dot", 14, "testdots.acr", &seed_type, {&dot_type}, &seed_rule});
    p.rules.push_back(
        RuleInfo{"dot --> dot", 24, "testdots.acr", &dot_type, {&dot_type}, &dot_rule});
    p.params.push_back(
        ParamInfo{"dot_radius", "double", "3.0", 2,
                  [](std::string_view t, std::string& e) { return assign(dot_radius, t, e); },
                  [] { return format_param(dot_radius); }, "", ""});
    p.params.push_back(
        ParamInfo{"explode", "bool", "false", 3,
                  [](std::string_view t, std::string& e) { return assign(explode, t, e); },
                  [] { return format_param(explode); }, "", ""});
    p.params.push_back(
        ParamInfo{"limit", "int", "1000", 4,
                  [](std::string_view t, std::string& e) { return assign(limit, t, e); },
                  [] { return format_param(limit); }, "", ""});
    return p;
}

struct Outcome {
    int code = -1;
    std::string out, err;
};

class Program : public ::testing::Test {
  protected:
    void SetUp() override {
        dot_radius = 3.0;
        explode = false;
        limit = 1000;
        dot_count = 0;
        dot_type.draw = nullptr;
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() /
               ("acanthus-test-program-" + std::to_string(::getpid()) + "-" + info->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string path(const std::string& name) const { return (dir_ / name).string(); }

    Outcome run(std::vector<std::string> args) {
        dot_count = 0;
        args.insert(args.begin(), "testdots");
        std::vector<char*> argv;
        for (std::string& a : args) argv.push_back(a.data());
        argv.push_back(nullptr);
        Outcome o;
        ::testing::internal::CaptureStdout();
        ::testing::internal::CaptureStderr();
        o.code = run_program(pattern_, static_cast<int>(args.size()), argv.data());
        o.out = ::testing::internal::GetCapturedStdout();
        o.err = ::testing::internal::GetCapturedStderr();
        return o;
    }

    static std::string read(const std::string& p) {
        std::ifstream in(p, std::ios::binary);
        std::ostringstream s;
        s << in.rdbuf();
        return s.str();
    }
    static void write(const std::string& p, const std::string& text) {
        std::ofstream(p, std::ios::binary) << text;
    }
    // What the copies recorded in `dir` (when each drew, and its value), in the order they drew.
    template <class Value>
    static std::vector<std::pair<long long, Value>> copy_records(const std::string& dir) {
        std::vector<std::pair<long long, Value>> out;
        for (const auto& e : fs::directory_iterator(dir)) {
            if (e.path().extension() == ".tmp") continue;
            std::istringstream line(read(e.path().string()));
            long long when = 0;
            Value value{};
            if (line >> when >> value)
                out.emplace_back(when, value);
            else
                ADD_FAILURE() << "unreadable record " << e.path();
        }
        std::sort(out.begin(), out.end());  // (copies draw one at a time)
        return out;
    }
    // Every file in the test directory except `keep`.
    std::vector<std::string> files() const {
        std::vector<std::string> names;
        for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename());
        return names;
    }

    Pattern pattern_ = make_pattern();
    fs::path dir_;
};

TEST_F(Program, HelpExitsZeroAndShowsOptionsAndExamples) {
    Outcome o = run({"--help"});
    EXPECT_EQ(o.code, 0);
    for (const char* word : {"--region", "--seed", "--param", "--metrics", "--debug-frame",
                             "--frames", "Examples:", "dot_radius", "Exit status"})
        EXPECT_NE(o.out.find(word), std::string::npos) << word;
}

TEST_F(Program, VersionExitsZero) {
    Outcome o = run({"--version"});
    EXPECT_EQ(o.code, 0);
    EXPECT_NE(o.out.find("Acanthus"), std::string::npos);
}

TEST_F(Program, UnknownOptionIsUsageError) {
    Outcome o = run({"--bogus", "-o", path("out.svg")});
    EXPECT_EQ(o.code, 2);
    EXPECT_EQ(o.err.rfind("testdots: error: ", 0), 0u) << o.err;
    EXPECT_NE(o.err.find("--bogus"), std::string::npos);
    EXPECT_TRUE(files().empty());
}

TEST_F(Program, MalformedValuesAreUsageErrors) {
    for (std::vector<std::string> args : {std::vector<std::string>{"--seed", "12"},
                                          {"--seed", "1,x"},
                                          {"--style", "dotted"},
                                          {"--resolution", "0"},
                                          {"--resolution", "16385"},
                                          {"--distance", "taxicab"},
                                          {"--width", "-3"},
                                          {"--background", "notacolour"},
                                          {"--param", "dot_radius"},
                                          {"--debug-frame", "0", "a.png"},
                                          {"--debug-frame", "3", "a.svg"},
                                          {"--every", "3"},
                                          {"--partial-every", "0.5"},
                                          {"--partial", path("partial.pdf")},
                                          {"--view", path("view.svg")},
                                          {"--view", path("v.png"), "--view-size", "800"},
                                          {"--view", path("v.png"), "--view-size", "8x800"},
                                          {"--view", path("v.png"), "--view-size", "800x9000"},
                                          {"--partial", path("p.svg"), "--partial-every", "0"},
                                          {"--progress", "--quiet"},
                                          {"--metrics", "-o", "-"},
                                          {"--epsilon", "nan"}}) {
        args.push_back("-o");
        args.push_back(path("out.svg"));
        Outcome o = run(args);
        EXPECT_EQ(o.code, 2) << args[0] << " " << args[1] << "\n" << o.err;
    }
    EXPECT_TRUE(files().empty());
}

TEST_F(Program, BadParameterValueNamesTheParameter) {
    write(path("out.svg"), "previous");
    Outcome o = run({"--param", "dot_radius=big", "-o", path("out.svg")});
    EXPECT_EQ(o.code, 1);
    EXPECT_NE(o.err.find("dot_radius"), std::string::npos) << o.err;
    EXPECT_EQ(read(path("out.svg")), "previous");
}

TEST_F(Program, UnknownParameterIsBadInput) {
    Outcome o = run({"--param", "colour=red", "-o", path("out.svg")});
    EXPECT_EQ(o.code, 1);
    EXPECT_NE(o.err.find("'colour'"), std::string::npos) << o.err;
    EXPECT_NE(o.err.find("dot_radius"), std::string::npos) << o.err;  // lists what exists
    EXPECT_TRUE(files().empty());
}

TEST_F(Program, ListParamsShowsDefaultAndCurrent) {
    Outcome o = run({"--param", "dot_radius=2.5", "--list-params"});
    EXPECT_EQ(o.code, 0);
    std::istringstream lines(o.out);
    std::string header, row;
    std::getline(lines, header);
    std::getline(lines, row);
    EXPECT_NE(header.find("current"), std::string::npos);
    EXPECT_NE(row.find("dot_radius"), std::string::npos);
    EXPECT_NE(row.find("3.0"), std::string::npos);
    EXPECT_NE(row.find("2.5"), std::string::npos);
    EXPECT_TRUE(files().empty());
}

TEST_F(Program, BadRegionFileIsNamedAndNothingIsWritten) {
    write(path("bad.svg"), "<svg xmlns='http://www.w3.org/2000/svg'><rect width='10'");
    write(path("out.png"), "previous");
    Outcome o = run({"--region", path("bad.svg"), "-o", path("out.png")});
    EXPECT_EQ(o.code, 1);
    EXPECT_NE(o.err.find("bad.svg"), std::string::npos) << o.err;
    EXPECT_EQ(read(path("out.png")), "previous");

    o = run({"--region", path("missing.svg"), "-o", path("out2.svg")});
    EXPECT_EQ(o.code, 1);
    EXPECT_NE(o.err.find("missing.svg"), std::string::npos) << o.err;
    EXPECT_FALSE(fs::exists(path("out2.svg")));
}

TEST_F(Program, UnknownOutputExtensionIsUsageError) {
    Outcome o = run({"--region", "rect:100,100", "-o", path("out.gif")});
    EXPECT_EQ(o.code, 2);
    EXPECT_NE(o.err.find("out.gif"), std::string::npos) << o.err;
    EXPECT_TRUE(files().empty());
}

TEST_F(Program, MissingOutputDirectoryIsRefusedBeforeGrowing) {
    Outcome o = run({"--region", "rect:100,100", "-o", path("no/such/dir/out.svg")});
    EXPECT_EQ(o.code, 1);
    EXPECT_NE(o.err.find("no/such/dir"), std::string::npos) << o.err;
}

TEST_F(Program, SeedOutsideRegionIsBadInput) {
    Outcome o = run({"--region", "rect:100,50", "--seed", "150,20", "-o", path("out.svg")});
    EXPECT_EQ(o.code, 1);
    EXPECT_NE(o.err.find("150,20"), std::string::npos) << o.err;
    EXPECT_TRUE(files().empty());
}

// A buffer larger than the memory the process may use is refused before it is allocated, with
// the estimate: exit 1, no output. (The address-space limit is lowered for this run only.)
TEST_F(Program, ResolutionTooLargeForMemoryIsBadInput) {
    rlimit saved{};
    ASSERT_EQ(getrlimit(RLIMIT_AS, &saved), 0);
    std::ifstream status("/proc/self/status");
    std::uint64_t vm_kb = 0;
    for (std::string line; std::getline(status, line);)
        if (line.rfind("VmSize:", 0) == 0) vm_kb = std::stoull(line.substr(7));
    rlimit low = saved;
    low.rlim_cur = vm_kb * 1024 + (512ull << 20);  // 512 MB of room; 16384 px needs ~4 GB
    if (saved.rlim_cur != RLIM_INFINITY && saved.rlim_cur < low.rlim_cur)
        low.rlim_cur = saved.rlim_cur;
    ASSERT_EQ(setrlimit(RLIMIT_AS, &low), 0);
    Outcome o = run({"--region", "rect:100,100", "--resolution", "16384", "-o", path("out.svg"),
                     "--json", path("tree.json")});
    ASSERT_EQ(setrlimit(RLIMIT_AS, &saved), 0);
    EXPECT_EQ(o.code, 1) << o.err;
    EXPECT_NE(o.err.find("--resolution 16384 needs about"), std::string::npos) << o.err;
    EXPECT_NE(o.err.find("use a lower --resolution"), std::string::npos) << o.err;
    EXPECT_TRUE(files().empty());
}

TEST_F(Program, RuleFailureExitsThreeNamingRuleAndLine) {
    write(path("out.svg"), "previous");
    Outcome o = run({"--region", "circle:50", "--param", "explode=true", "-o", path("out.svg"),
                     "--json", path("tree.json")});
    EXPECT_EQ(o.code, 3);
    EXPECT_NE(o.err.find("testdots.acr:24"), std::string::npos) << o.err;
    EXPECT_NE(o.err.find("dot --> dot"), std::string::npos) << o.err;
    EXPECT_EQ(read(path("out.svg")), "previous");
    EXPECT_FALSE(fs::exists(path("tree.json")));
}

TEST_F(Program, GrowsRendersAndReportsMetrics) {
    Outcome o = run({"--region", "ellipse:60,40", "--rng-seed", "3", "-o", path("out.svg"),
                     "--json", path("tree.json"), "--metrics", "--resolution", "128"});
    ASSERT_EQ(o.code, 0) << o.err;
    EXPECT_NE(read(path("out.svg")).find("<svg"), std::string::npos);

    nlohmann::json metrics = nlohmann::json::parse(o.out);
    EXPECT_GT(metrics.at("elements").get<long>(), 10);
    EXPECT_EQ(metrics.at("engine"), "incremental");
    EXPECT_GT(metrics.at("coverage").get<double>(), 0.1);
    EXPECT_EQ(metrics.at("rules").size(), 2u);

    nlohmann::json tree = nlohmann::json::parse(read(path("tree.json")));
    EXPECT_EQ(tree.at("elements").size(), metrics.at("elements").get<std::size_t>());
    EXPECT_EQ(tree.at("elements")[0].at("type"), "seed");
}

TEST_F(Program, SameSeedSameBytes) {
    ASSERT_EQ(run({"--region", "circle:50", "--resolution", "128", "-o", path("a.svg")}).code, 0);
    ASSERT_EQ(run({"--region", "circle:50", "--resolution", "128", "-o", path("b.svg")}).code, 0);
    EXPECT_EQ(read(path("a.svg")), read(path("b.svg")));
}

TEST_F(Program, ParamChangesTheResult) {
    ASSERT_EQ(run({"--region", "circle:50", "--resolution", "128", "--json", path("a.json"), "-o",
                   path("a.svg")})
                  .code,
              0);
    ASSERT_EQ(run({"--region", "circle:50", "--resolution", "128", "--param", "limit=5", "--json",
                   path("b.json"), "-o", path("b.svg")})
                  .code,
              0);
    auto a = nlohmann::json::parse(read(path("a.json"))).at("elements").size();
    auto b = nlohmann::json::parse(read(path("b.json"))).at("elements").size();
    EXPECT_EQ(b, 6u);  // the seed and five dots
    EXPECT_GT(a, b);
}

TEST_F(Program, SvgToStdout) {
    Outcome o = run({"--region", "rect:60,60", "--resolution", "64", "-o", "-"});
    ASSERT_EQ(o.code, 0) << o.err;
    EXPECT_NE(o.out.find("<svg"), std::string::npos);
}

TEST_F(Program, DebugFrameAndGrowthFrames) {
    Outcome o = run({"--region", "circle:50", "--resolution", "128", "--param", "limit=20", "-o",
                     path("out.png"), "--debug-frame", "3", path("debug.png"), "--frames",
                     path("frames"), "--every", "5"});
    ASSERT_EQ(o.code, 0) << o.err;
    EXPECT_TRUE(fs::exists(path("out.png")));
    EXPECT_EQ(read(path("debug.png")).substr(0, 4), "\x89PNG");
    EXPECT_TRUE(fs::exists(path("frames/frame-000001.png")));
    EXPECT_TRUE(fs::exists(path("frames/frame-000002.png")));
}

// --partial: the growth so far, published while the run goes on (outside the run's
// all-or-none outputs), each a whole SVG with no more elements than the finished picture.
TEST_F(Program, PartialPicturesWhileGrowing) {
    Outcome o = run({"--region", "circle:400", "--resolution", "512", "--param", "limit=3000",
                     "--param", "dot_radius=2", "--partial", path("partial.svg"), "--partial-every",
                     "0.01", "-o", path("out.svg")});
    ASSERT_EQ(o.code, 0) << o.err;
    const std::string partial = read(path("partial.svg"));
    const std::string done = read(path("out.svg"));
    ASSERT_NE(partial.find("</svg>"), std::string::npos);
    const auto circles = [](const std::string& svg) {
        std::size_t n = 0;
        for (std::size_t at = svg.find("<circle"); at != std::string::npos;
             at = svg.find("<circle", at + 1))
            ++n;
        return n;
    };
    EXPECT_GT(circles(partial), 0u);
    EXPECT_LE(circles(partial), circles(done));
    for (const std::string& f : files())  // no temporary left beside them
        EXPECT_TRUE(f == "partial.svg" || f == "out.svg") << f;
}

// --view: the finished picture as PNG too, the SVG's page fitted into --view-size pixels (a
// region twice as wide as high in 600 x 600: 600 wide); a PNG --partial the same way.
TEST_F(Program, ViewPictureFitsTheViewSize) {
    Outcome o = run({"--region", "rect:400,200", "--param", "limit=300", "--partial",
                     path("partial.png"), "--partial-every", "0.01", "--view", path("view.png"),
                     "--view-size", "600x600", "-o", path("out.svg")});
    ASSERT_EQ(o.code, 0) << o.err;
    const auto size = [](const std::string& png) {
        const auto word = [&](std::size_t at) {
            long v = 0;
            for (std::size_t i = 0; i < 4; ++i)
                v = v << 8 | static_cast<unsigned char>(png.at(at + i));
            return v;
        };
        return std::make_pair(word(16), word(20));
    };
    const std::string view = read(path("view.png"));
    ASSERT_EQ(view.substr(0, 4), "\x89PNG");
    const auto [width, height] = size(view);
    EXPECT_EQ(width, 600);
    EXPECT_NEAR(height, 600.0 * (200 + 16) / (400 + 16), 1.0);  // the page's 2% margins
    if (fs::exists(path("partial.png"))) {                      // (the first at half the size)
        const long partial_width = size(read(path("partial.png"))).first;
        EXPECT_TRUE(partial_width == 600 || partial_width == 300) << partial_width;
    }
    // A tall page fits by its height.
    o = run({"--region", "rect:100,400", "--param", "limit=50", "--view", path("tall.png"),
             "--view-size", "600x300", "-o", path("tall.svg")});
    ASSERT_EQ(o.code, 0) << o.err;
    EXPECT_EQ(size(read(path("tall.png"))).second, 300);
    // Its pixels stored (not deflated): the same picture as an ordinary PNG of that width.
    o = run({"--region", "rect:400,200", "--param", "limit=300", "--background", "#80ff8040",
             "--view", path("same.png"), "--view-size", "800x2000", "-o", path("plain.png")});
    ASSERT_EQ(o.code, 0) << o.err;
    EXPECT_GT(read(path("same.png")).size(), read(path("plain.png")).size());
    cairo_surface_t* a = cairo_image_surface_create_from_png(path("same.png").c_str());
    cairo_surface_t* b = cairo_image_surface_create_from_png(path("plain.png").c_str());
    ASSERT_EQ(cairo_surface_status(a), CAIRO_STATUS_SUCCESS);
    ASSERT_EQ(cairo_surface_status(b), CAIRO_STATUS_SUCCESS);
    const int stride = cairo_image_surface_get_stride(a), rows = cairo_image_surface_get_height(a);
    ASSERT_EQ(cairo_image_surface_get_width(a), 800);
    ASSERT_EQ(rows, cairo_image_surface_get_height(b));
    EXPECT_EQ(std::memcmp(cairo_image_surface_get_data(a), cairo_image_surface_get_data(b),
                          static_cast<std::size_t>(stride) * rows),
              0);
    cairo_surface_destroy(a);
    cairo_surface_destroy(b);
}

// Each partial picture is drawn by a copy of the program while the growth goes on: a copy
// that crashes costs that picture only, not the run, its outputs or a crash report.
TEST_F(Program, PartialPictureCopyCrashingLeavesTheRunAlone) {
    dot_type.draw = &crash_in_copies;
    Outcome o = run({"--region", "circle:400", "--resolution", "512", "--param", "limit=3000",
                     "--param", "dot_radius=2", "--partial", path("partial.svg"), "--partial-every",
                     "0.01", "-o", path("out.svg")});
    ASSERT_EQ(o.code, 0) << o.err;
    EXPECT_EQ(o.err.find("crash"), std::string::npos) << o.err;
    EXPECT_EQ(o.err.find("abort"), std::string::npos) << o.err;
    EXPECT_NE(read(path("out.svg")).find("</svg>"), std::string::npos);
    for (const std::string& f : files())  // no picture, and nothing the copies left
        EXPECT_EQ(f, "out.svg");
}

// A copy that never ends is stopped once the finished picture is drawn: the run ends, with
// its outputs and nothing of the copy's left (it waited for the first copy forever before).
TEST_F(Program, PartialPictureCopyHangingIsStopped) {
    dot_type.draw = &hang_in_copies;
    alarm(60);  // the failure this guards against is a run that never returns
    Outcome o = run({"--region", "circle:400", "--resolution", "512", "--param", "limit=3000",
                     "--param", "dot_radius=2", "--partial", path("partial.svg"), "--partial-every",
                     "0.01", "--body-time-limit", "0", "-o", path("out.svg")});
    alarm(0);
    dot_type.draw = nullptr;
    ASSERT_EQ(o.code, 0) << o.err;
    EXPECT_NE(read(path("out.svg")).find("</svg>"), std::string::npos);
    for (const std::string& f : files())  // no picture, and nothing the copy left
        EXPECT_EQ(f, "out.svg");
}

// The copies drawing partial pictures after the first run at a lower priority than the run
// (the growth keeps its core); the first, the viewer's first look, at the run's.
TEST_F(Program, LaterPartialPictureCopiesRunNicer) {
    errno = 0;
    const int run_nice = ::getpriority(PRIO_PROCESS, 0);
    ASSERT_EQ(errno, 0);
    if (run_nice >= 19) GTEST_SKIP() << "already at the lowest priority";
    fs::create_directories(path("nice"));
    niceness_dir = path("nice");
    dot_type.draw = &record_niceness_in_copies;
    Outcome o = run({"--region", "circle:400", "--resolution", "512", "--param", "limit=6000",
                     "--param", "dot_radius=2", "--partial", path("partial.svg"), "--partial-every",
                     "0.01", "-o", path("out.svg")});
    dot_type.draw = nullptr;
    ASSERT_EQ(o.code, 0) << o.err;
    const auto copies = copy_records<int>(path("nice"));  // (when it drew, niceness)
    ASSERT_GE(copies.size(), 2u) << "too few partial pictures to compare";
    EXPECT_EQ(copies.front().second, run_nice);
    for (std::size_t i = 1; i < copies.size(); ++i)
        EXPECT_GT(copies[i].second, run_nice) << "copy " << i;
}

// The copy drawing the output beside the view runs at a lower priority than the run: a viewer
// waits for the view alone.
TEST_F(Program, OutputCopyBesideTheViewRunsNicer) {
    errno = 0;
    const int run_nice = ::getpriority(PRIO_PROCESS, 0);
    ASSERT_EQ(errno, 0);
    if (run_nice >= 19) GTEST_SKIP() << "already at the lowest priority";
    fs::create_directories(path("nice"));
    niceness_dir = path("nice");
    dot_type.draw = &record_niceness_in_copies;
    Outcome o = run({"--region", "circle:200", "--resolution", "256", "--param", "limit=200",
                     "--view", path("view.png"), "--view-size", "300x300", "-o", path("out.svg")});
    dot_type.draw = nullptr;
    ASSERT_EQ(o.code, 0) << o.err;
    const auto copies = copy_records<int>(path("nice"));  // (when it drew, niceness)
    ASSERT_EQ(copies.size(), 1u);
    EXPECT_GT(copies.front().second, run_nice);
}

// PNG partial pictures are drawn at half the view's size (the viewer scales them up), the
// first (a viewer's first look) and the later ones alike; the view at its size.
TEST_F(Program, PartialPicturesAtHalfTheViewSize) {
    fs::create_directories(path("pixels"));
    niceness_dir = path("pixels");
    dot_type.draw = &record_pixel_in_copies;
    Outcome o =
        run({"--region", "circle:400", "--resolution", "512", "--param", "limit=6000", "--param",
             "dot_radius=2", "--partial", path("partial.png"), "--partial-every", "0.01",
             "--view-size", "600x600", "--view", path("view.png"), "-o", path("out.svg")});
    dot_type.draw = nullptr;
    ASSERT_EQ(o.code, 0) << o.err;
    const auto copies = copy_records<double>(path("pixels"));  // (when it drew, its pixel)
    // (the last copy draws the SVG output at the page's own size)
    ASSERT_GE(copies.size(), 3u) << "too few partial pictures to compare";
    for (std::size_t i = 1; i + 1 < copies.size(); ++i)
        EXPECT_NEAR(copies.front().second, copies[i].second, 0.02 * copies[i].second) << i;
    // The last partial picture and the view: PNG widths (IHDR) half and whole.
    const auto width = [](const std::string& png) {
        if (png.size() < 24) return 0u;
        unsigned w = 0;
        for (std::size_t k = 16; k < 20; ++k) w = (w << 8) | static_cast<unsigned char>(png[k]);
        return w;
    };
    const unsigned view = width(read(path("view.png")));
    EXPECT_GT(view, 500u);
    EXPECT_NEAR(width(read(path("partial.png"))), view / 2.0, 1.0);
}

// With --view, the output is drawn by a copy of the program while the run draws the view: the
// same file as without --view; a copy that crashes leaves the drawing to the run.
TEST_F(Program, OutputDrawnByACopyIsTheRunsPicture) {
    const auto args = [&](const std::string& out, bool view) {
        std::vector<std::string> a{"--region", "circle:200", "--resolution", "256",
                                   "--param",  "limit=200",  "-o",           path(out)};
        if (view) a.insert(a.end(), {"--view", path("view.png"), "--view-size", "300x300"});
        return a;
    };
    using Draw = void (*)(Canvas&, const Element&);
    for (const Draw draw : {Draw(nullptr), Draw(&crash_in_copies)}) {
        dot_type.draw = draw;
        Outcome o = run(args("plain.svg", false));
        ASSERT_EQ(o.code, 0) << o.err;
        o = run(args("out.svg", true));
        dot_type.draw = nullptr;
        ASSERT_EQ(o.code, 0) << o.err;
        EXPECT_EQ(o.err.find("abort"), std::string::npos) << o.err;
        EXPECT_NE(read(path("out.svg")).find("</svg>"), std::string::npos);
        EXPECT_EQ(read(path("out.svg")), read(path("plain.svg")));
        EXPECT_EQ(read(path("view.png")).substr(0, 4), "\x89PNG");
        for (const std::string& f : files())  // nothing the copy left
            EXPECT_TRUE(f == "plain.svg" || f == "out.svg" || f == "view.png") << f;
    }
}

// The view is published as soon as it is drawn, while the output is still being drawn (a
// viewer shows the finished picture without waiting for the rest of the run).
TEST_F(Program, ViewPublishedBeforeTheRunEnds) {
    view_to_wait_for = path("view.png");
    dot_type.draw = &wait_for_view_in_copies;
    Outcome o = run({"--region", "circle:200", "--resolution", "256", "--param", "limit=200",
                     "--view", path("view.png"), "--view-size", "300x300", "-o", path("out.svg")});
    dot_type.draw = nullptr;
    ASSERT_EQ(o.code, 0) << o.err;
    EXPECT_EQ(read(path("view.png.seen")), "seen");
    EXPECT_NE(read(path("out.svg")).find("</svg>"), std::string::npos);
}

// The output's copy begins once the view is published: drawn beside it, the copy and the
// coverage took a share of the processor the view needed.
TEST_F(Program, OutputCopyBeginsAfterTheViewIsPublished) {
    view_to_wait_for = path("view.png");
    dot_type.draw = &note_view_in_copies;
    Outcome o =
        run({"--region", "circle:200", "--resolution", "256", "--param", "limit=200", "--view",
             path("view.png"), "--view-size", "300x300", "-o", path("out.svg"), "--metrics"});
    dot_type.draw = nullptr;
    ASSERT_EQ(o.code, 0) << o.err;
    EXPECT_EQ(read(path("view.png.seen")), "seen");
    EXPECT_NE(o.out.find("\"coverage\""), std::string::npos) << o.out;
}

// A run that fails after its view was published removes it: all or none still.
TEST_F(Program, ViewPublishedThenRunFailingLeavesNoFile) {
    draws_here = 0;
    dot_type.draw = &fail_after_first_picture;
    Outcome o = run({"--region", "circle:100", "--resolution", "128", "--param", "limit=20",
                     "--view", path("view.png"), "--view-size", "300x300", "-o", path("out.svg")});
    dot_type.draw = nullptr;
    EXPECT_NE(o.code, 0);
    EXPECT_GT(draws_here, dot_count);  // the view was drawn
    EXPECT_NE(o.err.find("second picture refused"), std::string::npos) << o.err;
    EXPECT_TRUE(files().empty());
}

// A %draw that fails everywhere is reported once, by the run, and leaves no file.
TEST_F(Program, OutputCopyFailingEverywhereIsReportedOnce) {
    dot_type.draw = &throw_in_draw;
    Outcome o = run({"--region", "circle:100", "--resolution", "128", "--param", "limit=20",
                     "--view", path("view.png"), "--view-size", "300x300", "-o", path("out.svg")});
    dot_type.draw = nullptr;
    EXPECT_NE(o.code, 0);
    const std::size_t first = o.err.find("drawn badly");
    ASSERT_NE(first, std::string::npos) << o.err;
    EXPECT_EQ(o.err.find("drawn badly", first + 1), std::string::npos) << o.err;
    EXPECT_TRUE(files().empty());
}

TEST_F(Program, DebugFrameAfterTheEndWarns) {
    Outcome o = run({"--region", "circle:50", "--resolution", "64", "--param", "limit=3", "-o",
                     path("out.svg"), "--debug-frame", "100000", path("debug.png")});
    EXPECT_EQ(o.code, 0) << o.err;
    EXPECT_NE(o.err.find("warning"), std::string::npos);
    EXPECT_FALSE(fs::exists(path("debug.png")));
}

TEST(ParseSeed, AcceptsTwoNumbersOnly) {
    using acanthus::detail::parse_seed;
    ASSERT_TRUE(parse_seed("10,20.5"));
    EXPECT_EQ(*parse_seed("10,20.5"), (Point{10, 20.5}));
    EXPECT_EQ(*parse_seed(" -1e1 , +3"), (Point{-10, 3}));
    EXPECT_FALSE(parse_seed("10"));
    EXPECT_FALSE(parse_seed("10,"));
    EXPECT_FALSE(parse_seed("a,b"));
    EXPECT_FALSE(parse_seed("1,2,3"));
    EXPECT_FALSE(parse_seed("inf,2"));
}

}  // namespace
