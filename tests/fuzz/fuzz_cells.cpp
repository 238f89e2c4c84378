// libFuzzer target for the cells library's facade reader: any input is either a facade, which
// is then textured (about 20 bricks across, so each input stays quick) by the brick, framed or
// ashlar tree in one of the bonds, the choice read off the input's length, and read back as a
// cut list and straight joints; or an InputError.
#include <acanthus/error.hpp>
#include <acanthus/stdlib/cells.hpp>
#include <acanthus/stdlib/cells/cut_list.hpp>
#include <acanthus/stdlib/cells/head_joints.hpp>
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    namespace cells = acanthus::cells;
    std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        cells::Facade facade = cells::Facade::from_svg_string(text, "fuzz.svg");
        acanthus::Rect b = facade.bounds();
        cells::Options o;
        o.brick_length = std::max(b.width(), b.height()) / 20;
        o.brick_height = o.brick_length / 3;
        o.mortar = o.brick_length / 20;
        o.joint_tolerance = o.mortar / 3;
        static const cells::Bond bonds[] = {cells::Bond::running, cells::Bond::english,
                                            cells::Bond::flemish, cells::Bond::header,
                                            cells::Bond::ashlar};
        o.bond = bonds[size % 5];
        cells::check(o, "fuzz.svg");
        const std::size_t pick = size / 5 % 3;
        const cells::Node tree = o.bond == cells::Bond::ashlar ? cells::ashlar_tree()
                                 : pick == 1                   ? cells::framed_tree()
                                                               : cells::brick_tree();
        cells::Texture t = cells::texture(facade, tree, o, 1);
        (void)cells::cut_list(facade, t.cells, o, 10);
        (void)cells::straight_joints(t.cells, o.brick_length, o.mortar);
    } catch (const acanthus::InputError&) {
    }
    return 0;
}
