// For `acanthus preview`'s precompiled prelude, included after <acanthus/stdlib/cells.hpp> when
// a rule file's code includes that: the standard library's members the cells library's rule
// code uses (its options, trees, faces, cells and cut list), instantiated once with the prelude
// instead of at every save. Never called.
#pragma once

#include <acanthus/stdlib/cells.hpp>
#include <acanthus/stdlib/cells/cut_list.hpp>
#include <acanthus/stdlib/cells/head_joints.hpp>

namespace acanthus::cells::prelude_detail {

inline void instantiate(const Facade& facade, const Node& node) {
    Options options, copy(options);
    copy = options;
    Node tree(node);
    tree = node;
    for (const Face& f : facade.faces()) (void)f;
    std::vector<Face> faces(facade.faces());
    Texture texture, again(texture);
    again = texture;
    texture.cells.push_back(Cell{});
    for (const Cell& c : texture.cells) (void)c;
    std::vector<CutListItem> items = cut_list(facade, texture.cells, options, 1.0);
    items.push_back(CutListItem{});
    HeadJoints report, other(report);
    other = report;
    report.straight.push_back(StraightJoint{});
    for (const StraightJoint& j : report.straight) (void)j;
}

}  // namespace acanthus::cells::prelude_detail
