// SVG region reading beyond the shapes themselves: XML namespaces resolved by URI (elements and
// href), DOCTYPE entities, style sheets, percentages, viewports (nested svg, symbol), switch,
// and lib2geom failures on hostile arcs turned into InputError.
#include <gtest/gtest.h>

#include <acanthus/error.hpp>
#include <acanthus/region.hpp>
#include <cmath>
#include <string>

#include "svg/attributes.hpp"

using acanthus::InputError;
using acanthus::Region;

namespace {

constexpr double kArcArea = 1e-3;  // arcs are held as cubics within 6e-9 of the radius
const std::string kSvg = "xmlns=\"http://www.w3.org/2000/svg\"";
const std::string kXlink = "http://www.w3.org/1999/xlink";

Region doc(const std::string& text) { return Region::from_svg_string(text, "ns.svg"); }

// A root in the SVG namespace with `attrs` and `body`.
Region svg(const std::string& body, const std::string& attrs = "") {
    return doc("<svg " + kSvg + " " + attrs + ">" + body + "</svg>");
}

// The message of the InputError `text` raises ("" and a failure when there is none).
std::string error_of(const std::string& text) {
    try {
        doc(text);
    } catch (const InputError& e) {
        return e.what();
    }
    ADD_FAILURE() << "no InputError for " << text;
    return "";
}

const std::string kTile = "<defs><rect id=\"s\" width=\"10\" height=\"10\"/></defs>";
const std::string kMarker = "<rect x=\"100\" width=\"1\" height=\"1\"/>";  // area 1, far away

}  // namespace

TEST(region_namespaces, XlinkHrefUnderAnyPrefix) {
    // The case: a0 bound to the XLink namespace.
    EXPECT_NEAR(svg(kTile + "<use a0:href=\"#s\"/>", "xmlns:a0=\"" + kXlink + "\"").area(), 100,
                1e-9);
    // Declared on the use itself, or on a group around it.
    EXPECT_NEAR(svg(kTile + "<use xmlns:l=\"" + kXlink + "\" l:href=\"#s\"/>").area(), 100, 1e-9);
    EXPECT_NEAR(
        svg(kTile + "<g xmlns:xl=\"" + kXlink + "\"><use xl:href=\"#s\" x=\"5\"/></g>").bounds().x0,
        5, 1e-9);
}

TEST(region_namespaces, PlainHrefWinsOverXlinkHref) {
    Region r =
        svg("<defs><rect id=\"a\" width=\"10\" height=\"10\"/><rect id=\"b\" width=\"20\" "
            "height=\"20\"/></defs><use href=\"#b\" xlink:href=\"#a\"/>",
            "xmlns:xlink=\"" + kXlink + "\"");
    EXPECT_NEAR(r.area(), 400, 1e-9);
}

TEST(region_namespaces, HrefOfAnotherNamespaceIsNoReference) {
    // x:href with x bound elsewhere draws nothing; so does xlink:href once the xlink prefix is
    // bound to another URI further in.
    EXPECT_NEAR(
        svg(kTile + kMarker + "<use xmlns:x=\"http://example.org/x\" x:href=\"#s\"/>").area(), 1,
        1e-9);
    EXPECT_NEAR(svg(kTile + kMarker +
                        "<g xmlns:xlink=\"http://example.org/x\"><use xlink:href=\"#s\"/></g>",
                    "xmlns:xlink=\"" + kXlink + "\"")
                    .area(),
                1, 1e-9);
}

TEST(region_namespaces, UndeclaredHrefPrefixIsRefused) {
    std::string m =
        error_of("<svg " + kSvg + ">\n" + kTile + "\n<use id=\"u\" xlink:href=\"#s\"/></svg>");
    EXPECT_NE(m.find("ns.svg:3"), std::string::npos) << m;
    EXPECT_NE(m.find("<use id=\"u\">"), std::string::npos) << m;
    EXPECT_NE(m.find("prefix 'xlink' is not declared"), std::string::npos) << m;
}

TEST(region_namespaces, PrefixedSvgElements) {
    Region r = doc("<svg:svg xmlns:svg=\"http://www.w3.org/2000/svg\" xmlns:l=\"" + kXlink +
                   "\"><svg:defs><svg:path id=\"t\" d=\"M0,0 H10 V10 Z\"/></svg:defs>"
                   "<svg:g transform=\"translate(10,0)\"><svg:rect width=\"10\" height=\"10\"/>"
                   "<svg:use l:href=\"#t\" x=\"20\"/></svg:g></svg:svg>");
    EXPECT_NEAR(r.area(), 150, 1e-9);
    EXPECT_NEAR(r.bounds().x1, 40, 1e-9);
    // Inkscape declares both the default and the svg prefix.
    Region inkscape =
        svg("<svg:rect width=\"10\" height=\"10\"/><rect x=\"20\" width=\"10\" height=\"10\"/>",
            "xmlns:svg=\"http://www.w3.org/2000/svg\"");
    EXPECT_NEAR(inkscape.area(), 200, 1e-9);
}

TEST(region_namespaces, ElementsOfOtherNamespacesAreSkipped) {
    // svg: bound to another URI; a default namespace of another URI on a group skips the
    // group with everything in it, even elements prefixed back into SVG.
    EXPECT_NEAR(svg(kMarker + "<svg:rect width=\"10\" height=\"10\"/>",
                    "xmlns:svg=\"http://example.org/not-svg\"")
                    .area(),
                1, 1e-9);
    EXPECT_NEAR(svg(kMarker + "<g xmlns=\"http://example.org/x\"><rect width=\"10\" height=\"10\"/>"
                              "<s:rect width=\"10\" height=\"10\"/></g>",
                    "xmlns:s=\"http://www.w3.org/2000/svg\"")
                    .area(),
                1, 1e-9);
    // An undeclared element prefix is skipped, not refused.
    EXPECT_NEAR(svg(kMarker + "<foo:rect width=\"10\" height=\"10\"/>").area(), 1, 1e-9);
}

TEST(region_namespaces, NoNamespaceIsReadAsSvg) {
    // A hand-written file without xmlns, and xmlns="" inside an SVG file: rsvg draws both.
    EXPECT_NEAR(doc("<svg><rect width=\"10\" height=\"10\"/></svg>").area(), 100, 1e-9);
    EXPECT_NEAR(svg("<g xmlns=\"\"><rect width=\"10\" height=\"10\"/></g>").area(), 100, 1e-9);
}

TEST(region_namespaces, RootOfAnotherNamespaceIsRefused) {
    std::string m = error_of("<x:svg xmlns:x=\"http://example.org/x\"><rect/></x:svg>");
    EXPECT_NE(m.find("not an SVG file"), std::string::npos) << m;
}

TEST(region_namespaces, UseTargetIsReadInItsOwnScope) {
    // The target's prefix is declared where the target stands, not where the use stands.
    Region r =
        svg("<defs xmlns:q=\"http://www.w3.org/2000/svg\"><q:rect id=\"t\" width=\"10\" "
            "height=\"10\"/><q:symbol id=\"y\"><q:rect width=\"5\" height=\"5\"/></q:symbol></defs>"
            "<use href=\"#t\"/><use href=\"#y\" x=\"20\"/>");
    EXPECT_NEAR(r.area(), 125, 1e-9);
    // And a target in a foreign scope stays foreign, whatever the use's scope says.
    EXPECT_NEAR(svg(kMarker + "<g xmlns=\"http://example.org/x\"><rect id=\"f\" width=\"10\" "
                              "height=\"10\"/></g><use href=\"#f\"/>")
                    .area(),
                1, 1e-9);
}

TEST(region_namespaces, DoctypeEntitiesInNamespaceUris) {
    // As Adobe Illustrator writes files.
    Region r =
        doc("<?xml version=\"1.0\"?>\n<!DOCTYPE svg PUBLIC \"-//W3C//DTD SVG 1.1//EN\" "
            "\"http://www.w3.org/Graphics/SVG/1.1/DTD/svg11.dtd\" [\n"
            "<!ENTITY ns_svg \"http://www.w3.org/2000/svg\">\n<!ENTITY ns_xlink '" +
            kXlink +
            "'>\n<!ENTITY ns_ai \"http://ns.adobe.com/AdobeIllustrator/10.0/\">\n"
            "<!ENTITY % param \"ignored\">\n]>\n"
            "<svg xmlns=\"&ns_svg;\" xmlns:xlink=\"&ns_xlink;\" xmlns:i=\"&ns_ai;\"><switch>"
            "<foreignObject requiredExtensions=\"&ns_ai;\"><i:pgfRef xlink:href=\"#x\"/>"
            "</foreignObject><g i:extraneous=\"self\"><rect id=\"r\" width=\"10\" height=\"10\"/>"
            "<use xlink:href=\"#r\" x=\"20\"/></g></switch></svg>");
    EXPECT_NEAR(r.area(), 200, 1e-9);
}

TEST(region_namespaces, EntityExpansionIsBounded) {
    std::string big(1 << 20, 'a');
    std::string refs;
    for (int i = 0; i < 70; ++i) refs += "&e;";
    std::string m = error_of("<!DOCTYPE svg [<!ENTITY e \"" + big + "\">]><svg " + kSvg +
                             "><rect width=\"1\" height=\"1\" class=\"" + refs + "\"/></svg>");
    EXPECT_NE(m.find("entities expand"), std::string::npos) << m;
}

TEST(region_namespaces, ArcLib2geomCannotPlaceIsInputError) {
    // The case: lib2geom throws while placing the arc; never escapes as its exception.
    for (const char* d :
         {"M 1e88,0 A 1,1 6 0 0 0,1 Z", "M 0,0 A 1e-320,1e-320 0 0 0 1,1 L 1,0 Z"}) {
        std::string m =
            error_of("<svg " + kSvg + ">\n<path id=\"p\" d=\"" + std::string(d) + "\"/></svg>");
        EXPECT_NE(m.find("ns.svg:2: <path id=\"p\">"), std::string::npos) << m;
        EXPECT_NE(m.find("elliptical arc"), std::string::npos) << m;
    }
}

TEST(region_namespaces, SingularTransformDrawsNothing) {
    EXPECT_NEAR(svg(kMarker + "<circle r=\"10\" transform=\"scale(0)\"/>").area(), 1, 1e-9);
    EXPECT_NEAR(
        svg(kMarker + "<rect width=\"5\" height=\"5\" transform=\"matrix(1,2,2,4,0,0)\"/>").area(),
        1, 1e-9);
}

TEST(region_namespaces, PercentagesOfTheViewport) {
    // Of the root viewBox (x, width: its width; y, height: its height; r: the normalized
    // diagonal), else of the root's absolute width and height.
    Region r = svg("<rect x=\"10%\" y=\"50%\" width=\"50%\" height=\"25%\"/>",
                   "width=\"10cm\" viewBox=\"0 0 200 100\"");
    EXPECT_NEAR(r.bounds().x0, 20, 1e-9);
    EXPECT_NEAR(r.bounds().y0, 50, 1e-9);
    EXPECT_NEAR(r.area(), 100 * 25, 1e-9);
    Region c = svg("<circle cx=\"50%\" cy=\"50%\" r=\"10%\"/>", "width=\"300\" height=\"400\"");
    double r10 = 0.1 * std::sqrt((300.0 * 300 + 400 * 400) / 2);
    EXPECT_NEAR(c.area(), M_PI * r10 * r10, kArcArea);
    EXPECT_NEAR(c.bounds().x0, 150 - r10, 1e-6);
    // A nested svg is the viewport of what it holds.
    Region n =
        svg("<svg x=\"10\" width=\"40\" height=\"20\"><rect width=\"50%\" height=\"100%\"/></svg>",
            "viewBox=\"0 0 100 100\"");
    EXPECT_NEAR(n.area(), 20 * 20, 1e-9);
    std::string m = error_of("<svg " + kSvg + "><rect width=\"10%\" height=\"10\"/></svg>");
    EXPECT_NE(m.find("percentage of a viewport of unknown size"), std::string::npos) << m;
}

TEST(region_namespaces, SymbolViewBoxFittedIntoUse) {
    const std::string sym =
        "<symbol id=\"i\" viewBox=\"0 0 10 20\"><rect width=\"10\" height=\"20\"/></symbol>";
    // meet: scale 2 into 40 x 40, centred across.
    Region r = svg(sym + "<use href=\"#i\" x=\"5\" width=\"40\" height=\"40\"/>");
    EXPECT_NEAR(r.bounds().x0, 5 + 10, 1e-9);
    EXPECT_NEAR(r.bounds().x1, 5 + 30, 1e-9);
    EXPECT_NEAR(r.area(), 20 * 40, 1e-9);
    // none: stretched; xMaxYMax slice: scale 4, flush right and bottom.
    Region none = svg(
        "<symbol id=\"i\" viewBox=\"0 0 10 20\" preserveAspectRatio=\"none\"><rect width=\"10\" "
        "height=\"20\"/></symbol><use href=\"#i\" width=\"40\" height=\"40\"/>");
    EXPECT_NEAR(none.area(), 1600, 1e-9);
    Region slice =
        svg("<symbol id=\"i\" viewBox=\"0 0 10 20\" preserveAspectRatio=\"xMaxYMax slice\"><rect "
            "width=\"10\" height=\"20\"/></symbol><use href=\"#i\" width=\"40\" height=\"40\"/>");
    EXPECT_NEAR(slice.bounds().y1, 40, 1e-9);
    EXPECT_NEAR(slice.area(), 40 * 80, 1e-9);
    // A missing size is 100% of the viewport; a zero size draws nothing.
    Region full = svg(sym + "<use href=\"#i\"/>", "viewBox=\"0 0 100 100\"");
    EXPECT_NEAR(full.area(), 50 * 100, 1e-9);
    EXPECT_NEAR(svg(kMarker + sym + "<use href=\"#i\" width=\"0\" height=\"40\"/>").area(), 1,
                1e-9);
}

TEST(region_namespaces, UseSizeReplacesReferencedSvgSize) {
    Region r =
        svg("<defs><svg id=\"v\" width=\"10\" height=\"10\" viewBox=\"0 0 1 1\"><rect width=\"1\" "
            "height=\"1\"/></svg></defs><use href=\"#v\" width=\"30\" height=\"30\"/>");
    EXPECT_NEAR(r.area(), 900, 1e-9);
}

TEST(region_namespaces, SwitchDrawsFirstPassingChild) {
    Region r = svg(
        "<switch><rect requiredExtensions=\"http://example.org/e\" width=\"100\" height=\"100\"/>"
        "<rect systemLanguage=\"en\" width=\"100\" height=\"100\"/>"
        "<rect requiredFeatures=\"http://www.w3.org/TR/SVG11/feature#Extensibility\" "
        "width=\"100\" height=\"100\"/>"
        "<rect requiredFeatures=\"http://www.w3.org/TR/SVG11/feature#Shape\" width=\"10\" "
        "height=\"10\"/><rect width=\"50\" height=\"50\"/></switch>");
    EXPECT_NEAR(r.area(), 100, 1e-9);
    // The first passing child is chosen whatever it is: text draws nothing here.
    EXPECT_NEAR(
        svg(kMarker + "<switch><text>t</text><rect width=\"9\" height=\"9\"/></switch>").area(), 1,
        1e-9);
}

TEST(region_namespaces, AspectRatioParsing) {
    using acanthus::detail::parse_aspect_ratio;
    auto a = parse_aspect_ratio("");
    EXPECT_FALSE(a.none);
    EXPECT_DOUBLE_EQ(a.align_x, 0.5);
    EXPECT_FALSE(a.slice);
    a = parse_aspect_ratio(" defer xMinYMax  slice ");
    EXPECT_DOUBLE_EQ(a.align_x, 0);
    EXPECT_DOUBLE_EQ(a.align_y, 1);
    EXPECT_TRUE(a.slice);
    EXPECT_TRUE(parse_aspect_ratio("none").none);
    for (const char* bad : {"xMinYMoo", "meet", "xMidYMid cover", "none meet extra"})
        EXPECT_THROW(parse_aspect_ratio(bad), acanthus::detail::SvgSyntaxError) << bad;
    Geom::Affine m =
        acanthus::detail::viewbox_transform({0, 0, 10, 20}, parse_aspect_ratio(""), 5, 0, 40, 40);
    EXPECT_NEAR((Geom::Point(0, 0) * m)[Geom::X], 15, 1e-12);
    EXPECT_NEAR((Geom::Point(10, 20) * m)[Geom::Y], 40, 1e-12);
}

TEST(region_namespaces, StyleSheetFillRuleAndDisplay) {
    const std::string frame = " d=\"M0,0 H40 V40 H0 Z M10,10 H30 V30 H10 Z\"/>";
    auto area = [&](const std::string& sheet, const std::string& attrs) {
        return svg("<style>" + sheet + "</style><path " + attrs + frame).area();
    };
    EXPECT_NEAR(area(".a{fill:#fff;fill-rule:evenodd}", "class=\"b a\""), 1200, 1e-9);
    EXPECT_NEAR(area("#p{fill-rule:evenodd}", "id=\"p\""), 1200, 1e-9);
    EXPECT_NEAR(area("path{fill-rule:evenodd}", ""), 1200, 1e-9);
    // Specificity, then order; the style attribute wins unless the rule is !important; the
    // sheet wins over the presentation attribute.
    EXPECT_NEAR(area("path.a{fill-rule:evenodd} .a{fill-rule:nonzero}", "class=\"a\""), 1200, 1e-9);
    EXPECT_NEAR(area(".a{fill-rule:evenodd} .a{fill-rule:nonzero}", "class=\"a\""), 1600, 1e-9);
    EXPECT_NEAR(area(".a{fill-rule:evenodd}", "class=\"a\" style=\"fill-rule:nonzero\""), 1600,
                1e-9);
    EXPECT_NEAR(area(".a{fill-rule:evenodd!important}", "class=\"a\" style=\"fill-rule:nonzero\""),
                1200, 1e-9);
    EXPECT_NEAR(area(".a{fill-rule:evenodd}", "class=\"a\" fill-rule=\"nonzero\""), 1200, 1e-9);
    // Comments, at-rules and selectors a region does not match are left out.
    EXPECT_NEAR(area("/* .a{fill-rule:evenodd} */ @media screen{.a{fill-rule:evenodd}} "
                     "path:first-child{fill-rule:evenodd} [class]{fill-rule:evenodd}",
                     "class=\"a\""),
                1600, 1e-9);
    // Descendant and child combinators; display:none hides what it matches.
    Region r =
        svg("<style><![CDATA[ g.l > .h, svg g .x { display: none } ]]></style>" + kMarker +
            "<g class=\"l\"><rect class=\"h\" width=\"9\" height=\"9\"/><g><rect class=\"h x\" "
            "width=\"9\" height=\"9\"/></g></g><rect class=\"h\" x=\"50\" width=\"2\" "
            "height=\"2\"/>");
    EXPECT_NEAR(r.area(), 1 + 4, 1e-9);
}
