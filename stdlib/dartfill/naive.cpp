#include "methods.hpp"

namespace acanthus::dartfill {

void naive_dart_throwing(FillContext& context, Layout& layout) {
    Rect b = context.container().bounds();
    long cancellations = 0;
    while (cancellations < context.options().naive_cancellations && !context.full(layout)) {
        Point position{context.random().uniform(b.x0, b.x1), context.random().uniform(b.y0, b.y1)};
        if (context.try_place(layout, context.random_pose(position)))
            cancellations = 0;
        else
            ++cancellations;
    }
}

}  // namespace acanthus::dartfill
