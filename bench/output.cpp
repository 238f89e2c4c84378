// Output writing speed: elements per second rendering a 20,000-element ornament to SVG, PDF and
// PNG through render_to_file. The last line printed is one JSON object.
#include <unistd.h>

#include <acanthus/region.hpp>
#include <acanthus/render.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <string>
#include <vector>

using namespace acanthus;

namespace {

const ElementType disc_type{"disc", {ProxyKind::circle}, nullptr, nullptr, 1};
const ElementType tendril_type{"tendril", {ProxyKind::bezier}, nullptr, nullptr, 2};

struct Disc : Element {
    CircleProxy c;
    const ElementType& type() const override { return disc_type; }
    std::size_t proxy_count() const override { return 1; }
    Proxy& proxy(std::size_t) override { return c; }
};

struct Tendril : Element {
    BezierProxy b;
    const ElementType& type() const override { return tendril_type; }
    std::size_t proxy_count() const override { return 1; }
    Proxy& proxy(std::size_t) override { return b; }
};

constexpr int element_count = 20000;
constexpr int repeats = 3;

// Half discs, half Bézier tendrils on a jittered grid over a 1000 x 800 panel.
struct SyntheticOrnament {
    std::deque<Disc> discs;
    std::deque<Tendril> tendrils;
    std::vector<const Element*> elements;

    SyntheticOrnament() {
        int columns = 200;
        for (int i = 0; i < element_count; ++i) {
            double x = 2.5 + 5.0 * (i % columns), y = 4.0 + 7.9 * (i / columns);
            double wobble = std::sin(i * 0.7) * 0.6;
            Element* e;
            if (i % 2 == 0) {
                Disc& d = discs.emplace_back();
                d.c.set({x + wobble, y}, 1.2 + 0.5 * std::cos(i * 0.3));
                e = &d;
            } else {
                Tendril& t = tendrils.emplace_back();
                t.b.set({x - 2, y + 1}, {x - 1, y - 2 + wobble}, {x + 1, y + 2}, {x + 2, y - 1});
                e = &t;
            }
            e->id = i;
            elements.push_back(e);
        }
    }
};

double best_seconds(const std::string& path, const Pattern& pattern, const Region& region,
                    const std::vector<const Element*>& elements, const RenderOptions& options) {
    double best = 1e300;
    for (int r = 0; r < repeats; ++r) {
        auto start = std::chrono::steady_clock::now();
        render_to_file(path, pattern, region, elements, options);
        std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
        best = std::min(best, took.count());
    }
    return best;
}

}  // namespace

int main() {
    namespace fs = std::filesystem;
    fs::path dir =
        fs::temp_directory_path() / ("acanthus-bench-output-" + std::to_string(::getpid()));
    fs::create_directories(dir);

    Region region = Region::from_spec("rect:1000,800");
    Pattern pattern;
    pattern.name = "bench";
    pattern.types = {&disc_type, &tendril_type};
    SyntheticOrnament ornament;
    RenderOptions options;
    options.width = 1600;
    options.style = "filled";

    double rates[3];
    const char* formats[3] = {"svg", "pdf", "png"};
    for (int f = 0; f < 3; ++f) {
        std::string path = (dir / (std::string("ornament.") + formats[f])).string();
        double seconds = best_seconds(path, pattern, region, ornament.elements, options);
        rates[f] = element_count / seconds;
        std::printf("%s: %d elements in %.3f s (%.0f elements/s, %ju bytes)\n", formats[f],
                    element_count, seconds, rates[f],
                    static_cast<std::uintmax_t>(fs::file_size(path)));
    }
    fs::remove_all(dir);
    std::printf(
        "{\"benchmark\":\"output\",\"elements\":%d,\"svg_elements_per_second\":%.0f,"
        "\"pdf_elements_per_second\":%.0f,\"png_elements_per_second\":%.0f}\n",
        element_count, rates[0], rates[1], rates[2]);
    return 0;
}
