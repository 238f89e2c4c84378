// Checks a facade.acr run from the outside: reads the facade SVG again and the program's --json
// element tree, then asks what issue 11 asks. Cells never overlap, never cover an opening or
// leave the wall; with the joint added back they cover >= 99% of the wall; every window's sill
// has window_bottom cells under >= 80% of its width; every convex corner carries a corner cell.
// In running bond (`running=LENGTH`, the brick length), head joints of consecutive courses are
// at least a quarter brick apart away from openings and corners.
//   check_facade FACADE.svg TREE.json MORTAR [no-sills] [running=LENGTH]
// `no-sills`: skip the window_bottom check (for trees that lay no window bottoms).
// Prints what it found; exit 0 when all hold, 1 otherwise, 2 on bad arguments.
#include <acanthus/error.hpp>
#include <acanthus/input_file.hpp>
#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "../stdlib/cells/cells_oracle.hpp"

using namespace cells_test;
using acanthus::Rect;

namespace {

bool has(const std::vector<std::string>& v, const std::string& s) {
    return std::find(v.begin(), v.end(), s) != v.end();
}

std::vector<Cell> cells_of(const nlohmann::json& tree) {
    std::vector<Cell> out;
    for (const auto& e : tree.at("elements")) {
        if (e.at("type") != "cell") continue;
        Cell c;
        for (const auto& p : e.at("proxies").at(0).at("points"))
            c.polygon.push_back({p.at(0).get<double>(), p.at(1).get<double>()});
        const auto& f = e.at("fields");
        c.generator = f.at("generator").get<std::string>();
        std::string kind = f.at("feature").get<std::string>();
        c.feature = kind == "corner" ? FeatureKind::corner
                    : kind == "edge" ? FeatureKind::edge
                                     : FeatureKind::face;
        c.label = f.at("label").get<std::string>();
        c.course = f.at("course").get<int>();
        out.push_back(std::move(c));
    }
    return out;
}

Rect box_of(const std::vector<Point>& p) {
    Rect r{1e300, 1e300, -1e300, -1e300};
    for (Point q : p)
        r = {std::min(r.x0, q.x), std::min(r.y0, q.y), std::max(r.x1, q.x), std::max(r.y1, q.y)};
    return r;
}

struct Joint {
    double x, y0, y1;
};

// Head joints per course: where two bricks of one course abut (a joint's width apart), not
// within a brick length of an opening or a corner.
std::map<int, std::vector<Joint>> head_joints(const Facade& facade, const std::vector<Cell>& cells,
                                              double mortar, double length) {
    std::map<int, std::vector<Rect>> rows;
    for (const Cell& c : cells)
        if (c.generator == "bricks" && c.course >= 0 && c.polygon.size() == 4)
            rows[c.course].push_back(box_of(c.polygon));
    std::vector<Rect> keep_off;
    for (const auto& o : facade.openings()) {
        Rect b = box_of(o);
        keep_off.push_back({b.x0 - length, b.y0 - length, b.x1 + length, b.y1 + length});
    }
    for (const Corner& k : facade.corners())
        keep_off.push_back({k.position.x - length, k.position.y - length, k.position.x + length,
                            k.position.y + length});
    std::map<int, std::vector<Joint>> out;
    for (auto& [course, rects] : rows) {
        std::sort(rects.begin(), rects.end(), [](Rect a, Rect b) { return a.x0 < b.x0; });
        for (std::size_t i = 0; i + 1 < rects.size(); ++i) {
            Rect a = rects[i], b = rects[i + 1];
            // Head joints open or close within a tolerance so that bricks keep their size.
            const double gap = b.x0 - a.x1;
            if (gap <= 0 || gap > 2 * mortar || std::abs(a.y0 - b.y0) > 1e-6 ||
                std::abs(a.y1 - b.y1) > 1e-6)
                continue;
            Joint j{(a.x1 + b.x0) / 2, a.y0, a.y1};
            bool near = std::any_of(keep_off.begin(), keep_off.end(), [&](Rect r) {
                return j.x > r.x0 && j.x < r.x1 && j.y1 > r.y0 && j.y0 < r.y1;
            });
            if (!near) out[course].push_back(j);
        }
    }
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    bool sills = true;
    double running = 0;
    for (int i = 4; i < argc; ++i) {
        std::string a = argv[i];
        if (a == "no-sills")
            sills = false;
        else if (a.rfind("running=", 0) == 0)
            running = std::atof(a.c_str() + 8);
        else
            argc = 0;
    }
    if (argc < 4) {
        std::cerr
            << "usage: check_facade FACADE.svg TREE.json MORTAR [no-sills] [running=LENGTH]\n";
        return 2;
    }
    const double mortar = std::atof(argv[3]);
    try {
        Facade facade = Facade::from_svg_file(argv[1]);
        Texture t;
        t.cells = cells_of(
            nlohmann::json::parse(acanthus::read_input_file_or_throw(argv[2], "element tree")));
        bool ok = true;
        auto fail = [&](const std::string& why) {
            std::cout << "FAIL " << why << "\n";
            ok = false;
        };
        const double wall = facade.wall_area();
        Report r = check_texture(facade, t, mortar);
        std::cout << t.cells.size() << " cells; overlap " << r.overlap << ", over openings "
                  << r.over_openings << ", outside " << r.outside << ", coverage " << r.coverage
                  << "\n";
        // Exact geometry, drawn with doubles: allow a millionth of the wall for rounding.
        if (r.overlap > 1e-6 * wall) fail("cells overlap");
        if (r.over_openings > 1e-6 * wall) fail("cells cover an opening");
        if (r.outside > 1e-6 * wall) fail("cells leave the wall");
        if (r.coverage < 0.99) fail("coverage below 99%");

        for (const Edge& e : facade.edges()) {
            if (!sills) break;
            if (!e.opening || e.arc || e.part != Part::bottom || !has(e.labels, "window")) continue;
            double x0 = std::min(e.at(0).x, e.at(e.length).x);
            double x1 = std::max(e.at(0).x, e.at(e.length).x), y = e.at(0).y;
            std::vector<std::pair<double, double>> under;
            for (const Cell& c : t.cells) {
                if (c.generator != "window_bottom") continue;
                Rect b = box_of(c.polygon);
                if (b.y0 < y - 1e-6 || b.y0 > y + mortar + 1e-6) continue;  // the course below
                under.push_back({std::max(x0, b.x0 - mortar / 2), std::min(x1, b.x1 + mortar / 2)});
            }
            std::sort(under.begin(), under.end());
            double covered = 0, reach = x0;
            for (auto [a, b] : under) {
                covered += std::max(0.0, b - std::max(a, reach));
                reach = std::max(reach, b);
            }
            std::cout << "sill of " << e.labels.back() << ": " << covered / (x1 - x0)
                      << " under window_bottom\n";
            if (covered < 0.8 * (x1 - x0)) fail("window_bottom under less than 80% of a sill");
        }
        int convex = 0;
        for (const Corner& k : facade.corners()) {
            if (!k.convex) continue;
            ++convex;
            // A corner cell's claim (the drawn cell grown by half the joint) holds the corner.
            bool found = std::any_of(t.cells.begin(), t.cells.end(), [&](const Cell& c) {
                if (c.feature != FeatureKind::corner) return false;
                ClipperLib::ClipperOffset grow(16.0);
                grow.AddPath(to_path(c.polygon), ClipperLib::jtMiter, ClipperLib::etClosedPolygon);
                ClipperLib::Paths claim;
                grow.Execute(claim, (mortar / 2 + 1e-3) * kScale);
                ClipperLib::IntPoint at{std::llround(k.position.x * kScale),
                                        std::llround(k.position.y * kScale)};
                return std::any_of(claim.begin(), claim.end(), [&](const ClipperLib::Path& p) {
                    return ClipperLib::PointInPolygon(at, p) != 0;
                });
            });
            if (!found)
                fail("no corner cell at (" + std::to_string(k.position.x) + ", " +
                     std::to_string(k.position.y) + ")");
        }
        std::cout << convex << " convex corners\n";
        if (running > 0) {
            int compared = 0, close = 0;
            auto joints = head_joints(facade, t.cells, mortar, running);
            for (const auto& [course, xs] : joints) {
                auto next = joints.find(course + 1);
                if (next == joints.end()) continue;
                for (const Joint& a : xs)
                    for (const Joint& b : next->second) {
                        if (std::abs(a.x - b.x) > running) continue;  // far apart: not stacked
                        ++compared;
                        if (std::abs(a.x - b.x) < running / 4 - 1e-6) {
                            ++close;
                            fail("head joints at x " + std::to_string(a.x) + " and " +
                                 std::to_string(b.x) + " in courses " + std::to_string(course) +
                                 " and " + std::to_string(course + 1));
                        }
                    }
            }
            std::cout << compared << " head joints compared with the course above, " << close
                      << " closer than a quarter brick\n";
            if (compared == 0) fail("no head joints to compare");
        }
        return ok ? 0 : 1;
    } catch (const std::exception& e) {
        std::cout << "FAIL " << e.what() << "\n";
        return 1;
    }
}
