// How a motif looks (issue 10): an SVG reference element's own outline, turned and scaled, or for
// JSON references a glyph in its symbol's colour.
#include <acanthus/stdlib/growth.hpp>
#include <algorithm>
#include <cmath>

namespace acanthus::growth {
namespace {

// tint > 0 towards white, < 0 towards black.
Color tinted(Color c, double tint) {
    auto channel = [tint](double v) { return tint >= 0 ? v + (1 - v) * tint : v * (1 + tint); };
    return {channel(c.r), channel(c.g), channel(c.b), c.a};
}

}  // namespace

void draw_motif(Canvas& canvas, const Reference& reference, int source, Point centre, double angle,
                double scale, double tint) {
    if (source < 0 || static_cast<std::size_t>(source) >= reference.size()) return;
    const ReferenceElement& e = reference.element(static_cast<std::size_t>(source));
    const std::vector<Outline>& outlines = reference.outlines(static_cast<std::size_t>(source));
    tint = std::clamp(tint, -1.0, 1.0);
    if (outlines.empty()) {
        // A disc in the symbol's hue, slightly inside the collision circle, with a tick along
        // the motif's x axis so that orientation shows.
        const double r = 0.9 * reference.radius(static_cast<std::size_t>(source)) * scale;
        const double n = static_cast<double>(std::max<std::size_t>(reference.symbol_count(), 1));
        Color c = tinted(
            hue(reference.symbol_index(static_cast<std::size_t>(source)) / n, 0.55, 0.8), tint);
        canvas.fill_circle(centre, r, c);
        canvas.set_color(tinted({0.15, 0.12, 0.1, 1}, tint));
        canvas.set_line_width(std::max(r * 0.15, 1e-6));
        canvas.move_to(centre);
        canvas.line_to(centre + Vector(std::cos(angle), std::sin(angle)) * r);
        canvas.stroke();
        return;
    }
    // The outline is stored relative to the element's centre in its reference orientation.
    const double turn = angle - e.angle;
    const Vector ux = Vector(std::cos(turn), std::sin(turn)) * scale;
    const Vector uy = Vector(-std::sin(turn), std::cos(turn)) * scale;
    auto place = [&](Point p) { return centre + ux * p.x + uy * p.y; };
    auto add_path = [&](const Outline& o) {
        for (const OutlinePath& path : o.paths) {
            if (path.points.empty()) continue;
            canvas.move_to(place(path.points[0]));
            for (std::size_t k = 1; k + 2 < path.points.size(); k += 3)
                canvas.curve_to(place(path.points[k]), place(path.points[k + 1]),
                                place(path.points[k + 2]));
            if (path.closed) canvas.close_path();
        }
    };
    for (const Outline& o : outlines) {
        if (o.fill.a > 0) {
            add_path(o);
            canvas.set_color(tinted(o.fill, tint));
            canvas.fill();
        }
        if (o.stroke.a > 0 && o.stroke_width > 0) {
            add_path(o);
            canvas.set_color(tinted(o.stroke, tint));
            canvas.set_line_width(o.stroke_width * scale);
            canvas.stroke();
        }
    }
}

}  // namespace acanthus::growth
