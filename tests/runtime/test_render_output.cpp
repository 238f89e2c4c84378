// render_to_file's writing: all or nothing (a failing %draw or a bad option leaves the old file
// and no temporary behind), the usual file permissions, "-" for standard output.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>

#include <acanthus/error.hpp>
#include <acanthus/region.hpp>
#include <acanthus/render.hpp>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "fixtures/sample_elements.hpp"
#include "fixtures/temp_dir.hpp"

using namespace acanthus;
using namespace acanthus::test;
namespace fs = std::filesystem;

namespace {

Region panel() { return Region::from_spec("rect:100,80"); }

RenderOptions outline(double width = 400, const char* style = "drawn") {
    RenderOptions o;
    o.width = width;
    o.style = style;
    return o;
}

void draw_throws(Canvas&, const Element&) { throw std::runtime_error("bad petal maths"); }
const ElementType throwing_dot_type{"baddot", {ProxyKind::circle}, nullptr, &draw_throws, 33};

}  // namespace

TEST(Render, FailedRenderLeavesNoFileAndKeepsTheOldOne) {
    TempDir dir;
    sample::Ornament o;
    Region region = panel();
    std::string good = dir / "ornament.svg";
    render_to_file(good, o.pattern, region, o.placed, outline());
    std::string before = slurp(good);
    ASSERT_FALSE(before.empty());

    o.dots[4].kind = &throwing_dot_type;
    for (const char* name : {"ornament.svg", "ornament.pdf", "ornament.png", "ornament.eps"}) {
        try {
            render_to_file(dir / name, o.pattern, region, o.placed, outline());
            ADD_FAILURE() << "no error for a throwing %draw";
        } catch (const RuleFailure& e) {
            EXPECT_EQ(e.file(), "sample.acr");
            EXPECT_EQ(e.line(), 33);
            EXPECT_NE(std::string(e.what()).find("bad petal maths"), std::string::npos);
            EXPECT_NE(std::string(e.what()).find("%draw baddot"), std::string::npos);
        }
    }
    EXPECT_EQ(slurp(good), before);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"ornament.svg"});

    o.dots[4].kind = &sample::dot_type;
    EXPECT_THROW(render_to_file(good, o.pattern, region, o.placed, outline(400, "sparkly")),
                 UsageError);
    EXPECT_THROW(render_to_file(good, o.pattern, region, o.placed, outline(0)), UsageError);
    RenderOptions stroked = outline();
    stroked.stroke = "calligraphy";
    EXPECT_THROW(render_to_file(good, o.pattern, region, o.placed, stroked), UsageError);
    EXPECT_THROW(render_to_file(dir / "x.gif", o.pattern, region, o.placed, outline()), UsageError);
    EXPECT_THROW(render_to_file(dir / "missing/x.svg", o.pattern, region, o.placed, outline()),
                 InputError);
    EXPECT_EQ(slurp(good), before);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"ornament.svg"});
}

// In a child process: renders under a file size limit of 600 bytes; exits 0 when the render
// failed with InputError (its message on stderr) and left the folder empty.
[[noreturn]] void render_over_the_size_limit(const TempDir& dir, const std::string& path) {
    sample::Ornament o;
    std::signal(SIGXFSZ, SIG_IGN);  // write() fails with EFBIG instead
    const rlimit limit{600, 600};
    setrlimit(RLIMIT_FSIZE, &limit);
    try {
        render_to_file(path, o.pattern, panel(), o.placed, outline(3000, "order"));
        std::cerr << "no error";
    } catch (const InputError& e) {
        std::cerr << e.what();
        std::exit(dir.entries().empty() ? 0 : 1);
    }
    std::exit(2);
}

// PDF, PostScript and EPS go to the temporary file as Cairo writes them: a write that fails on
// the way (here the file size limit, as a full disk would) is an error naming the file, and
// leaves neither a partial file nor the temporary one.
TEST(Render, FailedWriteOnTheWayLeavesNoFile) {
    TempDir dir;
    for (const char* name : {"big.pdf", "big.ps", "big.eps", "big.png"}) {
        const std::string path = dir / name;
        EXPECT_EXIT(render_over_the_size_limit(dir, path), ::testing::ExitedWithCode(0),
                    "cannot write '" + path + "': File too large");
    }
    EXPECT_TRUE(dir.entries().empty());
}

TEST(Render, WritesFilesWithTheUsualPermissions) {
    TempDir dir;
    sample::Ornament o;
    render_to_file(dir / "p.svg", o.pattern, panel(), o.placed, outline());
    auto perms = fs::status(dir / "p.svg").permissions();
    EXPECT_NE(perms & fs::perms::owner_read, fs::perms::none);
    EXPECT_NE(perms & fs::perms::owner_write, fs::perms::none);
    mode_t mask = umask(0);
    umask(mask);
    if (!(mask & 044)) {
        EXPECT_NE(perms & fs::perms::others_read, fs::perms::none);
    }
}

TEST(Render, DashWritesSvgToStdout) {
    sample::Ornament o;
    testing::internal::CaptureStdout();
    render_to_file("-", o.pattern, panel(), o.placed, outline());
    std::string out = testing::internal::GetCapturedStdout();
    EXPECT_EQ(out.rfind("<?xml", 0), 0u);
    EXPECT_NE(out.find("</svg>"), std::string::npos);
}

// A draft (the preview's growth so far) is a PNG of the same size drawn with Cairo's coarser
// antialiasing, so its edge pixels differ from the finished picture's; an SVG is the same.
TEST(Render, DraftPngIsCoarserAndTheSameSize) {
    TempDir dir;
    sample::Ornament o;
    RenderOptions fine = outline(300);
    fine.fit_width = 240;
    fine.fit_height = 200;
    fine.stored_png = true;
    RenderOptions draft = fine;
    draft.draft = true;
    const auto read = [](const fs::path& p) {
        std::ifstream in(p, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    render_to_file(dir / "fine.png", o.pattern, panel(), o.placed, fine);
    render_to_file(dir / "draft.png", o.pattern, panel(), o.placed, draft);
    const std::string a = read(dir / "fine.png"), b = read(dir / "draft.png");
    ASSERT_EQ(a.size(), b.size());                // stored pixels: the same width and height
    EXPECT_EQ(a.substr(0, 24), b.substr(0, 24));  // signature and IHDR's size
    EXPECT_NE(a, b);
    render_to_file(dir / "fine.svg", o.pattern, panel(), o.placed, fine);
    render_to_file(dir / "draft.svg", o.pattern, panel(), o.placed, draft);
    EXPECT_EQ(read(dir / "fine.svg"), read(dir / "draft.svg"));
}
