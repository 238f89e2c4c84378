// Bad region inputs: each is refused with an InputError naming the file (and the element
// and line where there is one), never a crash.
#include <gtest/gtest.h>
#include <unistd.h>

#include <acanthus/error.hpp>
#include <acanthus/region.hpp>
#include <filesystem>
#include <fstream>
#include <string>

using acanthus::InputError;
using acanthus::Region;

namespace {

// The message of the InputError `f` throws ("" and a test failure when it does not throw).
template <typename F>
std::string error_of(F&& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    ADD_FAILURE() << "no InputError thrown";
    return "";
}

std::string svg_error(const std::string& body) {
    return error_of([&] {
        Region::from_svg_string(
            "<svg xmlns=\"http://www.w3.org/2000/svg\">\n" + body + "\n</svg>\n", "bad.svg");
    });
}

class TempFile {
  public:
    explicit TempFile(const std::string& content, const std::string& name = "region.svg") {
        dir_ = std::filesystem::temp_directory_path() /
               ("acanthus-region-" + std::to_string(::getpid()));
        std::filesystem::create_directories(dir_);
        path_ = (dir_ / name).string();
        std::ofstream(path_) << content;
    }
    ~TempFile() { std::filesystem::remove_all(dir_); }
    const std::string& path() const { return path_; }

  private:
    std::filesystem::path dir_;
    std::string path_;
};

}  // namespace

TEST(region_errors, MissingFile) {
    std::string m = error_of([] { Region::from_svg_file("/nonexistent/panel.svg"); });
    EXPECT_NE(m.find("/nonexistent/panel.svg"), std::string::npos) << m;
    EXPECT_NE(m.find("no such file"), std::string::npos) << m;
    std::string arg = error_of([] { Region::from_argument("/nonexistent/panel.svg"); });
    EXPECT_NE(arg.find("/nonexistent/panel.svg"), std::string::npos) << arg;
}

TEST(region_errors, DirectoryIsNotAFile) {
    std::string dir = std::filesystem::temp_directory_path().string();
    std::string m = error_of([&] { Region::from_svg_file(dir); });
    EXPECT_NE(m.find(dir), std::string::npos) << m;
    EXPECT_NE(m.find("directory"), std::string::npos) << m;
}

TEST(region_errors, UnreadableFile) {
    if (::geteuid() == 0) GTEST_SKIP() << "root reads any file";
    TempFile f("<svg xmlns=\"http://www.w3.org/2000/svg\"><rect width=\"1\" height=\"1\"/></svg>");
    std::filesystem::permissions(f.path(), std::filesystem::perms::none);
    std::string m = error_of([&] { Region::from_svg_file(f.path()); });
    EXPECT_NE(m.find(f.path()), std::string::npos) << m;
}

TEST(region_errors, NotXml) {
    TempFile f("this is not xml <svg", "junk.svg");
    std::string m = error_of([&] { Region::from_svg_file(f.path()); });
    EXPECT_NE(m.find(f.path() + ":1:"), std::string::npos) << m;
    EXPECT_NE(m.find("XML"), std::string::npos) << m;
}

TEST(region_errors, MalformedXmlReportsLine) {
    std::string m = error_of([] {
        Region::from_svg_string("<svg>\n<rect width=\"1\" height=\"1\">\n</svg>", "broken.svg");
    });
    EXPECT_NE(m.find("broken.svg:3:"), std::string::npos) << m;
}

TEST(region_errors, EmptyFile) {
    TempFile f("", "empty.svg");
    std::string m = error_of([&] { Region::from_svg_file(f.path()); });
    EXPECT_NE(m.find(f.path()), std::string::npos) << m;
}

TEST(region_errors, RootIsNotSvg) {
    std::string m = error_of([] { Region::from_svg_string("<html><body/></html>", "page.svg"); });
    EXPECT_NE(m.find("page.svg"), std::string::npos) << m;
    EXPECT_NE(m.find("<html>"), std::string::npos) << m;
}

TEST(region_errors, NoFillableShape) {
    std::string m = svg_error("<defs><rect width=\"10\" height=\"10\"/></defs><text>x</text>");
    EXPECT_NE(m.find("bad.svg: no fillable shape"), std::string::npos) << m;
}

TEST(region_errors, PathDataDoesNotParse) {
    std::string m = svg_error("<path id=\"p1\" d=\"M 0 0 L 10 10 Q oops\"/>");
    EXPECT_NE(m.find("bad.svg:2: <path id=\"p1\">"), std::string::npos) << m;
    EXPECT_NE(m.find("path data does not parse"), std::string::npos) << m;
}

TEST(region_errors, NonFiniteCoordinates) {
    std::string m = svg_error("<path id=\"big\" d=\"M 0 0 L 1e400 0 L 0 10 Z\"/>");
    EXPECT_NE(m.find("bad.svg"), std::string::npos) << m;
    EXPECT_NE(m.find("big"), std::string::npos) << m;
    std::string t =
        svg_error("<rect id=\"r\" width=\"1e300\" height=\"1e300\" transform=\"scale(1e300)\"/>");
    EXPECT_NE(t.find("<rect id=\"r\">"), std::string::npos) << t;
    EXPECT_NE(t.find("not finite"), std::string::npos) << t;
    std::string n = svg_error("<circle id=\"c\" r=\"nan\"/>");
    EXPECT_NE(n.find("<circle id=\"c\">"), std::string::npos) << n;
}

TEST(region_errors, ZeroArea) {
    std::string m = svg_error("<path d=\"M0,0 L10,0 L20,0 Z\"/>");
    EXPECT_NE(m.find("bad.svg: region has no area"), std::string::npos) << m;
    std::string pts = svg_error("<polygon points=\"0,0 5,5 10,10\"/>");
    EXPECT_NE(pts.find("no area"), std::string::npos) << pts;
    std::string zero = svg_error("<rect width=\"0\" height=\"10\"/>");
    EXPECT_NE(zero.find("bad.svg"), std::string::npos) << zero;
}

TEST(region_errors, NegativeSizes) {
    std::string m = svg_error("<rect id=\"neg\" width=\"-5\" height=\"10\"/>");
    EXPECT_NE(m.find("bad.svg:2: <rect id=\"neg\">"), std::string::npos) << m;
    EXPECT_NE(m.find("negative"), std::string::npos) << m;
    std::string r = svg_error("<circle r=\"-1\"/>");
    EXPECT_NE(r.find("<circle>"), std::string::npos) << r;
}

TEST(region_errors, BadAttributes) {
    EXPECT_NE(svg_error("<rect id=\"u\" width=\"10em\" height=\"10\"/>").find("unsupported length"),
              std::string::npos);
    // A percentage needs a viewport: this root has neither viewBox nor width and height.
    EXPECT_NE(svg_error("<rect width=\"10%\" height=\"10\"/>").find("percentage of a viewport"),
              std::string::npos);
    EXPECT_NE(svg_error("<rect width=\"ten\" height=\"10\"/>").find("not a length"),
              std::string::npos);
    EXPECT_NE(svg_error("<polygon points=\"0,0 10,0 10\"/>").find("odd number"), std::string::npos);
    std::string t =
        svg_error("<g id=\"g1\" transform=\"rotate(1,2)\"><rect width=\"1\" height=\"1\"/></g>");
    EXPECT_NE(t.find("<g id=\"g1\">"), std::string::npos) << t;
    EXPECT_NE(t.find("rotate"), std::string::npos) << t;
    EXPECT_NE(svg_error("<rect transform=\"spin(3)\" width=\"1\" height=\"1\"/>").find("spin"),
              std::string::npos);
    EXPECT_NE(
        svg_error("<rect transform=\"translate(1,2\" width=\"1\" height=\"1\"/>").find("unclosed"),
        std::string::npos);
    EXPECT_NE(svg_error("<rect fill-rule=\"odd\" width=\"1\" height=\"1\"/>").find("fill-rule"),
              std::string::npos);
}

TEST(region_errors, DeepNesting) {
    std::string body;
    for (int i = 0; i < 300; ++i) body += "<g>";
    body += "<rect width=\"1\" height=\"1\"/>";
    for (int i = 0; i < 300; ++i) body += "</g>";
    std::string m = svg_error(body);
    EXPECT_NE(m.find("nested deeper"), std::string::npos) << m;
    EXPECT_NE(m.find("bad.svg"), std::string::npos) << m;
}

TEST(region_errors, UseCycleAndUnknownReference) {
    std::string cycle =
        svg_error("<g id=\"a\"><use href=\"#b\"/></g><g id=\"b\"><use href=\"#a\"/></g>");
    EXPECT_NE(cycle.find("bad.svg"), std::string::npos) << cycle;
    std::string self = svg_error("<g id=\"a\"><use href=\"#a\"/></g>");
    EXPECT_NE(self.find("ancestor"), std::string::npos) << self;
    std::string unknown = svg_error("<use id=\"u1\" href=\"#nothing\"/>");
    EXPECT_NE(unknown.find("<use id=\"u1\">"), std::string::npos) << unknown;
    EXPECT_NE(unknown.find("#nothing"), std::string::npos) << unknown;
}

TEST(region_errors, ExponentialUseFanOutIsBounded) {
    // Each level uses the previous one ten times: 10^6 copies if expanded.
    std::string body = "<defs><rect id=\"l0\" width=\"1\" height=\"1\"/>";
    for (int level = 1; level <= 6; ++level) {
        body += "<g id=\"l" + std::to_string(level) + "\">";
        for (int k = 0; k < 10; ++k)
            body += "<use href=\"#l" + std::to_string(level - 1) + "\" x=\"" + std::to_string(k) +
                    "\"/>";
        body += "</g>";
    }
    body += "</defs><use href=\"#l6\"/>";
    std::string m = svg_error(body);
    EXPECT_NE(m.find("expansions"), std::string::npos) << m;
}

TEST(region_errors, BadSpecs) {
    for (const char* spec :
         {"rect:0,5", "rect:-1,5", "rect:a,5", "rect:5", "rect:5,5,5", "circle:", "circle:inf",
          "circle:nan", "circle:1e999", "ellipse:3", "ellipse:3,0", "rect:5,", "square:5"}) {
        std::string m = error_of([&] { Region::from_spec(spec); });
        EXPECT_NE(m.find(std::string("\"") + spec + "\""), std::string::npos) << spec << ": " << m;
    }
    EXPECT_NE(error_of([] { Region::from_argument("rect:1,x"); }).find("not a number"),
              std::string::npos);
}
