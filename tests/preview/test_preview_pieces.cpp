// The preview's pure pieces: diagnostics parsed from compiler output, guides written from
// strokes, program options split into the page's settings.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "driver/preview_diagnostics.hpp"
#include "driver/preview_guides.hpp"
#include "driver/preview_settings.hpp"

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

TEST(PreviewDiagnostics, ProgramRuleFailureLocatedAtTheRule) {
    auto d = parse_diagnostics(
        "dots: error: dots.acr:26: rule 'seed --> dot': still running after 10 s\n");
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].file, "dots.acr");
    EXPECT_EQ(d[0].line, 26);
    EXPECT_EQ(d[0].message, "rule 'seed --> dot': still running after 10 s");
}

TEST(PreviewGuides, StrokesBecomePolylinesOfTheirClass) {
    auto body = nlohmann::json::parse(R"({"strokes": [
        {"kind": "flow", "points": [[0, 0], [10, 5]]},
        {"kind": "spray", "width": 12.5, "points": [[1, 1], [2, 2], [3, 3]]}]})");
    std::string svg, error;
    ASSERT_TRUE(guides_svg(body, svg, error)) << error;
    EXPECT_NE(svg.find("<polyline class=\"flow\""), std::string::npos);
    EXPECT_NE(svg.find("class=\"spray\" fill=\"none\" stroke=\"#c63\" stroke-width=\"12.5\""),
              std::string::npos);
    EXPECT_NE(svg.find("points=\"0,0 10,5 \""), std::string::npos);
}

TEST(PreviewGuides, BadStrokesRefused) {
    std::string svg, error;
    for (const char* bad : {R"({})", R"({"strokes": [{"kind": "paint", "points": [[0,0],[1,1]]}]})",
                            R"({"strokes": [{"kind": "flow", "points": [[0,0]]}]})",
                            R"({"strokes": [{"kind": "spray", "points": [[0,0],[1,1]]}]})",
                            R"({"strokes": [{"kind": "flow", "points": [[0,0],[1e12,1]]}]})",
                            R"({"strokes": [{"kind": "flow", "points": [[0,0],["a",1]]}]})"}) {
        EXPECT_FALSE(guides_svg(nlohmann::json::parse(bad), svg, error)) << bad;
        EXPECT_FALSE(error.empty());
    }
    EXPECT_TRUE(guides_svg(nlohmann::json::parse(R"({"strokes": []})"), svg, error));
    EXPECT_TRUE(svg.empty());
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
    for (const char* opt : {"-o", "--metrics", "--frames", "--json", "--debug-frame"}) {
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

}  // namespace
}  // namespace acanthus
