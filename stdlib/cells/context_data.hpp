// What a Context holds while a tree runs: occupancy maps, the cells so far, the running
// generator, and per-face layouts that generators share (a brick layout, an ashlar grid).
#pragma once

#include <acanthus/partial_picture.hpp>
#include <acanthus/progress.hpp>
#include <acanthus/stdlib/cells.hpp>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace acanthus::cells::detail {

struct ContextData {
    const Facade* facade = nullptr;
    Options options;
    Random random;
    std::vector<EdgeOccupancy> edges;
    std::vector<std::unique_ptr<FaceOccupancy>> faces;
    std::vector<Cell> cells;
    std::string generator;
    FeatureRef feature;
    std::string label;
    double edge_tolerance = 0;
    double smallest_cell = 0;     // drawn area under which a piece is left to the mortar
    std::vector<int> near_edges;  // scratch for place()
    long expected_cells = 0;      // the estimate progress reports show; 0: unknown
    bool quoined = false;         // brick layouts made from now on bond jamb quoins in
    bool stone = false;           // a stone wall: lintels on the ashlar grid
    bool lintels = false;         // brick layouts keep every straight head's lintel (framed tree)
    int ashlar_rounds = 0;        // the most rounds of repairs an ashlar face took (TextureStats)

    // A new cell of the running generator and feature, built in place; the caller sets polygon.
    // Reported as progress: a whole facade is one rule body, and the watchdog takes a body that
    // stops reporting for a runaway.
    Cell& add_cell(int course) {
        Cell& c = cells.emplace_back();
        report_progress("cells", static_cast<long>(cells.size()), expected_cells);
        // The cells so far (this one's polygon is not set yet) for a partial picture while the
        // texture goes on: the elements are made only by the copy of the program that draws it.
        if (PartialMaker make = partial_maker())
            report_partial(static_cast<long>(cells.size()) - 1,
                           [this, make](std::vector<const Element*>& out) {
                               for (const Cell& done : cells)
                                   if (done.polygon.size() >= 3) out.push_back(make(done));
                           });
        c.generator = generator;
        c.feature = feature.kind;
        c.label = label;
        c.course = course;
        c.feature_index = feature.index;
        return c;
    }
    std::map<std::string, std::shared_ptr<void>> shared;  // key: what + face

    // The layout of type T under `key`, made by `make()` on first use.
    template <class T, class Make>
    T& layout(const std::string& key, Make&& make) {
        std::shared_ptr<void>& slot = shared[key];
        if (!slot) slot = std::make_shared<T>(make());
        return *static_cast<T*>(slot.get());
    }
};

// The face a feature belongs to.
int face_of(const Facade& facade, const FeatureRef& feature);

}  // namespace acanthus::cells::detail
