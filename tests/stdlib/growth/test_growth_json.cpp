// The reference JSON of issue 10: a good file loads with the documented defaults; every bad input
// throws InputError naming the file and, where there is one, the element or flip.
#include <gtest/gtest.h>

#include <acanthus/error.hpp>
#include <acanthus/stdlib/growth.hpp>
#include <filesystem>
#include <fstream>
#include <string>

using namespace acanthus;
using namespace acanthus::growth;

namespace {

// A hexagon of six around a centre: the centre is surrounded, so it has a ring to copy.
const char* kGood = R"({"elements": [
  {"symbol": "a", "label": "1", "x": 0, "y": 0, "angle": 0.5, "size": 3},
  {"symbol": "b", "x": 10, "y": 0},
  {"symbol": "a", "x": 5, "y": 8.66},
  {"symbol": "b", "x": -5, "y": 8.66},
  {"symbol": "a", "x": -10, "y": 0},
  {"symbol": "b", "x": -5, "y": -8.66},
  {"symbol": "a", "x": 5, "y": -8.66}
], "flips": []})";

// The message of the InputError `text` raises, or "" when it loads.
std::string error_of(const std::string& text) {
    try {
        Reference::from_json_string(text, "ref.json");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

void expect_error(const std::string& text, const std::string& part) {
    std::string message = error_of(text);
    ASSERT_FALSE(message.empty()) << "loaded: " << text;
    EXPECT_NE(message.find("ref.json"), std::string::npos) << message;
    EXPECT_NE(message.find(part), std::string::npos) << message;
}

TEST(GrowthJson, GoodFileLoadsWithDefaults) {
    Reference ref = Reference::from_json_string(kGood, "ref.json");
    ASSERT_EQ(ref.size(), 7u);
    EXPECT_EQ(ref.element(0).label, "1");
    EXPECT_DOUBLE_EQ(ref.element(0).angle, 0.5);
    EXPECT_DOUBLE_EQ(ref.radius(0), 3);
    EXPECT_EQ(ref.element(1).label, "");
    EXPECT_DOUBLE_EQ(ref.element(1).angle, 0);
    EXPECT_NEAR(ref.radius(1), 0.35 * ref.mean_edge_length(), 1e-12);
    EXPECT_EQ(ref.edges().size(), 12u);
}

TEST(GrowthJson, SubIsTheLabelsOldName) {
    std::string old = kGood;
    old.replace(old.find("\"label\""), 7, "\"sub\"");
    EXPECT_EQ(Reference::from_json_string(old, "ref.json").element(0).label, "1");
    const std::string head = R"({"elements": [{"symbol": "a", "x": 0, "y": 0},
                                  {"symbol": "a", "x": 1, "y": 0}, )";
    expect_error(head + R"({"symbol": "a", "x": 0, "y": 1, "label": "p", "sub": "q"}]})",
                 "element 2: \"label\" and its old name \"sub\" both given");
    expect_error(head + R"({"symbol": "a", "x": 0, "y": 1, "label": 7}]})",
                 "element 2: \"label\" is not a string");
}

TEST(GrowthJson, FileIsReadFromDisk) {
    auto path = std::filesystem::temp_directory_path() / "growth_test_ref.json";
    std::ofstream(path) << kGood;
    EXPECT_EQ(Reference::from_json_file(path.string()).size(), 7u);
    std::filesystem::remove(path);
}

TEST(GrowthJson, MissingFile) {
    try {
        Reference::from_json_file("/nonexistent/ref.json");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/ref.json"), std::string::npos);
    }
}

TEST(GrowthJson, ErrorsSayLineAndColumnAndOutOfRange) {
    // Issue 27: a malformed file says where, and a number no double holds is called out of range.
    expect_error("{\"elements\": [\n  {\"symbol\": \"a\", \"x\": 0,, \"y\": 0}]}",
                 "ref.json:2:26: malformed JSON");
    expect_error("{\"elements\": [\n  {\"symbol\": \"a\", \"x\": 1e999, \"y\": 0}]}",
                 "ref.json:2:24: number out of range: 1e999");
    expect_error("{\"elements\": [{\"symbol\": \"a\", \"x\": 1, \"y\": -2e400}]}",
                 "number out of range: -2e400");
}

TEST(GrowthJson, NoSurroundedElementIsRefusedWithTheReason) {
    // Four in a row of triangles: every element is on the boundary, no ring to copy.
    expect_error(R"({"elements": [{"symbol": "a", "x": 0, "y": 0}, {"symbol": "a", "x": 10, "y": 0},
                  {"symbol": "a", "x": 5, "y": 8.66}, {"symbol": "a", "x": 15, "y": 8.66}]})",
                 "ref.json: no element is surrounded by its neighbours");
}

TEST(GrowthJson, MalformedJson) {
    expect_error(R"({"elements": [{"symbol": "a", "x": 0, "y": 0},)", "malformed JSON");
    expect_error(R"([1, 2, 3])", "\"elements\"");
    expect_error(std::string(100000, '[') + std::string(100000, ']'), "nested too deeply");
}

TEST(GrowthJson, ElementWithoutSymbolOrCoordinates) {
    const std::string head = R"({"elements": [{"symbol": "a", "x": 0, "y": 0},
                                  {"symbol": "a", "x": 1, "y": 0}, )";
    expect_error(head + R"({"x": 0, "y": 1}]})", "element 2: missing \"symbol\"");
    expect_error(head + R"({"symbol": "a", "y": 1}]})", "element 2: missing \"x\"");
    expect_error(head + R"({"symbol": "a", "x": 1}]})", "element 2: missing \"y\"");
    expect_error(head + R"({"symbol": 3, "x": 0, "y": 1}]})", "element 2: \"symbol\"");
    expect_error(head + R"({"symbol": "a", "x": "1", "y": 1}]})", "element 2: \"x\"");
}

TEST(GrowthJson, FewerThanThreeElements) {
    expect_error(R"({"elements": [{"symbol": "a", "x": 0, "y": 0},
                                  {"symbol": "a", "x": 1, "y": 0}]})",
                 "at least 3 elements");
}

TEST(GrowthJson, AllCollinear) {
    expect_error(R"({"elements": [{"symbol": "a", "x": 0, "y": 0}, {"symbol": "a", "x": 1, "y": 1},
                                  {"symbol": "a", "x": 2, "y": 2}, {"symbol": "a", "x": 3, "y": 3}]})",
                 "one line");
}

TEST(GrowthJson, FlipNamingNoEdge) {
    std::string base = kGood;
    std::string bad = base.substr(0, base.find("\"flips\"")) + R"("flips": [[1, 4]]})";
    expect_error(bad, "flip 0 [1, 4]");
    bad = base.substr(0, base.find("\"flips\"")) + R"("flips": [[0, 7]]})";
    expect_error(bad, "flip 0 [0, 7]");
    bad = base.substr(0, base.find("\"flips\"")) + R"("flips": [[0]]})";
    expect_error(bad, "flip 0");
}

TEST(GrowthJson, NaNAndInfinity) {
    const std::string head = R"({"elements": [{"symbol": "a", "x": 0, "y": 0},
                                  {"symbol": "a", "x": 1, "y": 0}, )";
    // JSON has no NaN: written bare it is malformed, as a string it is not a number, and an
    // overflowing literal is not finite.
    expect_error(head + R"({"symbol": "a", "x": NaN, "y": 1}]})", "malformed JSON");
    expect_error(head + R"({"symbol": "a", "x": "NaN", "y": 1}]})", "element 2: \"x\"");
    expect_error(head + R"({"symbol": "a", "x": 1e999, "y": 1}]})", "");
    expect_error(head + R"({"symbol": "a", "x": 0.5, "y": 1, "angle": 1e999}]})", "");
    // Through the C++ API a NaN coordinate names its element.
    std::vector<ReferenceElement> e{
        {"a", "", {0, 0}, 0, 0}, {"a", "", {1, 0}, 0, 0}, {"a", "", {NAN, 1}, 0, 0}};
    try {
        Reference::from_elements(e, {}, "api");
        FAIL();
    } catch (const InputError& x) {
        EXPECT_NE(std::string(x.what()).find("api: element 2"), std::string::npos) << x.what();
    }
}

TEST(GrowthJson, BadSizeAndDuplicates) {
    const std::string head = R"({"elements": [{"symbol": "a", "x": 0, "y": 0},
                                  {"symbol": "a", "x": 1, "y": 0}, )";
    expect_error(head + R"({"symbol": "a", "x": 0, "y": 1, "size": -2}]})", "element 2");
    expect_error(head + R"({"symbol": "a", "x": 0, "y": 0}]})", "element 2: lies on element 0");
}

TEST(GrowthJson, CoordinatesOutOfRange) {
    // The range regions and placed elements keep (docs/cli.md): ±1e9 is in, beyond is refused.
    const std::string head = R"({"elements": [{"symbol": "a", "x": 0, "y": 0},
                                  {"symbol": "a", "x": 1e9, "y": 0}, )";
    EXPECT_EQ(error_of(head + R"({"symbol": "a", "x": 0, "y": -1e9}]})").find("out of range"),
              std::string::npos);
    expect_error(head + R"({"symbol": "a", "x": 0, "y": -1.5e9}]})",
                 "element 2: coordinates out of range");
    expect_error(head + R"({"symbol": "a", "x": 0, "y": 1, "size": 1e300}]})",
                 "element 2: \"size\" out of range");
}

}  // namespace
