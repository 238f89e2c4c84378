// Straight joints read from laid cells, as a mason reads a wall: the head joints between
// neighbouring bricks of a course, each compared with those of the course right above it. Shared
// by the straight-joint map (rules/facade.acr, facade_straight_joints) and the tests' checker.
#pragma once

#include <acanthus/stdlib/cells.hpp>
#include <vector>

namespace acanthus::cells {

// A head joint: the gap's middle and its course's drawn extent (SVG numbers: y0 above y1).
struct HeadJoint {
    double x = 0, y0 = 0, y1 = 0;
};

// A head joint closer than a quarter brick to one in the course above.
struct StraightJoint {
    HeadJoint lower, upper;
};

struct HeadJoints {
    long compared = 0;  // head joints with a joint in the course above to compare
    std::vector<StraightJoint> straight;
};

// `p` is four corners of an axis-aligned box, `r` (a clipped piece is not a brick).
bool is_rect(const std::vector<Point>& p, Rect& r);

// Laid in courses of bricks: bricks, window bottoms, quoins and lintels (not stones, arches,
// soldiers on end over a head or coloured blocks).
bool coursed(const Cell& cell);

// The straight joints of the coursed cells that are axis-aligned rectangles: neighbours in one
// course (the same drawn bottom and top within 5% of the joint) at most two joints apart make a
// head joint; it is straight when a head joint of the course above lies within a quarter of
// `brick_length`. In order of the lower joints' tops, then x.
HeadJoints straight_joints(const std::vector<Cell>& cells, double brick_length, double mortar);

}  // namespace acanthus::cells
