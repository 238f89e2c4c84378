// The mason's cut list: its counts are those of the laid cells (counted here from the cells'
// shapes on their own), CSV and JSON agree, and a file that cannot be written is refused whole.
#include <gtest/gtest.h>

#include <acanthus/error.hpp>
#include <acanthus/stdlib/cells.hpp>
#include <acanthus/stdlib/cells/cut_list.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

using namespace acanthus;
using namespace acanthus::cells;

namespace {

Options centimetres(Bond bond) {  // as rules/facade.acr lays them
    Options o;
    o.brick_length = 21.5, o.brick_height = 6.5, o.mortar = 1, o.joint_tolerance = 0.3;
    o.bond = bond;
    return o;
}

Facade example(const char* name) {
    return Facade::from_svg_file(std::string(ACANTHUS_SOURCE_DIR) + "/examples/facades/" + name +
                                 ".svg");
}

// Width and height of a cell when it is an axis-aligned rectangle of four corners.
bool box(const Cell& c, double& w, double& h) {
    if (c.polygon.size() != 4) return false;
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    for (const Point& p : c.polygon) {
        x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
        y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    }
    for (const Point& p : c.polygon)
        if ((std::abs(p.x - x0) > 1e-9 && std::abs(p.x - x1) > 1e-9) ||
            (std::abs(p.y - y0) > 1e-9 && std::abs(p.y - y1) > 1e-9))
            return false;
    w = x1 - x0, h = y1 - y0;
    return true;
}

struct Row {
    std::string generator, kind;
    long count = 0;
    long width = 0, height = 0, intrados = -1, extrados = -1;
};

std::vector<Row> parse_csv(const std::string& text) {
    std::vector<Row> rows;
    std::istringstream in(text);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "facade,generator,kind,count,width_mm,height_mm,intrados_mm,extrados_mm");
    while (std::getline(in, line)) {
        std::vector<std::string> f;
        std::stringstream ls(line);
        std::string cell;
        while (std::getline(ls, cell, ',')) f.push_back(cell);
        if (line.back() == ',') f.push_back("");
        EXPECT_EQ(f.size(), 8u) << line;
        if (f.size() != 8) continue;
        Row r{f[1], f[2], std::stol(f[3]), std::stol(f[4]), std::stol(f[5])};
        if (!f[6].empty()) r.intrados = std::stol(f[6]), r.extrados = std::stol(f[7]);
        rows.push_back(r);
    }
    return rows;
}

long total(const std::vector<Row>& rows, const std::string& kind) {
    long n = 0;
    for (const Row& r : rows) n += r.kind == kind ? r.count : 0;
    return n;
}

// Cells of `generator` whose face is a rectangle `w` x `h` (cm) within a millimetre.
long count_rects(const std::vector<Cell>& cells, const std::string& generator, double w, double h) {
    long n = 0;
    for (const Cell& c : cells) {
        double cw = 0, ch = 0;
        if (c.generator == generator && box(c, cw, ch) && std::abs(cw - w) <= 0.1 &&
            std::abs(ch - h) <= 0.1)
            ++n;
    }
    return n;
}

long of_generator(const std::vector<Row>& rows, const std::string& generator) {
    long n = 0;
    for (const Row& r : rows) n += r.generator == generator ? r.count : 0;
    return n;
}

long count_generator(const std::vector<Cell>& cells, const std::string& generator) {
    long n = 0;
    for (const Cell& c : cells) n += c.generator == generator;
    return n;
}

}  // namespace

TEST(CellsCutList, CountsAreTheLaidCells) {
    for (Bond bond : {Bond::english, Bond::flemish, Bond::running}) {
        SCOPED_TRACE(std::string(to_string(bond)));
        Facade f = example("row-house");
        Options o = centimetres(bond);
        Texture t = texture(f, brick_tree(), o, 7);
        std::vector<Row> rows = parse_csv(cut_list_csv(cut_list(f, t.cells, o, 10)));
        long all = 0;
        for (const Row& r : rows) all += r.count;
        EXPECT_EQ(all, static_cast<long>(t.cells.size()));
        // Quarter brick: 5.625 cm with its joint.
        const long whole = count_rects(t.cells, "bricks", 21.5, 6.5);
        EXPECT_GT(whole, 100);
        EXPECT_EQ(total(rows, "stretcher"), whole);
        const long halves = count_rects(t.cells, "bricks", 10.25, 6.5);
        EXPECT_EQ(total(rows, bond == Bond::running ? "half bat" : "header"), halves);
        if (bond != Bond::running) {
            EXPECT_GT(halves, 100);
        }
        // A king closer's face is a three-quarter bat's (Flemish bond: 104 on the row-house now
        // that its jambs fall on joints and the closers beside them are whole).
        EXPECT_EQ(total(rows, "three-quarter bat") + total(rows, "king closer"),
                  count_rects(t.cells, "bricks", 15.875, 6.5));
        EXPECT_EQ(total(rows, "queen closer"), count_rects(t.cells, "bricks", 4.625, 6.5));
        EXPECT_EQ(total(rows, "soldier"), count_generator(t.cells, "soldier_course"));
        EXPECT_GT(total(rows, "soldier"), 0);
        EXPECT_EQ(total(rows, "sill header"), count_generator(t.cells, "window_bottom"));
        EXPECT_EQ(total(rows, "voussoir") + total(rows, "skewback"),
                  count_generator(t.cells, "arch_stones"));
        // Voussoirs taper outwards; each line's sizes are whole millimetres of a real stone.
        EXPECT_GT(total(rows, "voussoir"), 0);
        for (const Row& r : rows) {
            EXPECT_GT(r.width, 0);
            EXPECT_GT(r.height, 0);
            if (r.kind == "voussoir") {
                EXPECT_GT(r.extrados, r.intrados);
            }
            if (r.kind == "stretcher") {  // whole within a millimetre, as the checker takes it
                EXPECT_LE(std::abs(r.width - 215), 1);
            }
            if (r.kind == "stretcher" || r.kind == "header") {
                EXPECT_EQ(r.height, 65);
            }
        }
    }
}

TEST(CellsCutList, JsonAgreesWithCsv) {
    Facade f = example("gable");
    Options o = centimetres(Bond::flemish);
    Texture t = texture(f, brick_tree(), o, 3);
    std::vector<CutListItem> items = cut_list(f, t.cells, o, 10);
    std::vector<Row> rows = parse_csv(cut_list_csv(items));
    nlohmann::json doc = nlohmann::json::parse(cut_list_json(items));
    ASSERT_EQ(doc["facades"].size(), 1u);
    EXPECT_EQ(doc["facades"][0]["name"], f.name());
    const nlohmann::json& pieces = doc["facades"][0]["pieces"];
    ASSERT_EQ(pieces.size(), rows.size());
    for (std::size_t i = 0; i < rows.size(); ++i) {
        EXPECT_EQ(pieces[i]["generator"], rows[i].generator);
        EXPECT_EQ(pieces[i]["kind"], rows[i].kind);
        EXPECT_EQ(pieces[i]["count"], rows[i].count);
        EXPECT_EQ(pieces[i]["width_mm"], rows[i].width);
        EXPECT_EQ(pieces[i]["height_mm"], rows[i].height);
        if (rows[i].kind == "voussoir") {
            EXPECT_EQ(pieces[i]["intrados_mm"], rows[i].intrados);
            EXPECT_EQ(pieces[i]["extrados_mm"], rows[i].extrados);
        }
    }
    // The same seed, the same bytes.
    Texture again = texture(f, brick_tree(), o, 3);
    EXPECT_EQ(cut_list_json(cut_list(f, again.cells, o, 10)), cut_list_json(items));
}

TEST(CellsCutList, AshlarStonesBySize) {
    Facade f = example("row-house");
    Options o = centimetres(Bond::ashlar);
    Texture t = texture(f, ashlar_tree(), o, 1);
    std::vector<Row> rows = parse_csv(cut_list_csv(cut_list(f, t.cells, o, 10)));
    // Stones cut to an arch's extrados are shaped cuts.
    EXPECT_EQ(of_generator(rows, "ashlar"), count_generator(t.cells, "ashlar"));
    EXPECT_GT(total(rows, "ashlar stone"), count_generator(t.cells, "ashlar") * 9 / 10);
    EXPECT_EQ(total(rows, "sill stone"), count_generator(t.cells, "window_bottom"));
    EXPECT_GT(total(rows, "ashlar stone"), 0);
    EXPECT_GT(total(rows, "lintel"), 0);
}

TEST(CellsCutList, FramedTreeQuoinsAndLintels) {
    Facade f = example("row-house");
    Options o = centimetres(Bond::flemish);
    Texture t = texture(f, framed_tree(), o, 1);
    std::vector<Row> rows = parse_csv(cut_list_csv(cut_list(f, t.cells, o, 10)));
    EXPECT_EQ(of_generator(rows, "quoins"), count_generator(t.cells, "quoins"));
    EXPECT_EQ(total(rows, "quoin stone"), of_generator(rows, "quoins"));  // rectangles all
    EXPECT_GT(total(rows, "quoin stone"), 0);
    EXPECT_EQ(total(rows, "lintel"), count_generator(t.cells, "lintel"));
    EXPECT_EQ(total(rows, "stretcher"), count_rects(t.cells, "bricks", 21.5, 6.5));
}

TEST(CellsCutList, WritesWholeFileOrNone) {
    namespace fs = std::filesystem;
    Facade f = example("oculus");
    Options o = centimetres(Bond::english);
    std::vector<CutListItem> items = cut_list(f, texture(f, brick_tree(), o, 1).cells, o, 10);
    const fs::path dir = fs::path(::testing::TempDir()) / "cells_cut_list";
    fs::create_directories(dir);
    const std::string csv = (dir / "list.csv").string(), json = (dir / "list.json").string();
    write_cut_list(csv, items);
    write_cut_list(json, items);
    std::ifstream a(csv), b(json);
    std::stringstream sa, sb;
    sa << a.rdbuf();
    sb << b.rdbuf();
    EXPECT_EQ(sa.str(), cut_list_csv(items));
    EXPECT_EQ(sb.str(), cut_list_json(items));

    // A directory that does not exist: an InputError naming the file, nothing written.
    const std::string bad = (dir / "missing" / "list.csv").string();
    try {
        write_cut_list(bad, items);
        ADD_FAILURE() << "no error for " << bad;
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(dir / "missing"));
    EXPECT_THROW(write_cut_list((dir / "list.txt").string(), items), InputError);
    EXPECT_FALSE(fs::exists(dir / "list.txt"));
    fs::remove_all(dir);
}
