// A mason's cut list (bill of quantities) of a laid facade: how many of each piece, by kind and
// size, counted from the cells themselves (docs/stdlib/cells.md, "Cut list").
#pragma once

#include <acanthus/stdlib/cells.hpp>
#include <string>
#include <vector>

namespace acanthus::cells {

// One line of the list: `count` pieces of one kind and size (millimetres). Voussoirs give the
// widths at the intrados and the extrados (their taper) and their depth as `height`; every other
// piece its face's width and height (a shaped cut, its bounding box).
struct CutListItem {
    std::string facade;
    std::string kind;  // stretcher, header, queen closer, three-quarter bat, half bat, cut brick,
                       // shaped cut, voussoir, skewback, soldier, lintel, sill header, ...
    std::string generator;
    double width = 0, height = 0;
    double intrados = 0, extrados = 0;  // voussoirs only
    long count = 0;
};

// The pieces of `cells` laid on `facade` with `options`, sizes rounded to whole millimetres
// (`mm_per_unit`: millimetres in one of the drawing's units, 10 for centimetres), sorted by
// generator, kind and size. Deterministic: the same cells give the same list.
std::vector<CutListItem> cut_list(const Facade& facade, const std::vector<Cell>& cells,
                                  const Options& options, double mm_per_unit);

// The list as CSV (a header line, then one line per item) or JSON ({"facades": [{"name",
// "pieces": [...]}]}).
std::string cut_list_csv(const std::vector<CutListItem>& items);
std::string cut_list_json(const std::vector<CutListItem>& items);

// Writes the list to `path`, CSV or JSON by its extension (.csv, .json), through a temporary
// file renamed over it: no partial file. Throws InputError naming the file when the extension is
// neither or the file cannot be written.
void write_cut_list(const std::string& path, const std::vector<CutListItem>& items);

}  // namespace acanthus::cells
