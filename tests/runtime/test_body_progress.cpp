// report_progress(): the runaway-body watchdog stops a body that makes no progress, not one that
// is long and reports a growing count; the progress line shows the running body's report. The
// pattern is written by hand the way the compiler generates one: a seed whose one rule works for
// a while inside its body, reporting (or not) as `beat` says.
#include <gtest/gtest.h>
#include <unistd.h>

#include <acanthus/body.hpp>
#include <acanthus/program.hpp>
#include <acanthus/progress.hpp>
#include <acanthus/rule_call.hpp>
#include <chrono>
#include <climits>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include "pattern/body_progress.hpp"
#include "pattern/running_body.hpp"
#include "program/progress_line.hpp"

namespace {

namespace fs = std::filesystem;
using namespace acanthus;
using namespace acanthus::detail;
using Clock = std::chrono::steady_clock;

enum class Beat { growing, constant, none };
Beat beat = Beat::growing;
double work_seconds = 1;

struct seed final : Element {
    PointProxy p0;
    const ElementType& type() const override;
    std::size_t proxy_count() const override { return 1; }
    Proxy& proxy(std::size_t) override { return p0; }
};

struct dot final : Element {
    CircleProxy p0;
    const ElementType& type() const override;
    std::size_t proxy_count() const override { return 1; }
    Proxy& proxy(std::size_t) override { return p0; }
};

Element* create_seed() { return new seed; }
Element* create_dot() { return new dot; }
const ElementType seed_type{"seed", {ProxyKind::point}, &create_seed, nullptr, 1};
const ElementType dot_type{"dot", {ProxyKind::circle}, &create_dot, nullptr, 5};
const ElementType& seed::type() const { return seed_type; }
const ElementType& dot::type() const { return dot_type; }

// One long body call: `work_seconds` of work in 1 ms steps, one report per step.
Result seed_rule(RuleCall& call_) {
    seed& parent = call_.parent<seed>();
    dot* c0 = call_.make_static<dot>();
    const auto end = Clock::now() + std::chrono::duration<double>(work_seconds);
    long steps = 0;
    while (Clock::now() < end) {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
        ++steps;
        if (beat == Beat::growing) body::report_progress("work", steps, 1000000);
        if (beat == Beat::constant) body::report_progress("work", 5, 1000000);
    }
    c0->p0.set(parent.p0, 3.0);
    parent.sterile = true;
    return SUCCESS;
}

Pattern make_pattern() {
    Pattern p;
    p.name = "heartbeat";
    p.file = "heartbeat.acr";
    p.types = {&seed_type, &dot_type};
    p.seed = &seed_type;
    p.rules.push_back(
        RuleInfo{"seed --> dot", 14, "heartbeat.acr", &seed_type, {&dot_type}, &seed_rule});
    return p;
}

struct Outcome {
    int code = -1;
    std::string err;
};

class BodyProgressRun : public ::testing::Test {
  protected:
    void SetUp() override {
        GTEST_FLAG_SET(death_test_style, "threadsafe");  // the run starts a watchdog thread
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        // A death test's child runs SetUp again and exits without TearDown: it shares its
        // parent's folder, which the parent removes.
        const bool child = !GTEST_FLAG_GET(internal_run_death_test).empty();
        const pid_t owner = child ? ::getppid() : ::getpid();
        dir_ = fs::temp_directory_path() /
               ("acanthus-test-body-progress-" + std::to_string(owner) + "-" + info->name());
        if (!child) fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    int run_code(std::vector<std::string> args) {
        args.insert(args.begin(), "heartbeat");
        args.insert(args.end(), {"--region", "rect:60,40", "-o", (dir_ / "out.svg").string()});
        std::vector<char*> argv;
        for (std::string& a : args) argv.push_back(a.data());
        argv.push_back(nullptr);
        return run_program(pattern_, static_cast<int>(args.size()), argv.data());
    }
    Outcome run(std::vector<std::string> args) {
        Outcome o;
        ::testing::internal::CaptureStderr();
        o.code = run_code(std::move(args));
        o.err = ::testing::internal::GetCapturedStderr();
        return o;
    }

    Pattern pattern_ = make_pattern();
    fs::path dir_;
};

// --- the watchdog --------------------------------------------------------------------------------

TEST_F(BodyProgressRun, GrowingReportsKeepALongBodyAlive) {
    beat = Beat::growing;
    work_seconds = 2.5;
    EXPECT_EXIT(std::exit(run_code({"--body-time-limit", "1"})), ::testing::ExitedWithCode(0), "");
}

TEST_F(BodyProgressRun, ConstantReportsAreStoppedNamingTheRule) {
    beat = Beat::constant;
    work_seconds = 4;
    EXPECT_EXIT(std::exit(run_code({"--body-time-limit", "1"})), ::testing::ExitedWithCode(3),
                "heartbeat: error: heartbeat.acr:14: rule 'seed --> dot': still running, with no "
                "progress reported for 1 s \\(an endless loop\\?\\)");
}

TEST_F(BodyProgressRun, SilentBodyIsStoppedNamingTheRule) {
    beat = Beat::none;
    work_seconds = 4;
    EXPECT_EXIT(std::exit(run_code({"--body-time-limit", "1"})), ::testing::ExitedWithCode(3),
                "heartbeat: error: heartbeat.acr:14: rule 'seed --> dot': still running after 1 s "
                "\\(an endless loop\\?\\)");
}

TEST_F(BodyProgressRun, GrowingReportsDoNotLiftTheTimeLimitGrace) {
    beat = Beat::growing;
    work_seconds = 4;
    EXPECT_EXIT(std::exit(run_code({"--time-limit", "0.5"})), ::testing::ExitedWithCode(3),
                "heartbeat.acr:14: rule 'seed --> dot': still running 1 s after the --time-limit");
}

// --- the progress line ---------------------------------------------------------------------------

TEST_F(BodyProgressRun, ProgressLineShowsTheRunningBodysReport) {
    beat = Beat::growing;
    work_seconds = 1.5;
    const Outcome o = run({"--progress"});
    EXPECT_EQ(o.code, 0) << o.err;
    const std::regex line("(^|\n)heartbeat: work [0-9,]+ / 1,000,000, [0-9]+\\.[0-9] s\n");
    EXPECT_TRUE(std::regex_search(o.err, line)) << o.err;
}

TEST_F(BodyProgressRun, QuietShowsNoReport) {
    beat = Beat::growing;
    work_seconds = 0.5;
    const Outcome o = run({"--quiet"});
    EXPECT_EQ(o.code, 0) << o.err;
    EXPECT_EQ(o.err, "");
}

// --- the heartbeat itself ------------------------------------------------------------------------

TEST(BodyProgress, BelongsToTheBodyCallThatReported) {
    EXPECT_EQ(running_body_progress().what, nullptr);  // between bodies
    const std::string label = "heartbeat.acr:14: rule 'seed --> dot'";
    {
        const RunningBody running(label);
        EXPECT_EQ(running_body_progress().what, nullptr);  // this call has not reported
        report_progress("cells", 82000, 161700);
        const BodyProgress p = running_body_progress();
        ASSERT_NE(p.what, nullptr);
        EXPECT_STREQ(p.what, "cells");
        EXPECT_EQ(p.done, 82000);
        EXPECT_EQ(p.total, 161700);
    }
    EXPECT_EQ(running_body_progress().what, nullptr);  // that body has ended
    const RunningBody next(label);
    EXPECT_EQ(running_body_progress().what, nullptr);  // a new call starts without a report
}

// --- what the line shows -------------------------------------------------------------------------

TEST(BodyProgressText, ThousandsSeparators) {
    EXPECT_EQ(with_thousands(0), "0");
    EXPECT_EQ(with_thousands(999), "999");
    EXPECT_EQ(with_thousands(1000), "1,000");
    EXPECT_EQ(with_thousands(82000), "82,000");
    EXPECT_EQ(with_thousands(161700), "161,700");
    EXPECT_EQ(with_thousands(1234567), "1,234,567");
    EXPECT_EQ(with_thousands(-1234), "-1,234");
    EXPECT_EQ(with_thousands(LONG_MAX), "9,223,372,036,854,775,807");
    EXPECT_EQ(with_thousands(LONG_MIN), "-9,223,372,036,854,775,808");
}

TEST(BodyProgressText, WhatDoneAndTotal) {
    EXPECT_EQ(body_progress_text("cells", 82000, 161700), "cells 82,000 / 161,700");
    EXPECT_EQ(body_progress_text("cells", 82000, 0), "cells 82,000");         // total unknown
    EXPECT_EQ(body_progress_text("cells", 170000, 161700), "cells 170,000");  // estimate passed
    EXPECT_EQ(body_progress_text("motifs", 0, 5), "motifs 0 / 5");
    EXPECT_EQ(body_progress_text("", 12, 20), "12 / 20");
    EXPECT_EQ(body_progress_text(nullptr, 12, 0), "12");
}

}  // namespace
