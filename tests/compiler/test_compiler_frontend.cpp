// Unit tests of the compiler's pieces: dollar-token scanning, member analysis, parameter
// defaults, reserved names, import resolution order.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "body_rewriter.hpp"
#include "code_generator.hpp"
#include "diagnostics.hpp"
#include "member_fields.hpp"
#include "param_type.hpp"
#include "parse_driver.hpp"
#include "reserved_names.hpp"

namespace acanthus {
namespace {

using Target = ast::DollarToken::Target;

struct Parsed {
    SourceFiles files;
    Diagnostics diagnostics{files};
    std::unique_ptr<ast::RuleFile> file;
    std::string report() const {
        std::ostringstream out;
        diagnostics.print(out);
        return out.str();
    }
};

std::unique_ptr<Parsed> parse(std::string text) {
    auto p = std::make_unique<Parsed>();
    std::uint32_t index = p->files.add("t.acr", std::move(text));
    ParseDriver driver(p->files, p->diagnostics);
    p->file = driver.parse(index);
    return p;
}

const ast::RuleDecl& only_rule(const Parsed& p) {
    for (const ast::Section& s : p.file->sections) {
        if (const auto* r = std::get_if<ast::RuleDecl>(&s)) return *r;
    }
    throw std::runtime_error("no rule parsed");
}

TEST(DollarTokens, EveryFormOfTableOne) {
    auto p = parse(
        "%rule\nflower --> stem flower\n* x leaf\n{\n"
        "$$ $ $(1) $$0 $1 $1(2) $$x $x $x(1) $goal\n}\n%endrule\n");
    ASSERT_EQ(p->diagnostics.error_count(), 0u) << p->report();
    const auto& d = only_rule(*p).body.dollars;
    ASSERT_EQ(d.size(), 10u);
    EXPECT_TRUE(d[0].target == Target::parent && d[0].element);
    EXPECT_TRUE(d[1].target == Target::parent && !d[1].element && d[1].proxy == 0);
    EXPECT_TRUE(d[2].target == Target::parent && d[2].explicit_proxy && d[2].proxy == 1);
    EXPECT_TRUE(d[3].target == Target::child && d[3].element && d[3].child == 0);
    EXPECT_TRUE(d[4].target == Target::child && !d[4].element && d[4].child == 1);
    EXPECT_TRUE(d[5].target == Target::child && d[5].child == 1 && d[5].proxy == 2);
    EXPECT_TRUE(d[6].target == Target::var && d[6].element && d[6].var == "x");
    EXPECT_TRUE(d[7].target == Target::var && !d[7].element && d[7].proxy == 0);
    EXPECT_TRUE(d[8].target == Target::var && d[8].proxy == 1);
    EXPECT_EQ(d[9].target, Target::goal);
    EXPECT_EQ(d[9].where.begin.line, 5u);
    EXPECT_EQ(d[9].where.begin.column, 37u);
}

TEST(DollarTokens, LiteralsAndCommentsAreSkipped) {
    auto p = parse(
        "%rule\nseed -->\n{\n"
        "\"$0\" '$' u8\"$$\" L'$' R\"d($1 )\" $2)d\" 1'000 // $goal\n"
        "/* $$ \n $ */ $\n}\n%endrule\n");
    ASSERT_EQ(p->diagnostics.error_count(), 0u) << p->report();
    const auto& d = only_rule(*p).body.dollars;
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].where.begin.line, 6u);
    EXPECT_EQ(d[0].where.begin.column, 7u);
}

TEST(DollarTokens, RewriteKeepsLines) {
    std::string text =
        "%rule\nseed --> dot\n* x dot\n{\n  $0.set( $, 1 );\n  $$x; $x(1);\n  "
        "$goal;\n}\n%endrule\n";
    auto p = parse(text);
    ASSERT_EQ(p->diagnostics.error_count(), 0u) << p->report();
    std::string out = rewrite_body(text, only_rule(*p).body);
    EXPECT_EQ(out,
              "{\n  c0_->p0.set( self_->p0, 1 );\n  (*x); x->p1;\n  acanthus::body::goal();\n}\n");
}

TEST(Sections, HeaderOnKeywordLineOrNext) {
    auto p = parse(
        "%element dot circle\nint a;\n%endelement\n%element\n\nleaf bezier bezier\n%endelement\n");
    ASSERT_EQ(p->diagnostics.error_count(), 0u) << p->report();
    ASSERT_EQ(p->file->sections.size(), 2u);
    const auto& a = std::get<ast::ElementDecl>(p->file->sections[0]);
    const auto& b = std::get<ast::ElementDecl>(p->file->sections[1]);
    ASSERT_EQ(a.header.size(), 2u);
    EXPECT_EQ(a.header[1].text, "circle");
    EXPECT_EQ(a.members.begin.line, 2u);
    ASSERT_EQ(b.header.size(), 3u);
    EXPECT_EQ(b.header[0].text, "leaf");
}

TEST(Sections, RecoveryContinuesAfterABadSection) {
    auto p = parse("%rule\nseed -> dot\n{ }\n%endrule\n%param double r = 2.5;\n");
    EXPECT_EQ(p->diagnostics.error_count(), 1u);
    ASSERT_EQ(p->file->sections.size(), 1u);
    const auto& param = std::get<ast::ParamDecl>(p->file->sections[0]);
    EXPECT_EQ(param.name.text, "r");
    EXPECT_EQ(param.default_value.text, "2.5");
}

TEST(Sections, EndMarkerEndsABodyEvenInsideAComment) {
    auto p = parse("%source\n/* open\n%endsource\n%element seed point\n%endelement\n");
    EXPECT_EQ(p->diagnostics.error_count(), 0u) << p->report();
    EXPECT_EQ(p->file->sections.size(), 2u);
}

// The preview compiles each rule apart from the others, each unit with the %source: its
// variables and functions must be one object across the units, so they become `inline`.
TEST(SplitUnits, SourceDefinitionsBecomeInline) {
    EXPECT_EQ(inline_namespace_definitions("static int phase = 0;\n"), "inline int phase = 0;\n");
    EXPECT_EQ(inline_namespace_definitions("static inline int f() { return 1; }"),
              "       inline int f() { return 1; }");
    EXPECT_EQ(inline_namespace_definitions("int dot_count = 0;\nstd::vector<Circle> placed;\n"),
              "inline int dot_count = 0;\ninline std::vector<Circle> placed;\n");
    EXPECT_EQ(inline_namespace_definitions("double half(double x) { static int n; return x / 2; }"),
              "inline double half(double x) { static int n; return x / 2; }");
    EXPECT_EQ(inline_namespace_definitions("auto twice = [](int x) { return 2 * x; };"),
              "inline auto twice = [](int x) { return 2 * x; };");
    EXPECT_EQ(inline_namespace_definitions("int table[] = {1, 2};"),
              "inline int table[] = {1, 2};");
    EXPECT_EQ(inline_namespace_definitions("namespace n {\n  static int k;\n}\n"),
              "namespace n {\n  inline int k;\n}\n");
    // Left alone: members, locals, templates, constants, declarations, comments, literals and
    // the preprocessor.
    for (const char* same :
         {"struct S { static int count; static int f(); };\n", "struct S { int x; } s;\n",
          "template <class T> T twice(T x) { return 2 * x; }\n", "constexpr double k = 1.5;\n",
          "inline int shared = 0;\n",
          "int f(int);\nextern int elsewhere;\nusing namespace std;\ntypedef int I;\n",
          "static_assert(sizeof(int) == 4);\n",
          "#define ONCE static int once\n#include <vector>\n"})
        EXPECT_EQ(inline_namespace_definitions(same), same);
    EXPECT_EQ(inline_namespace_definitions("// static int a;\n/* static int b; */\n"
                                           "const char* s = \"static int c;\";\n"),
              "// static int a;\n/* static int b; */\ninline const char* s = \"static int c;\";\n");
}

TEST(MemberFields, ZeroInitializesSimpleDeclarations) {
    MemberAnalysis m = analyze_members(
        "int a;\nlong b = 2, c;\ndouble w[3];\nleaf* next; // note\nint f() { return a; }\n"
        "static int n;\nint bits : 2;\nstd::map<int, int> m;\nint& r;\nstd::string s;\n"
        "unsigned int u;\nconst bool k;\n");
    EXPECT_EQ(
        m.text,
        "int a{};\nlong b = 2, c{};\ndouble w[3]{};\nleaf* next{}; // note\nint f() { return a; }\n"
        "static int n;\nint bits : 2;\nstd::map<int, int> m{};\nint& r;\nstd::string s{};\n"
        "unsigned int u{};\nconst bool k{};\n");
    std::vector<std::string> names;
    for (const MemberField& f : m.fields) names.push_back(f.name + ":" + f.type);
    EXPECT_EQ(names, (std::vector<std::string>{"a:int", "b:long", "c:long", "s:std::string",
                                               "u:unsigned int", "k:bool"}));
}

TEST(ParamDefaults, AcceptWhatTheTypeCanHold) {
    std::string why;
    auto d = *find_param_type("double");
    auto i = *find_param_type("int");
    auto b = *find_param_type("bool");
    auto s = *find_param_type("string");
    EXPECT_TRUE(default_parses(d, "3.0", why));
    EXPECT_TRUE(default_parses(d, "-2.5e-3", why));
    EXPECT_TRUE(default_parses(d, "7", why));
    EXPECT_FALSE(default_parses(d, "1e999", why));
    EXPECT_FALSE(default_parses(d, "nan", why));
    EXPECT_FALSE(default_parses(d, "3.0.1", why));
    EXPECT_TRUE(default_parses(i, "-12", why));
    EXPECT_FALSE(default_parses(i, "2147483648", why));
    EXPECT_FALSE(default_parses(i, "1.5", why));
    EXPECT_TRUE(default_parses(b, "true", why));
    EXPECT_FALSE(default_parses(b, "1", why));
    EXPECT_TRUE(default_parses(s, "\"a \\\"b\\\"\"", why));
    EXPECT_FALSE(default_parses(s, "\"a\" \"b\"", why));
    EXPECT_FALSE(find_param_type("unsigned"));
    EXPECT_EQ(find_param_type("string")->cpp, "std::string");
}

TEST(ReservedNames, KeywordsSupportNamesAndGeneratedNames) {
    EXPECT_TRUE(reserved_name_problem("int"));
    EXPECT_TRUE(reserved_name_problem("Point"));
    EXPECT_TRUE(reserved_name_problem("acr_rule_1"));
    EXPECT_TRUE(reserved_name_problem("c0_"));
    EXPECT_FALSE(reserved_name_problem("flower"));
    EXPECT_EQ(edit_distance("leef", "leaf"), 1u);
}

// Every name body.hpp brings into rule bodies is one a rule file may not declare again.
TEST(ReservedNames, EveryNameBodyHppBringsIn) {
    std::ifstream in(std::string(ACANTHUS_SOURCE_DIR) + "/runtime/include/acanthus/body.hpp");
    ASSERT_TRUE(in) << "cannot read body.hpp";
    std::stringstream text;
    text << in.rdbuf();
    const std::string header = text.str();
    std::set<std::string> names;
    const std::regex patterns[] = {
        std::regex(R"(using acanthus::(\w+);)"),          // re-exported names
        std::regex(R"(\n\w[\w:<>*&, ]*\s[*&]?(\w+)\()"),  // free functions (unindented)
        std::regex(R"(\b(?:struct|class) (\w+))"),        // types
        std::regex(R"(inline constexpr \w+ (\w+))"),      // objects (rng)
    };
    for (const std::regex& re : patterns)
        for (std::sregex_iterator it(header.begin(), header.end(), re), end; it != end; ++it)
            names.insert((*it)[1]);
    EXPECT_GT(names.size(), 30u);
    for (const std::string& name : names) {
        if (name == "A" || name == "B") continue;  // template parameters of min/max
        EXPECT_TRUE(acanthus::reserved_name_problem(name).has_value()) << name;
    }
}

TEST(Diagnostics, SortedWithSourceLineAndCaret) {
    SourceFiles files;
    std::uint32_t f = files.add("x.acr", "first line\n\tsecond line\n");
    Diagnostics d(files);
    SourceRange late{{f, 2, 2, 12}, {f, 2, 8, 18}};
    SourceRange early{{f, 1, 7, 6}, {f, 1, 11, 10}};
    d.error(late, "late");
    d.error(early, "early", {{late, "see here"}});
    std::ostringstream out;
    d.print(out);
    EXPECT_EQ(out.str(),
              "x.acr:1:7: error: early\n"
              "    1 | first line\n"
              "      |       ^~~~\n"
              "x.acr:2:2: note: see here\n"
              "    2 | \tsecond line\n"
              "      | \t^~~~~~\n"
              "x.acr:2:2: error: late\n"
              "    2 | \tsecond line\n"
              "      | \t^~~~~~\n");
}

}  // namespace
}  // namespace acanthus
