// cells: a 100 m x 30 m facade (user units: mm) with 200 openings in running bond, then the
// same facade a tenth as tall (20 openings) for the cost per cell as the facade grows 10x.
// Prints one JSON line. `bench_cells --dump FILE` also writes the big facade's cells, one a line
// (generator, feature, course, vertices to 17 digits), to compare outputs across changes.
#include <2geom/svg-path-parser.h>

#include <acanthus/stdlib/cells.hpp>
#include <acanthus/stdlib/cells/facade_shape.hpp>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace cells = acanthus::cells;

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

int main(int argc, char** argv) {
    const char* dump_path = argc == 3 && std::strcmp(argv[1], "--dump") == 0 ? argv[2] : nullptr;
    run(2, 1);                         // warm up
    Run small = run(20, 1);            // 100 m x 3 m, 20 openings: a tenth of the big facade
    Run big = run(20, 10, dump_path);  // 100 m x 30 m, 200 openings
    double per_small = small.seconds / static_cast<double>(small.cells);
    double per_big = big.seconds / static_cast<double>(big.cells);
    std::printf(
        "{\"cells\": %zu, \"seconds\": %.4f, \"cells_per_second\": %.0f, \"small_cells\": %zu, "
        "\"small_seconds\": %.4f, \"cost_per_cell_ratio\": %.3f, \"target_cells_per_second\": "
        "500000}\n",
        big.cells, big.seconds, static_cast<double>(big.cells) / big.seconds, small.cells,
        small.seconds, per_big / per_small);
    return 0;
}
