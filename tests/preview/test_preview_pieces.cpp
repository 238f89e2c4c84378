// The preview's pure pieces: diagnostics parsed from compiler output, guides written from
// strokes, the stroke tools libraries declare, program options split into the page's settings, the
// server's connection threads and program slots, the file watcher, the rule code's build.
#include <dlfcn.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <future>
#include <mutex>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "compilation.hpp"
#include "fixtures/temp_dir.hpp"
#include "server/diagnostics.hpp"
#include "server/guides.hpp"
#include "server/limits.hpp"
#include "server/settings.hpp"
#include "server/stroke_tools.hpp"
#include "server/watcher.hpp"
#include "toolchain/precompiled_prelude.hpp"
#include "toolchain/process.hpp"
#include "toolchain/program_build.hpp"
#include "toolchain/toolchain.hpp"

namespace acanthus {
namespace {

TEST(PreviewDiagnostics, AcanthusAndGccLinesNotesSkipped) {
    const std::string out =
        "dots.acr:26:1: error: unterminated '%rule' section\n"
        "   26 | %rule\n"
        "      | ^~~~~\n"
        "dots.acr:38:1: note: expected '%endrule' before '%rule'\n"
        "dots.acr: In function 'acanthus::Result acr_rule_0(acanthus::RuleCall&)':\n"
        "dir/my file.acr:30:41: error: expected ';' before 'x'\n"
        "acanthus: error: cannot read 'x.acr': no such file\n";
    auto d = parse_diagnostics(out);
    ASSERT_EQ(d.size(), 3u);
    EXPECT_EQ(d[0].file, "dots.acr");
    EXPECT_EQ(d[0].line, 26);
    EXPECT_EQ(d[0].column, 1);
    EXPECT_EQ(d[0].message, "unterminated '%rule' section");
    EXPECT_EQ(d[1].file, "dir/my file.acr");
    EXPECT_EQ(d[1].column, 41);
    EXPECT_EQ(d[2].file, "acanthus");
    EXPECT_EQ(d[2].line, 0);
}

// A rule file whose line 2 is a body line the compiler rewrote ($goal).
std::string rule_file_with_body_line(const acanthus::test::TempDir& dir) {
    const std::string path = dir / "in_rule_source.acr";
    std::ofstream(path) << "%rule\n    double r = min( max_radius, $goal.radius ) oops;\n";
    return path;
}

TEST(PreviewDiagnostics, ClangErrorsShowTheRuleLineAndItsColumn) {
    const acanthus::test::TempDir dir("diagnostics");
    const std::string rule = rule_file_with_body_line(dir);
    const std::string out =
        rule +
        ":2:64: error: expected ';' at end of declaration\n"
        "    double r = min( max_radius, acanthus::body::goal().radius ) oops;\n"
        "                                                               ^\n"
        "                                                               ;\n"
        "/tmp/acanthus-build.Ab12Cd/in_rule_source.cpp:90:5: note: declared here\n"
        "    int goal();\n"
        "    ^\n"
        "1 error generated.\n";
    EXPECT_EQ(in_rule_source(out), rule +
                                       ":2:47: error: expected ';' at end of declaration\n"
                                       "    double r = min( max_radius, $goal.radius ) oops;\n"
                                       "                                              ^\n"
                                       "1 error generated.\n");
    // A column inside the rewritten part goes to its start in the rule file.
    const std::string inside =
        rule +
        ":2:40: error: no member named 'goal'\n"
        "    double r = min( max_radius, acanthus::body::goal().radius ) oops;\n";
    EXPECT_NE(in_rule_source(inside).find(":2:33: error"), std::string::npos);
}

TEST(PreviewDiagnostics, GccErrorsShowTheRuleLineAndItsColumn) {
    const acanthus::test::TempDir dir("diagnostics");
    const std::string rule = rule_file_with_body_line(dir);
    const std::string out =
        rule +
        ":2:64: error: expected ',' or ';' before 'oops'\n"
        "    2 |     double r = min( max_radius, acanthus::body::goal().radius ) oops;\n"
        "      |                                                               ^~~~~\n"
        "In file included from /tmp/acanthus-build.Xy/p.cpp:1:\n";
    EXPECT_EQ(in_rule_source(out),
              rule +
                  ":2:47: error: expected ',' or ';' before 'oops'\n"
                  "    2 |     double r = min( max_radius, $goal.radius ) oops;\n"
                  "      |                                               ^\n");
    // Lines the compiler printed from the rule file itself are left as they are.
    const std::string own = rule + ":1:1: error: x\n%rule\n^\n";
    EXPECT_EQ(in_rule_source(own), own);
}

TEST(PreviewDiagnostics, ProgramRuleFailureLocatedAtTheRule) {
    auto d = parse_diagnostics(
        "dots: error: dots.acr:26: rule 'seed --> dot': still running after 10 s\n");
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].file, "dots.acr");
    EXPECT_EQ(d[0].line, 26);
    EXPECT_EQ(d[0].message, "rule 'seed --> dot': still running after 10 s");
}

TEST(PreviewDiagnostics, SourceAroundEachErrorOfTheRuleFilesOnly) {
    const acanthus::test::TempDir temp("diagnostics");
    const std::string dir = temp.path().string();
    const std::string rules = dir + "/context.acr", other = dir + "/other.acr";
    {
        std::ofstream out(rules);
        for (int i = 1; i <= 9; ++i) out << "line " << i << "\n";
        std::ofstream(other) << "secret\n";
    }
    std::vector<PreviewDiagnostic> d = {{rules, 5, 3, "bad"},
                                        {rules, 1, 1, "first"},
                                        {rules, 9, 2, "last"},
                                        {other, 1, 1, "not ours"},
                                        {rules, 0, 0, "unlocated"}};
    // Named another way (`dir/./`): the same file.
    add_source_context(d, {dir + "/./context.acr"});
    EXPECT_EQ(d[0].context_first, 3);
    EXPECT_EQ(d[0].context,
              (std::vector<std::string>{"line 3", "line 4", "line 5", "line 6", "line 7"}));
    EXPECT_EQ(d[1].context_first, 1);
    EXPECT_EQ(d[1].context, (std::vector<std::string>{"line 1", "line 2", "line 3"}));
    EXPECT_EQ(d[2].context, (std::vector<std::string>{"line 7", "line 8", "line 9"}));
    EXPECT_TRUE(d[3].context.empty());  // not one of the rule files: never read
    EXPECT_TRUE(d[4].context.empty());
}

TEST(PreviewEditor, PlaceholdersOrTheLineConvention) {
    EXPECT_EQ(editor_command("code -g {file}:{line}:{column}", "/r/a b.acr", 12, 5),
              (std::vector<std::string>{"code", "-g", "/r/a b.acr:12:5"}));
    EXPECT_EQ(editor_command("vim", "/r/a.acr", 7, 1),
              (std::vector<std::string>{"vim", "+7", "/r/a.acr"}));
    // Quotes keep words together; nothing is expanded (no shell).
    EXPECT_EQ(
        editor_command("'/opt/my editor/bin' --line \"{line}\" $HOME {file}", "/r/{line}.acr", 3,
                       1),
        (std::vector<std::string>{"/opt/my editor/bin", "--line", "3", "$HOME", "/r/{line}.acr"}));
    EXPECT_TRUE(editor_command("   ", "/r/a.acr", 1, 1).empty());
}

// A declaration like the growth library's registration makes (stdlib/growth/CMakeLists.txt).
StrokeTool guides_tool() {
    std::vector<StrokeTool> tools;
    std::string error;
    EXPECT_TRUE(parse_stroke_tools(R"([{"library": "guided", "file_param": "guided_file",
        "mode_param": "guided_mode", "kinds": ["flow", "boundary", "spray"],
        "width_kinds": ["spray"], "mode_kinds": ["flow"]}])",
                                   tools, error))
        << error;
    return tools.empty() ? StrokeTool{} : tools[0];
}

TEST(PreviewGuides, StrokesBecomePolylinesOfTheirClass) {
    auto body = nlohmann::json::parse(R"({"strokes": [
        {"kind": "flow", "points": [[0, 0], [10, 5]]},
        {"kind": "spray", "width": 12.5, "points": [[1, 1], [2, 2], [3, 3]]}]})");
    std::string svg, error;
    std::vector<std::string> kinds;
    ASSERT_TRUE(guides_svg(body, guides_tool(), svg, kinds, error)) << error;
    EXPECT_NE(svg.find("<polyline class=\"flow\""), std::string::npos);
    EXPECT_NE(svg.find("class=\"spray\" fill=\"none\" stroke=\"#c63\" stroke-width=\"12.5\""),
              std::string::npos);
    EXPECT_NE(svg.find("points=\"0,0 10,5 \""), std::string::npos);
    EXPECT_EQ(kinds, (std::vector<std::string>{"flow", "spray"}));
    EXPECT_EQ(guides_tool().mode_for(kinds), "flow");
    EXPECT_EQ(guides_tool().mode_for({"spray", "boundary"}), "");
}

TEST(PreviewGuides, BadStrokesRefused) {
    std::string svg, error;
    std::vector<std::string> kinds;
    for (const char* bad : {R"({})", R"({"strokes": [{"kind": "paint", "points": [[0,0],[1,1]]}]})",
                            R"({"strokes": [{"kind": "flow", "points": [[0,0]]}]})",
                            R"({"strokes": [{"kind": "spray", "points": [[0,0],[1,1]]}]})",
                            R"({"strokes": [{"kind": "flow", "points": [[0,0],[1e12,1]]}]})",
                            R"({"strokes": [{"kind": "flow", "points": [[0,0],["a",1]]}]})"}) {
        EXPECT_FALSE(guides_svg(nlohmann::json::parse(bad), guides_tool(), svg, kinds, error))
            << bad;
        EXPECT_FALSE(error.empty());
    }
    EXPECT_TRUE(
        guides_svg(nlohmann::json::parse(R"({"strokes": []})"), guides_tool(), svg, kinds, error));
    EXPECT_TRUE(svg.empty());
}

TEST(PreviewStrokeTools, BadDeclarationsRefused) {
    std::vector<StrokeTool> tools;
    for (
        const char* bad :
        {R"({})", R"([{"kinds": ["a"], "width_kinds": [], "mode_kinds": []}])",
         R"([{"library": "x", "file_param": "f", "kinds": [], "width_kinds": [], "mode_kinds": []}])",
         R"([{"library": "x", "file_param": "f", "kinds": ["a"], "width_kinds": ["b"],
               "mode_kinds": []}])",
         R"([{"library": "x", "file_param": "f g", "kinds": ["a"], "width_kinds": [],
               "mode_kinds": []}])",
         "not json"}) {
        std::string error;
        EXPECT_FALSE(parse_stroke_tools(bad, tools, error)) << bad;
        EXPECT_FALSE(error.empty()) << bad;
    }
    std::string error;
    EXPECT_TRUE(parse_stroke_tools("[]", tools, error));
    EXPECT_TRUE(tools.empty());
}

// Only a program that imports the library, and has its parameter, gets its tools: a rule file
// that declares a parameter of the same name itself does not.
TEST(PreviewStrokeTools, OnlyForProgramsImportingTheLibrary) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("acanthus-tools-" + std::to_string(getpid()));
    fs::create_directories(dir / "stdlib");
    const std::string stdlib = (dir / "stdlib").string();
    const std::string library = (dir / "stdlib" / "guided.acr").string();
    const std::string rule = (dir / "rule.acr").string();
    const std::vector<StrokeTool> declared = {guides_tool()};
    const std::vector<ParamSummary> with_param = {{"radius", "double", "1", "", ""},
                                                  {"guided_file", "std::string", "\"\"", "", ""}};
    const std::vector<ParamSummary> without_param = {{"radius", "double", "1", "", ""}};
    // Imported: tools. The same file named through "..": still the library.
    EXPECT_EQ(stroke_tools_of(declared, {rule, library}, {stdlib}, with_param).size(), 1u);
    EXPECT_EQ(
        stroke_tools_of(declared, {rule, stdlib + "/../stdlib/guided.acr"}, {stdlib}, with_param)
            .size(),
        1u);
    // Not imported, or a file of the same name elsewhere: none.
    EXPECT_TRUE(stroke_tools_of(declared, {rule}, {stdlib}, with_param).empty());
    EXPECT_TRUE(
        stroke_tools_of(declared, {rule, (dir / "guided.acr").string()}, {stdlib}, with_param)
            .empty());
    // Imported but without the parameter (another version of the library): none.
    EXPECT_TRUE(stroke_tools_of(declared, {rule, library}, {stdlib}, without_param).empty());
    fs::remove_all(dir);
}

// The declarations the build baked in parse: the growth library's guides among them.
TEST(PreviewStrokeTools, RegisteredDeclarationsParse) {
    std::vector<StrokeTool> tools;
    std::string error;
    ASSERT_TRUE(parse_stroke_tools(find_toolchain().preview_strokes, tools, error)) << error;
    const auto growth = std::find_if(tools.begin(), tools.end(),
                                     [](const StrokeTool& t) { return t.library == "growth"; });
    ASSERT_NE(growth, tools.end());
    EXPECT_EQ(growth->file_param, "growth_guides");
    EXPECT_EQ(growth->mode_param, "growth_mode");
    EXPECT_EQ(growth->kinds, (std::vector<std::string>{"flow", "boundary", "spray"}));
}

TEST(PreviewSettings, ProgramOptionsSplitIntoControls) {
    PreviewSettings s;
    std::string error;
    ASSERT_TRUE(s.take({"--region", "heart.svg", "--seed=1,2", "--param", "r=2", "--param=q=x y",
                        "--rng-seed", "7", "--style", "order", "--time-limit", "5"},
                       error))
        << error;
    EXPECT_EQ(s.region, "heart.svg");
    EXPECT_EQ(s.seeds, std::vector<std::string>{"1,2"});
    EXPECT_EQ(s.params.at("r"), "2");
    EXPECT_EQ(s.params.at("q"), "x y");
    EXPECT_EQ(s.rng_seed, "7");
    EXPECT_EQ(s.other, (std::vector<std::string>{"--style", "order"}));
    EXPECT_EQ(s.time_limit, 5);
    const std::vector<std::string> args = s.arguments();
    EXPECT_EQ(args.back(), "5");
    EXPECT_EQ(s.arguments(true).back(), "5");  // the user's own --time-limit is shown...
    PreviewSettings d;
    EXPECT_EQ(d.arguments(true), std::vector<std::string>{});  // ...the preview's default not
    EXPECT_EQ(d.arguments(), (std::vector<std::string>{"--time-limit", "20"}));
}

TEST(PreviewSettings, OptionsThePreviewOwnsRefused) {
    for (const char* opt : {"-o", "--metrics", "--frames", "--json", "--debug-frame", "--partial",
                            "--view", "--view-size"}) {
        PreviewSettings s;
        std::string error;
        EXPECT_FALSE(s.take({opt, "x"}, error)) << opt;
        EXPECT_NE(error.find("set by the preview"), std::string::npos);
    }
    PreviewSettings s;
    std::string error;
    EXPECT_FALSE(s.take({"--time-limit", "-1"}, error));
    EXPECT_FALSE(s.take({"--param", "novalue"}, error));
    EXPECT_FALSE(s.take({"--region"}, error));
}

// Connections that never end (event streams, half requests) do not keep the next one waiting,
// up to the bound; beyond it a connection waits for a thread.
TEST(ConnectionThreads, LongConnectionsLeaveRoomAndTheBoundHolds) {
    ConnectionThreads threads(21, 2);
    std::promise<void> release;
    std::shared_future<void> released = release.get_future().share();
    std::atomic<int> started{0};
    for (int i = 0; i < 20; ++i)
        threads.enqueue([&, released] {
            ++started;
            released.wait();
        });
    std::promise<void> quick;
    threads.enqueue([&] { quick.set_value(); });
    EXPECT_EQ(quick.get_future().wait_for(std::chrono::seconds(5)), std::future_status::ready);
    EXPECT_LE(threads.threads(), 21u);
    std::promise<void> beyond;
    threads.enqueue([&] { beyond.set_value(); });  // 20 blocked, 21 threads: one is free
    EXPECT_EQ(beyond.get_future().wait_for(std::chrono::seconds(5)), std::future_status::ready);
    release.set_value();
    threads.shutdown();
    EXPECT_EQ(started, 20);
    EXPECT_EQ(threads.threads(), 0u);
}

TEST(ConnectionThreads, WaitsForAThreadAtTheBound) {
    ConnectionThreads threads(2, 0);
    std::promise<void> release;
    std::shared_future<void> released = release.get_future().share();
    for (int i = 0; i < 2; ++i) threads.enqueue([released] { released.wait(); });
    std::promise<void> third;
    threads.enqueue([&] { third.set_value(); });
    std::future<void> done = third.get_future();
    EXPECT_EQ(done.wait_for(std::chrono::milliseconds(200)), std::future_status::timeout);
    EXPECT_EQ(threads.threads(), 2u);
    release.set_value();
    EXPECT_EQ(done.wait_for(std::chrono::seconds(5)), std::future_status::ready);
    threads.shutdown();
}

TEST(ConnectionThreads, IdleThreadsEndDownToTheKeptOnes) {
    ConnectionThreads threads(8, 1, std::chrono::milliseconds(50));
    std::promise<void> release;
    std::shared_future<void> released = release.get_future().share();
    for (int i = 0; i < 4; ++i) threads.enqueue([released] { released.wait(); });
    release.set_value();
    for (int i = 0; i < 100 && threads.threads() > 1; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    EXPECT_EQ(threads.threads(), 1u);
    std::promise<void> later;
    threads.enqueue([&] { later.set_value(); });
    EXPECT_EQ(later.get_future().wait_for(std::chrono::seconds(5)), std::future_status::ready);
}

TEST(RunSlots, RunningThenQueuedThenBusy) {
    RunSlots slots(2, 1);
    EXPECT_EQ(slots.take(std::chrono::milliseconds(0)), RunSlots::Outcome::taken);
    EXPECT_EQ(slots.take(std::chrono::milliseconds(0)), RunSlots::Outcome::taken);
    EXPECT_EQ(slots.take(std::chrono::milliseconds(20)), RunSlots::Outcome::timed_out);
    auto queued =
        std::async(std::launch::async, [&] { return slots.take(std::chrono::seconds(5)); });
    for (int i = 0; i < 500 && slots.waiting() == 0; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    EXPECT_EQ(slots.take(std::chrono::milliseconds(0)), RunSlots::Outcome::busy);
    slots.give_back();
    EXPECT_EQ(queued.get(), RunSlots::Outcome::taken);
    slots.give_back();
    slots.give_back();
    EXPECT_EQ(slots.take(std::chrono::milliseconds(0)), RunSlots::Outcome::taken);
}

// Saves by rename (as editors and the bench do) and in place are both reported, once each; a
// save of the same bytes is not. (Waits are generous bounds, not speed targets.)
TEST(FileWatcher, ReportsRenamedAndRewrittenSavesOfNewContentOnly) {
    namespace fs = std::filesystem;
    const fs::path dir =
        fs::temp_directory_path() / ("acanthus-watcher-" + std::to_string(getpid()));
    fs::create_directories(dir);
    const fs::path rule = dir / "a.acr";
    const auto write = [](const fs::path& path, const std::string& text) {
        std::ofstream(path, std::ios::binary) << text;
    };
    write(rule, "one");
    std::atomic<int> changes{0};
    FileWatcher watcher([&] { ++changes; });
    watcher.watch({rule.string()});
    const auto changes_after = [&](int want) {
        for (int i = 0; i < 500 && changes < want; ++i)
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        std::this_thread::sleep_for(std::chrono::milliseconds(100));  // and no more
        return changes.load();
    };
    write(dir / "a.acr.tmp", "two");
    fs::rename(dir / "a.acr.tmp", rule);
    EXPECT_EQ(changes_after(1), 1);
    write(rule, "three");
    EXPECT_EQ(changes_after(2), 2);
    const auto unchanged = [&] {  // the watcher looks at least every 0.5 s
        std::this_thread::sleep_for(std::chrono::milliseconds(700));
        return changes.load();
    };
    write(rule, "three");  // the same bytes again
    EXPECT_EQ(unchanged(), 2);
    write(dir / "other.txt", "a file not watched");
    EXPECT_EQ(unchanged(), 2);
    watcher.stop();
    fs::remove_all(dir);
}

// The build tests run clang++, where there is one.
bool has_clang() {
    std::string error;
    return run_process({"sh", "-c", "command -v clang++ >/dev/null"}, error) == 0;
}

// clang++ at -O0 building a shared library, linked by the linker itself.
bool clang_library_options(const Toolchain& toolchain, BuildOptions& options, std::string& error) {
    options.cxx = "clang++";
    options.optimization = "0";
    options.shared_library = true;
    return direct_link_command(toolchain, options, options.link_command, error);
}

// ACANTHUS_CACHE_DIR set to a test's own folder while the test runs.
class CacheDirFor {
  public:
    explicit CacheDirFor(const std::string& dir) {
        const char* old = std::getenv("ACANTHUS_CACHE_DIR");
        had_ = old != nullptr;
        if (had_) kept_ = old;
        setenv("ACANTHUS_CACHE_DIR", dir.c_str(), 1);
    }
    ~CacheDirFor() {
        if (had_)
            setenv("ACANTHUS_CACHE_DIR", kept_.c_str(), 1);
        else
            unsetenv("ACANTHUS_CACHE_DIR");
    }
    CacheDirFor(const CacheDirFor&) = delete;
    CacheDirFor& operator=(const CacheDirFor&) = delete;

  private:
    bool had_ = false;
    std::string kept_;
};

// Each command a build runs, recorded in `ran`, then run.
void record_runs(BuildOptions& options, std::vector<std::vector<std::string>>& ran) {
    options.runner = [&ran](const std::vector<std::string>& argv, std::string& e) {
        ran.push_back(argv);
        return run_process(argv, e);
    };
}

// How many of the recorded commands have `word` among their arguments.
int commands_with(const std::vector<std::vector<std::string>>& ran, const std::string& word) {
    int n = 0;
    for (const auto& argv : ran) n += std::find(argv.begin(), argv.end(), word) != argv.end();
    return n;
}

// The sum of what the three parts of a split library return; -1 when it does not load.
int parts_sum(const std::string& library) {
    void* handle = dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) return -1;
    int total = 0;
    for (const char* name : {"tables_part", "code_part", "rule_part"})
        if (auto f = reinterpret_cast<int (*)()>(dlsym(handle, name))) total += f();
    dlclose(handle);
    return total;
}

// The preview builds rule code in two processes, neither of them a compiler driver that starts
// another: the compiler on its own (-c) and the linker itself, with the command the driver gives.
TEST(PreviewBuild, RuleLibraryCompiledThenLinkedByTheLinkerItself) {
    if (!has_clang()) GTEST_SKIP() << "no clang++";
    std::string error;
    const test::TempDir dir("build");
    Toolchain toolchain = find_toolchain();
    BuildOptions options;
    ASSERT_TRUE(clang_library_options(toolchain, options, error)) << error;
    const auto& link = options.link_command;
    EXPECT_EQ(std::count(link.begin(), link.end(), kLinkObject), 1);
    EXPECT_EQ(std::count(link.begin(), link.end(), kLinkOutput), 1);
    EXPECT_NE(std::filesystem::path(link.front()).filename().string().find("ld"), std::string::npos)
        << link.front();
    std::vector<std::vector<std::string>> ran;
    options.runner = [&ran](const std::vector<std::string>& argv, std::string& e) {
        ran.push_back(argv);
        return run_process(argv, e);
    };
    const std::string library = (dir.path() / "answer.so").string();
    ASSERT_TRUE(build_executable(toolchain, options, "answer",
                                 "extern \"C\" int acanthus_answer() { return 42; }\n", library,
                                 error))
        << error;
    ASSERT_EQ(ran.size(), 2u);
    EXPECT_EQ(ran[0].front(), "clang++");
    EXPECT_NE(std::find(ran[0].begin(), ran[0].end(), "-c"), ran[0].end());
    EXPECT_EQ(ran[1].front(), link.front());
    void* handle = dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
    ASSERT_NE(handle, nullptr) << dlerror();
    using Answer = int (*)();
    auto answer = reinterpret_cast<Answer>(dlsym(handle, "acanthus_answer"));
    ASSERT_NE(answer, nullptr);
    EXPECT_EQ(answer(), 42);
    dlclose(handle);
}

// A split build compiles the units it lacks two at a time; the code unit (the %draw bodies) at
// its own level, and with code_unit_later first at the ordinary one, the optimised one left to
// a later build of the same units.
TEST(PreviewBuild, SplitUnitsTwoAtATimeTheCodeUnitOptimisedLater) {
    if (!has_clang()) GTEST_SKIP() << "no clang++";
    std::string error;
    const test::TempDir dir("split");
    const CacheDirFor cache(dir.path().string());
    Toolchain toolchain = find_toolchain();
    BuildOptions options;
    ASSERT_TRUE(clang_library_options(toolchain, options, error)) << error;
    options.jobs = 2;
    options.code_unit_optimization = "2";
    std::mutex mutex;
    std::vector<std::vector<std::string>> ran;
    int running = 0, most = 0;
    options.runner = [&](const std::vector<std::string>& argv, std::string& e) {
        {
            std::lock_guard lock(mutex);
            ran.push_back(argv);
            most = std::max(most, ++running);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(300));  // long enough to overlap
        const int status = run_process(argv, e);
        std::lock_guard lock(mutex);
        --running;
        return status;
    };
    const std::vector<std::string> units{"extern \"C\" int tables_part() { return 1; }\n",
                                         "extern \"C\" int code_part() { return 20; }\n",
                                         "extern \"C\" int rule_part() { return 300; }\n"};
    const auto compiled_at = [&](const char* level) {
        int n = 0;
        for (const auto& argv : ran)
            n += std::find(argv.begin(), argv.end(), "-c") != argv.end() &&
                 std::find(argv.begin(), argv.end(), std::string("-O") + level) != argv.end();
        return n;
    };
    const auto sum = parts_sum;
    std::string first, second, third;
    bool splittable = true, code_later = false;
    options.code_unit_later = true;
    ASSERT_TRUE(cached_split_library(toolchain, options, "split", units, first, splittable, error,
                                     ~std::size_t(0), nullptr, &code_later))
        << error;
    EXPECT_TRUE(code_later);
    EXPECT_EQ(compiled_at("0"), 3);
    EXPECT_EQ(most, 2);
    EXPECT_EQ(sum(first), 321);
    ran.clear();
    options.code_unit_later = false;  // the build after the picture
    ASSERT_TRUE(cached_split_library(toolchain, options, "split", units, second, splittable, error,
                                     ~std::size_t(0), nullptr, &code_later))
        << error;
    EXPECT_FALSE(code_later);
    EXPECT_EQ(compiled_at("0"), 0);
    EXPECT_EQ(compiled_at("2"), 1);
    EXPECT_NE(second, first);
    EXPECT_EQ(sum(second), 321);
    ran.clear();
    options.code_unit_later = true;  // the next save finds the optimised unit
    ASSERT_TRUE(cached_split_library(toolchain, options, "split", units, third, splittable, error,
                                     ~std::size_t(0), nullptr, &code_later))
        << error;
    EXPECT_FALSE(code_later);
    EXPECT_TRUE(ran.empty());
    EXPECT_EQ(third, second);
}

// The rule units optimised after a picture (optimise_rules): a save then links the optimised
// object of each rule it did not edit, and compiles the edited one at the ordinary level.
TEST(PreviewBuild, RuleUnitsOptimisedAfterAPictureForTheSavesAfter) {
    if (!has_clang()) GTEST_SKIP() << "no clang++";
    std::string error;
    const test::TempDir dir("split-rules-optimised");
    const CacheDirFor cache(dir.path().string());
    Toolchain toolchain = find_toolchain();
    BuildOptions options;
    ASSERT_TRUE(clang_library_options(toolchain, options, error)) << error;
    ASSERT_EQ(options.optimization, "0");
    options.code_unit_optimization = "2";
    // Which unit each compile was (its function's name, read while the source is there), at
    // which level: "rule_part@2".
    std::vector<std::string> seen;
    options.runner = [&seen](const std::vector<std::string>& argv, std::string& e) {
        const auto c = std::find(argv.begin(), argv.end(), "-c");
        if (c != argv.end() && c + 1 != argv.end()) {
            std::ifstream in(*(c + 1));
            const std::string text(std::istreambuf_iterator<char>(in), {});
            const std::size_t at = text.find("int ") + 4;
            for (const char* level : {"-O0", "-O2"})
                if (std::find(argv.begin(), argv.end(), level) != argv.end())
                    seen.push_back(text.substr(at, text.find("()") - at) + "@" + (level + 2));
        }
        return run_process(argv, e);
    };
    const auto compiled = [&] {
        std::sort(seen.begin(), seen.end());
        return seen;
    };
    const auto rule = [](const char* name, int n) {
        return std::string("extern \"C\" int ") + name + "() { return " + std::to_string(n) +
               "; }\n";
    };
    std::vector<std::string> units{rule("tables_part", 1), rule("code_part", 20),
                                   rule("rule_part", 300), rule("other_rule", 4000)};
    std::string library;
    bool splittable = true;
    // The build after a picture: every unit, the code and the rules optimised.
    options.optimise_rules = true;
    ASSERT_TRUE(cached_split_library(toolchain, options, "r", units, library, splittable, error))
        << error;
    EXPECT_EQ(compiled(), (std::vector<std::string>{"code_part@2", "other_rule@2", "rule_part@2",
                                                    "tables_part@0"}));
    EXPECT_EQ(parts_sum(library), 321);
    // A save that edits one rule: that rule at the ordinary level, the other one optimised.
    seen.clear();
    options.optimise_rules = false;
    units[2] = rule("rule_part", 301);
    ASSERT_TRUE(cached_split_library(toolchain, options, "r", units, library, splittable, error))
        << error;
    EXPECT_EQ(compiled(), (std::vector<std::string>{"rule_part@0"}));
    EXPECT_EQ(parts_sum(library), 322);
    const std::string edited = library;
    // Back to the rule as it was: its optimised object, nothing compiled.
    seen.clear();
    units[2] = rule("rule_part", 300);
    ASSERT_TRUE(cached_split_library(toolchain, options, "r", units, library, splittable, error))
        << error;
    EXPECT_TRUE(compiled().empty());
    EXPECT_EQ(parts_sum(library), 321);
    EXPECT_NE(library, edited);
}

// The generated units' shared header: what the code unit and every rule unit start with (the
// %param globals, the %source, the element classes), and not the tables.
TEST(PreviewBuild, GeneratedUnitsStartWithTheirHeader) {
    const test::TempDir dir("units-header");
    const std::string input = (dir.path() / "two.acr").string();
    std::ofstream(input) << "%param double size = 2.0;\n"
                            "%element\nseed point\n%endelement\n"
                            "%element\ndot circle\nint order;\n%endelement\n"
                            "%source\nint placed_so_far = 0;\n%endsource\n"
                            "%rule\nseed --> dot\n{\n    $0.set( $, size );\n"
                            "    $$.sterile = 1;\n    return SUCCESS;\n}\n%endrule\n"
                            "%rule\ndot --> dot\n{\n    if ( $goal.radius < 1 ) return FAILURE;\n"
                            "    $0.set( $goal.center, 1 );\n    return SUCCESS;\n}\n%endrule\n";
    CompileRequest request;
    request.input = input;
    request.generate.output_name = "two.cpp";
    std::string cpp;
    std::ostringstream diagnostics;
    GeneratedUnits units;
    ASSERT_TRUE(compile_rule_file(request, true, cpp, diagnostics, nullptr, nullptr, &units))
        << diagnostics.str();
    ASSERT_EQ(units.rules.size(), 2u);
    EXPECT_NE(units.header.find("placed_so_far"), std::string::npos);
    EXPECT_NE(units.header.find("struct dot"), std::string::npos);
    EXPECT_NE(units.header.find("size"), std::string::npos);
    EXPECT_EQ(units.header.find("acr_rule_"), std::string::npos);
    EXPECT_EQ(units.code.compare(0, units.header.size(), units.header), 0);
    for (const std::string& rule : units.rules)
        EXPECT_EQ(rule.compare(0, units.header.size(), units.header), 0);
    EXPECT_NE(units.tables.compare(0, units.header.size(), units.header), 0);
}

// The part every unit but the tables starts with is precompiled once (chained on the prelude
// when there is one) by a build that asks for it; from then on a unit that starts with it is
// compiled as its own code alone, with that .gch, and the library is the same program.
TEST(PreviewBuild, SplitUnitsCompiledWithTheirHeaderPrecompiled) {
    if (!has_clang()) GTEST_SKIP() << "no clang++";
    std::string error;
    const test::TempDir dir("split-header");
    const CacheDirFor cache(dir.path().string());
    Toolchain toolchain = find_toolchain();
    BuildOptions options;
    ASSERT_TRUE(clang_library_options(toolchain, options, error)) << error;
    std::vector<std::vector<std::string>> ran;
    record_runs(options, ran);
    options.unit_header =
        "#include <vector>\n"
        "struct Shared { std::vector<int> v{100, 200}; };\n"
        "inline int twice(int x) { return 2 * x; }\n";
    const auto rule = [&](int n) {
        return options.unit_header + "extern \"C\" int rule_part() { return Shared{}.v[1] + " +
               std::to_string(n) + "; }\n";
    };
    std::vector<std::string> units{
        "extern \"C\" int tables_part() { return 1; }\n",
        options.unit_header + "extern \"C\" int code_part() { return twice(10); }\n", rule(100)};
    const auto count = [&](const std::string& word) { return commands_with(ran, word); };
    const auto sum = parts_sum;
    std::string library;
    bool splittable = true;
    // Not asked to precompile: the units compiled whole.
    ASSERT_TRUE(cached_split_library(toolchain, options, "h", units, library, splittable, error))
        << error;
    EXPECT_EQ(count("c++-header"), 0);
    EXPECT_EQ(count("-include-pch"), 0);
    EXPECT_EQ(sum(library), 321);
    // Asked (the build after a picture): the header first, then the changed rule with it.
    ran.clear();
    options.precompile_unit_header = true;
    units[2] = rule(101);
    ASSERT_TRUE(cached_split_library(toolchain, options, "h", units, library, splittable, error))
        << error;
    ASSERT_EQ(count("c++-header"), 1);
    EXPECT_EQ(count("-include-pch"), 1);
    EXPECT_EQ(sum(library), 322);
    // The next save's rule: compiled with the cached .gch, its source without the header.
    ran.clear();
    options.precompile_unit_header = false;
    units[2] = rule(102);
    ASSERT_TRUE(cached_split_library(toolchain, options, "h", units, library, splittable, error))
        << error;
    ASSERT_EQ(ran.size(), 2u);  // the rule's unit and the link
    EXPECT_EQ(count("c++-header"), 0);
    ASSERT_EQ(count("-include-pch"), 1);
    EXPECT_EQ(sum(library), 323);
    // A header that does not compile is remembered: the units are compiled whole.
    ran.clear();
    options.precompile_unit_header = true;
    options.unit_header = "#error not a header\n";
    units = {units[0], options.unit_header, options.unit_header + "int x;\n"};
    EXPECT_FALSE(cached_split_library(toolchain, options, "h", units, library, splittable, error));
    EXPECT_EQ(count("c++-header"), 1);
    EXPECT_EQ(count("-include-pch"), 0);
    ran.clear();
    EXPECT_FALSE(cached_split_library(toolchain, options, "h", units, library, splittable, error));
    EXPECT_EQ(count("c++-header"), 0);
}

// The unit header is precompiled with the rule units' functions after it (renamed, never
// compiled): the templates the rules use are instantiated in the .gch, not again by the unit
// of a save that edits a rule. Seen by a deprecation warning that a template gives only when
// it is instantiated: printed by the header's compile, not by the rule's.
TEST(PreviewBuild, UnitHeaderPrecompiledWithTheRulesTemplates) {
    if (!has_clang()) GTEST_SKIP() << "no clang++";
    std::string error;
    const test::TempDir dir("split-header-warm");
    const CacheDirFor cache(dir.path().string());
    Toolchain toolchain = find_toolchain();
    BuildOptions options;
    ASSERT_TRUE(clang_library_options(toolchain, options, error)) << error;
    // Each command's messages in a file of its own (ran[k]: dir/messages-k.txt).
    std::vector<std::vector<std::string>> ran;
    options.runner = [&](const std::vector<std::string>& argv, std::string& e) {
        std::string command;
        for (const std::string& a : argv) command += "'" + a + "' ";
        command += "2>'" +
                   (dir.path() / ("messages-" + std::to_string(ran.size()) + ".txt")).string() +
                   "'";
        ran.push_back(argv);
        return run_process({"/bin/sh", "-c", command}, e);
    };
    const auto messages_of = [&](const std::string& word) {
        std::string text;
        for (std::size_t k = 0; k < ran.size(); ++k)
            if (std::find(ran[k].begin(), ran[k].end(), word) != ran[k].end()) {
                std::ifstream in(dir.path() / ("messages-" + std::to_string(k) + ".txt"));
                text += std::string(std::istreambuf_iterator<char>(in), {});
            }
        return text;
    };
    options.unit_header =
        "namespace acanthus { using Result = int; struct RuleCall {}; }\n"
        "struct Legacy { [[deprecated(\"instantiated\")]] static int value() { return 300; } };\n"
        "template <class T> int read() { return T::value(); }\n";
    const auto rule = [&](int n) {
        return options.unit_header +
               "\n// seed --> dot\nacanthus::Result acr_rule_0(acanthus::RuleCall& call_) {\n" +
               "    (void)call_;\n    return read<Legacy>() + " + std::to_string(n) + ";\n}\n";
    };
    const std::vector<std::string> units{
        "namespace acanthus { using Result = int; struct RuleCall {}; }\n"
        "acanthus::Result acr_rule_0(acanthus::RuleCall&);\n"
        "extern \"C\" int tables_part() { return 1; }\n"
        "extern \"C\" int rule_part() { acanthus::RuleCall c; return acr_rule_0(c); }\n",
        options.unit_header + "extern \"C\" int code_part() { return 20; }\n", rule(0)};
    std::string library;
    bool splittable = true;
    options.precompile_unit_header = true;
    ASSERT_TRUE(cached_split_library(toolchain, options, "w", units, library, splittable, error))
        << error;
    EXPECT_EQ(parts_sum(library), 321);
    ASSERT_EQ(commands_with(ran, "c++-header"), 1);
    EXPECT_NE(messages_of("c++-header").find("instantiated"), std::string::npos);
    EXPECT_EQ(commands_with(ran, "-include-pch"), 2);  // (the code and the rule, with it)
    // The next save's rule, compiled with the .gch: the template is there already.
    ran.clear();
    options.precompile_unit_header = false;
    std::vector<std::string> saved = units;
    saved[2] = rule(1);
    ASSERT_TRUE(cached_split_library(toolchain, options, "w", saved, library, splittable, error))
        << error;
    EXPECT_EQ(parts_sum(library), 322);
    ASSERT_EQ(commands_with(ran, "-include-pch"), 1);
    EXPECT_EQ(messages_of("-include-pch").find("instantiated"), std::string::npos)
        << messages_of("-include-pch");
}

// A rule body that gains a line moves the #line numbers of the %source after it in the header:
// the header precompiled before is still the same code, and the changed rule is compiled with
// it, not with the header's text again. A header that uses its line numbers (__LINE__) is not.
TEST(PreviewBuild, UnitHeaderPrecompiledKeptWhenOnlyItsLinesMove) {
    if (!has_clang()) GTEST_SKIP() << "no clang++";
    std::string error;
    const test::TempDir dir("split-header-lines");
    const CacheDirFor cache(dir.path().string());
    Toolchain toolchain = find_toolchain();
    BuildOptions options;
    ASSERT_TRUE(clang_library_options(toolchain, options, error)) << error;
    std::vector<std::vector<std::string>> ran;
    record_runs(options, ran);
    const auto header_at = [](int line, const std::string& body) {
        return "#line " + std::to_string(line) + " \"p.acr\"\n" + body + "#line 9 \"p.cpp\"\n";
    };
    const auto units_with = [](const std::string& header, int n) {
        return std::vector<std::string>{
            "extern \"C\" int tables_part() { return 1; }\n",
            header + "extern \"C\" int code_part() { return twice(10); }\n",
            header + "extern \"C\" int rule_part() { return twice(" + std::to_string(n) + "); }\n"};
    };
    const auto count = [&](const std::string& word) { return commands_with(ran, word); };
    const auto sum = parts_sum;
    for (const std::string& body : {std::string("inline int twice(int x) { return 2 * x; }\n"),
                                    std::string("inline int twice(int x) { return 2 * x + "
                                                "(__LINE__ - __LINE__); }\n")}) {
        const bool uses_lines = body.find("__LINE__") != std::string::npos;
        std::string library;
        bool splittable = true;
        options.precompile_unit_header = true;
        options.unit_header = header_at(40, body);
        std::vector<std::string> units = units_with(options.unit_header, 100);
        ASSERT_TRUE(
            cached_split_library(toolchain, options, "l", units, library, splittable, error))
            << error;
        ASSERT_EQ(sum(library), 221);
        // The save: a line more in a rule above the %source; the rule changed too.
        ran.clear();
        options.precompile_unit_header = false;
        options.unit_header = header_at(41, body);
        units = units_with(options.unit_header, 101);
        ASSERT_TRUE(
            cached_split_library(toolchain, options, "l", units, library, splittable, error))
            << error;
        EXPECT_EQ(sum(library), 223);
        EXPECT_EQ(count("c++-header"), 0);
        EXPECT_EQ(count("-include-pch"), uses_lines ? 0 : 1) << body;
    }
}

// The code unit at its own level with the precompiled prelude: the prelude's .gch was made at
// the ordinary level, which clang refuses for another (__OPTIMIZE__ differs), so the optimised
// code unit is compiled without it and builds (it failed at every save before: the %draw
// bodies were never optimised in the preview).
TEST(PreviewBuild, CodeUnitOptimisedBuildsBesideThePrecompiledPrelude) {
    if (!has_clang()) GTEST_SKIP() << "no clang++";
    std::string error;
    const test::TempDir dir("split-prelude");
    const CacheDirFor cache(dir.path().string());
    Toolchain toolchain = find_toolchain();
    BuildOptions options;
    ASSERT_TRUE(clang_library_options(toolchain, options, error)) << error;
    ASSERT_TRUE(use_precompiled_prelude(toolchain, options, error, "")) << error;
    ASSERT_FALSE(options.precompiled_header.empty());
    options.code_unit_optimization = "2";
    std::vector<std::vector<std::string>> ran;
    record_runs(options, ran);
    const std::string includes = "#include <acanthus/rules.hpp>\n#include <string>\n";
    const std::vector<std::string> units{
        includes + "extern \"C\" int tables_part() { return 1; }\n",
        includes + "extern \"C\" int code_part() { return int(std::string(\"ab\").size()); }\n",
        includes + "extern \"C\" int rule_part() { return 300; }\n"};
    std::string library;
    bool splittable = true;
    ASSERT_TRUE(cached_split_library(toolchain, options, "p", units, library, splittable, error))
        << error;
    int at_o2 = 0, at_o0_with_prelude = 0;
    for (const auto& argv : ran) {
        if (std::find(argv.begin(), argv.end(), "-c") == argv.end()) continue;
        const bool prelude =
            std::find(argv.begin(), argv.end(), options.precompiled_header) != argv.end();
        if (std::find(argv.begin(), argv.end(), "-O2") != argv.end()) {
            ++at_o2;
            EXPECT_FALSE(prelude);
        } else {
            at_o0_with_prelude += prelude;
        }
    }
    EXPECT_EQ(at_o2, 1);
    EXPECT_EQ(at_o0_with_prelude, 2);
    void* handle = dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
    ASSERT_NE(handle, nullptr) << dlerror();
    auto code = reinterpret_cast<int (*)()>(dlsym(handle, "code_part"));
    ASSERT_NE(code, nullptr);
    EXPECT_EQ(code(), 2);
    dlclose(handle);
}

}  // namespace
}  // namespace acanthus
