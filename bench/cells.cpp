// cells: a 100 m x 30 m facade (user units: mm) with 200 openings in running bond, then the
// same facade a tenth as tall (20 openings) for the cost per cell as the facade grows 10x.
// Then the same two facades end to end: rules/facade.acr built into a program, each facade an SVG
// file it reads, grown and rendered to PNG in its own process (program_* figures, medians of
// three runs). Prints one JSON line. `bench_cells --dump FILE` also writes the big facade's cells,
// one a line (generator, feature, course, vertices to 17 digits), to compare outputs across
// changes.
#include <2geom/svg-path-parser.h>

#include <acanthus/stdlib/cells.hpp>
#include <acanthus/stdlib/cells/facade_shape.hpp>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <exception>
#include <fstream>
#include <string>
#include <vector>

#include "program_run.hpp"

namespace cells = acanthus::cells;
namespace fs = std::filesystem;

static cells::FacadeShape rect(double x, double y, double w, double h, const char* cls,
                               std::string id) {
    cells::FacadeShape s;
    std::string d = "M " + std::to_string(x) + " " + std::to_string(y) + " h " + std::to_string(w) +
                    " v " + std::to_string(h) + " h " + std::to_string(-w) + " Z";
    s.paths = Geom::parse_svg_path(d.c_str());
    s.classes = {cls};
    s.id = std::move(id);
    return s;
}

// A wall `cols` x `rows` window bays of 5 m x 3 m, a 1.2 m x 1.5 m window in each.
static cells::Facade facade(int cols, int rows) {
    std::vector<cells::FacadeShape> shapes{
        rect(0, 0, cols * 5000.0, rows * 3000.0, "wall", "wall")};
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < cols; ++i)
            // The id appended, not "w" + ...: GCC 12 at -O3 misreads that as an overlapping copy.
            shapes.push_back(rect(i * 5000 + 1900, j * 3000 + 900, 1200, 1500, "window",
                                  std::string("w").append(std::to_string(j * cols + i))));
    return cells::Facade::from_shapes(std::move(shapes), "bench");
}

struct Run {
    std::size_t cells;
    double seconds;
};

static void dump(const cells::Texture& t, const char* path) {
    std::FILE* out = std::fopen(path, "w");
    if (!out) return;
    for (const cells::Cell& c : t.cells) {
        std::fprintf(out, "%s %s %d", c.generator.c_str(),
                     std::string(cells::to_string(c.feature)).c_str(), c.course);
        for (const acanthus::Point& p : c.polygon) std::fprintf(out, " %.17g,%.17g", p.x, p.y);
        std::fputc('\n', out);
    }
    std::fclose(out);
}

static Run run(int cols, int rows, const char* dump_path = nullptr) {
    auto t0 = std::chrono::steady_clock::now();
    cells::Facade f = facade(cols, rows);
    cells::Options o;
    cells::Texture t = cells::texture(f, cells::brick_tree(), o, 1);
    double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (dump_path) dump(t, dump_path);
    return {t.cells.size(), s};
}

// facade(cols, rows) as the SVG file rules/facade.acr reads: a class="wall" rect and one
// class="window" rect per bay, in the same millimetres.
static void write_facade_svg(int cols, int rows, const fs::path& path) {
    std::ofstream out(path);
    const int w = cols * 5000, h = rows * 3000;
    out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << w << "\" height=\"" << h
        << "\" viewBox=\"0 0 " << w << ' ' << h
        << "\">\n<rect class=\"wall\" x=\"0\" y=\"0\" width=\"" << w << "\" height=\"" << h
        << "\"/>\n";
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < cols; ++i)
            out << "<rect class=\"window\" x=\"" << i * 5000 + 1900 << "\" y=\"" << j * 3000 + 900
                << "\" width=\"1200\" height=\"1500\"/>\n";
    out << "</svg>\n";
    if (!out.flush()) throw std::runtime_error("cannot write " + path.string());
}

struct ProgramFigures {
    bench::ProgramMedian big, small;
};

// The facade program on both facades, runs taking turns so that a change in the machine's load
// touches both alike. The library's brick size and joint (mm), which the rule file's defaults
// (cm) are not.
static ProgramFigures program_figures() {
    bench::TempDir dir;
    const fs::path program = bench::build_program("facade", dir.path());
    write_facade_svg(20, 10, dir.path() / "big.svg");
    write_facade_svg(20, 1, dir.path() / "small.svg");
    auto args = [&](const char* facade) {
        return std::vector<std::string>{"--region", (dir.path() / facade).string(),
                                        "--param",  "cells_brick=215x65",
                                        "--param",  "cells_mortar=10",
                                        "-o",       (dir.path() / "facade.png").string()};
    };
    bench::run_program(program, args("small.svg"));  // warm up (page cache, libraries)
    ProgramFigures f;
    for (int k = 0; k < 3; ++k) {
        f.small.add(bench::run_program(program, args("small.svg")), "facade, small facade");
        f.big.add(bench::run_program(program, args("big.svg")), "facade, big facade");
    }
    return f;
}

int main(int argc, char** argv) {
    const char* dump_path = argc == 3 && std::strcmp(argv[1], "--dump") == 0 ? argv[2] : nullptr;
    run(2, 1);                         // warm up
    Run small = run(20, 1);            // 100 m x 3 m, 20 openings: a tenth of the big facade
    Run big = run(20, 10, dump_path);  // 100 m x 30 m, 200 openings
    double per_small = small.seconds / static_cast<double>(small.cells);
    double per_big = big.seconds / static_cast<double>(big.cells);
    ProgramFigures p;
    try {
        p = program_figures();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_cells: %s\n", e.what());
        return 1;
    }
    // Every element but the one seed is a cell.
    const double p_big = static_cast<double>(p.big.elements - 1);
    const double p_small = static_cast<double>(p.small.elements - 1);
    std::printf(
        "{\"cells\": %zu, \"seconds\": %.4f, \"cells_per_second\": %.0f, \"small_cells\": %zu, "
        "\"small_seconds\": %.4f, \"cost_per_cell_ratio\": %.3f, \"target_cells_per_second\": "
        "500000, \"program_elements\": %ld, \"program_cells\": %.0f, "
        "\"program_growth_seconds\": %.4f, \"program_render_seconds\": %.4f, "
        "\"program_cells_per_second\": %.0f, \"program_wall_seconds\": %.4f, "
        "\"program_small_cells\": %.0f, \"program_small_growth_seconds\": %.4f, "
        "\"program_small_wall_seconds\": %.4f, \"program_cost_per_cell_ratio\": %.3f, "
        "\"program_runs\": %zu, \"program_target_cells_per_second\": 500000, "
        "\"program_target_cost_ratio\": 1.5}\n",
        big.cells, big.seconds, static_cast<double>(big.cells) / big.seconds, small.cells,
        small.seconds, per_big / per_small, p.big.elements, p_big, p.big.growth_seconds,
        p.big.render_seconds, p_big / p.big.growth_seconds, p.big.wall_seconds, p_small,
        p.small.growth_seconds, p.small.wall_seconds,
        (p.big.growth_seconds / p_big) / (p.small.growth_seconds / p_small), p.big.growth.size());
    return 0;
}
