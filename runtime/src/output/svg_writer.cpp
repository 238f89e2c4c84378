// The structured SVG writer (see svg_writer.hpp and docs/rendering.md).
#include "output/svg_writer.hpp"

#include <cairo.h>

#include <algorithm>
#include <charconv>
#include <cmath>

namespace acanthus::detail {

namespace {

// Beyond this many distinct styles (an order-coloured poster), a shape carries its own style
// attribute: the class table stays small, whatever the element count.
constexpr std::size_t max_classes = 4096;

// `value` to `digits` decimals as std::to_chars' fixed format rounds it (the exact binary
// value, ties to even), trailing zeros dropped. std::to_chars with a precision took a third of
// a large SVG's drawing; scaled to an integer in a double it is exact unless the product lies
// within its rounding error of a tie, and those few go to std::to_chars.
std::string fixed(double value, int digits) {
    if (!std::isfinite(value)) return "0";
    static constexpr double powers[] = {1, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8};
    if (digits >= 0 && digits <= 8) {
        const double scaled = value * powers[digits];  // (10^digits is exact)
        const double magnitude = std::abs(scaled);
        if (magnitude < 0x1p52) {
            auto n = static_cast<unsigned long long>(magnitude);  // (floor)
            const double fraction = magnitude - static_cast<double>(n);
            // The exact product is within half an ulp of `scaled`; a margin of four ulps.
            if (std::abs(fraction - 0.5) > magnitude * 0x1p-50) {
                n += fraction > 0.5 ? 1 : 0;
                char buffer[32];
                char* end = buffer + sizeof buffer;
                char* p = end;
                int left = digits;
                while (left > 0 && n % 10 == 0) {  // trailing zeros of the decimals
                    n /= 10;
                    --left;
                }
                for (int i = 0; i < left; ++i, n /= 10) *--p = static_cast<char>('0' + n % 10);
                if (left > 0) *--p = '.';
                do *--p = static_cast<char>('0' + n % 10);
                while ((n /= 10) != 0);
                const bool zero = p == end - 1 && *p == '0';
                if (value < 0 && !zero) *--p = '-';  // ("-0" is "0")
                return std::string(p, end);
            }
        }
    }
    char buffer[64];
    auto [end, ec] =
        std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, digits);
    if (ec != std::errc()) return "0";
    std::string text(buffer, end);
    if (text.find('.') != std::string::npos) {
        text.erase(text.find_last_not_of('0') + 1);
        if (text.back() == '.') text.pop_back();
    }
    if (text == "-0") text = "0";
    return text;
}

std::string hex_color(double r, double g, double b) {
    static constexpr char digits[] = "0123456789abcdef";
    std::string text = "#";
    for (double c : {r, g, b}) {
        long v = std::lround(std::clamp(c, 0.0, 1.0) * 255);
        text += digits[v / 16];
        text += digits[v % 16];
    }
    return text;
}

// A transformation that keeps circles circles and scales every width by the same amount.
bool conformal(const cairo_matrix_t& m, double& scale) {
    double a = m.xx * m.xx + m.yx * m.yx, b = m.xy * m.xy + m.yy * m.yy;
    double c = m.xx * m.xy + m.yx * m.yy;
    scale = std::sqrt(std::abs(m.xx * m.yy - m.xy * m.yx));
    double tolerance = 1e-9 * std::max(a, b);
    return scale > 0 && std::abs(a - b) <= tolerance && std::abs(c) <= tolerance;
}

Point device(const cairo_matrix_t& m, double x, double y) {
    return {m.xx * x + m.xy * y + m.x0, m.yx * x + m.yy * y + m.y0};
}

}  // namespace

int svg_digits(int width, int height) {
    double side = std::max({width, height, 1});
    return std::clamp(static_cast<int>(std::ceil(std::log10(20000.0 / side) - 1e-9)), 0, 3);
}

std::string svg_number(double value, int digits) { return fixed(value, digits); }

std::string xml_escape(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            case '\'':
                out += "&apos;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

SvgWriter::SvgWriter(OutputStream& out, int width, int height, const std::string& title)
    : out_(out), digits_(svg_digits(width, height)) {
    std::string w = std::to_string(width), h = std::to_string(height);
    std::string head =
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" "
        "xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" width=\"" +
        w + "pt\" height=\"" + h + "pt\" viewBox=\"0 0 " + w + " " + h + "\" version=\"1.1\">\n";
    if (!title.empty()) head += "<title>" + xml_escape(title) + "</title>\n";
    out_.write(head);
}

void SvgWriter::background(Color color) {
    begin_layer("background", "layer-background");
    element_ += "<rect id=\"background\" x=\"0\" y=\"0\" width=\"100%\" height=\"100%\" fill=\"" +
                hex_color(color.r, color.g, color.b) + "\"";
    if (color.a < 1) element_ += " fill-opacity=\"" + fixed(color.a, 3) + "\"";
    element_ += "/>\n";
    end_layer();
}

void SvgWriter::begin_layer(const std::string& label, const std::string& id) {
    element_ += "<g inkscape:groupmode=\"layer\" inkscape:label=\"" + xml_escape(label) +
                "\" id=\"" + xml_escape(id) + "\">\n";
}

void SvgWriter::end_layer() {
    flush_shape();
    element_ += "</g>\n";
    out_.write(element_);
    element_.clear();
}

void SvgWriter::begin_element(const std::string& type, long id, long parent) {
    flush_shape();
    out_.write(element_);
    element_.clear();
    // The type is the layer's and the id's prefix, the placement id the id's number, the depth
    // in --json: only the parent is not written elsewhere (docs/rendering.md, "Groups").
    element_ += "<g id=\"" + xml_escape(type) + "-" + std::to_string(id) + "\" data-parent=\"" +
                (parent >= 0 ? std::to_string(parent) : "none") + "\">";
    group_start_ = element_.size();
    fallback_ = false;
}

void SvgWriter::replace_shapes(std::string fragment) {
    has_pending_ = false;
    element_.resize(group_start_);
    element_ += fragment;
    fallback_ = false;
}

void SvgWriter::raw(std::string_view fragment) {
    flush_shape();
    element_ += fragment;
}

void SvgWriter::end_element() {
    flush_shape();
    element_ += "</g>\n";
    out_.write(element_);
    element_.clear();
}

void SvgWriter::finish() {
    flush_shape();
    out_.write(element_);
    element_.clear();
    // At the end, as the classes are known only now: CSS applies to the whole document.
    std::string tail;
    if (!class_order_.empty()) {
        tail += "<style type=\"text/css\">\n";
        for (std::size_t k = 0; k < class_order_.size(); ++k)
            tail += ".s" + std::to_string(k) + "{" + *class_order_[k] + "}\n";
        tail += "</style>\n";
    }
    tail += "</svg>\n";
    out_.write(tail);
}

std::string SvgWriter::paint(cairo_t* cr, bool fill) {
    double r, g, b, a;
    cairo_matrix_t m;
    cairo_get_matrix(cr, &m);
    double scale = 1;
    if (cairo_pattern_get_rgba(cairo_get_source(cr), &r, &g, &b, &a) != CAIRO_STATUS_SUCCESS ||
        cairo_get_operator(cr) != CAIRO_OPERATOR_OVER || !conformal(m, scale)) {
        fallback_ = true;  // a gradient, another operator or a skew: Cairo draws this element
        return {};
    }
    std::string part = fill ? "fill:" : "stroke:";
    part += hex_color(r, g, b);
    if (a < 1) part += fill ? ";fill-opacity:" + fixed(a, 3) : ";stroke-opacity:" + fixed(a, 3);
    if (fill) {
        if (cairo_get_fill_rule(cr) == CAIRO_FILL_RULE_EVEN_ODD) part += ";fill-rule:evenodd";
        return part;
    }
    if (cairo_get_dash_count(cr) > 0) fallback_ = true;
    // Widths are written once per class: to 0.01 at least, as a rim of 0.75 is not one of 0.8.
    part += ";stroke-width:" + svg_number(cairo_get_line_width(cr) * scale, std::max(digits_, 2));
    switch (cairo_get_line_cap(cr)) {
        case CAIRO_LINE_CAP_ROUND:
            part += ";stroke-linecap:round";
            break;
        case CAIRO_LINE_CAP_SQUARE:
            part += ";stroke-linecap:square";
            break;
        default:
            break;
    }
    switch (cairo_get_line_join(cr)) {
        case CAIRO_LINE_JOIN_ROUND:
            part += ";stroke-linejoin:round";
            break;
        case CAIRO_LINE_JOIN_BEVEL:
            part += ";stroke-linejoin:bevel";
            break;
        default:
            part += ";stroke-miterlimit:" + fixed(cairo_get_miter_limit(cr), 3);
            break;
    }
    return part;
}

void SvgWriter::path(cairo_t* cr, bool fill) {
    cairo_matrix_t m;
    cairo_get_matrix(cr, &m);
    cairo_path_t* p = cairo_copy_path(cr);
    std::string d;
    bool closed = false;
    Point start{0, 0};
    for (int i = 0; p->status == CAIRO_STATUS_SUCCESS && i < p->num_data;
         i += p->data[i].header.length) {
        const cairo_path_data_t* data = &p->data[i];
        switch (data->header.type) {
            case CAIRO_PATH_MOVE_TO: {
                Point q = device(m, data[1].point.x, data[1].point.y);
                bool last = i + data->header.length >= p->num_data;
                // Cairo's implicit move back to the start after a close: SVG does it itself.
                if (closed && (last || (q.x == start.x && q.y == start.y))) break;
                if (last) break;
                d += 'M';  // char then text: "M" + string trips GCC 12's -Wrestrict at -O3
                d += point_text(q);
                start = q;
                break;
            }
            case CAIRO_PATH_LINE_TO:
                d += 'L';
                d += point_text(device(m, data[1].point.x, data[1].point.y));
                break;
            case CAIRO_PATH_CURVE_TO:
                d += 'C';
                d += point_text(device(m, data[1].point.x, data[1].point.y)) + " " +
                     point_text(device(m, data[2].point.x, data[2].point.y)) + " " +
                     point_text(device(m, data[3].point.x, data[3].point.y));
                break;
            case CAIRO_PATH_CLOSE_PATH:
                d += "Z";
                break;
        }
        closed = data->header.type == CAIRO_PATH_CLOSE_PATH;
    }
    if (p->status != CAIRO_STATUS_SUCCESS) fallback_ = true;
    cairo_path_destroy(p);
    if (d.empty()) return;
    std::string style = paint(cr, fill);
    add({"path", " d=\"" + d + "\"", fill ? style : "", fill ? "" : style});
}

void SvgWriter::circle(cairo_t* cr, Point center, double radius, bool fill) {
    cairo_matrix_t m;
    cairo_get_matrix(cr, &m);
    double scale = 1;
    if (!conformal(m, scale)) {  // an ellipse on the page: drawn as Cairo's path
        cairo_new_path(cr);
        cairo_arc(cr, center.x, center.y, radius, 0, 2 * M_PI);
        cairo_close_path(cr);
        path(cr, fill);
        cairo_new_path(cr);
        return;
    }
    Point c = device(m, center.x, center.y);
    std::string style = paint(cr, fill);
    add({"circle",
         " cx=\"" + number(c.x) + "\" cy=\"" + number(c.y) + "\" r=\"" + number(radius * scale) +
             "\"",
         fill ? style : "", fill ? "" : style});
}

void SvgWriter::polygon(cairo_t* cr, const std::vector<Point>& points, bool fill) {
    cairo_matrix_t m;
    cairo_get_matrix(cr, &m);
    std::string text;
    for (const Point& q : points) {
        Point p = device(m, q.x, q.y);
        if (!text.empty()) text += ' ';
        text += number(p.x) + "," + number(p.y);
    }
    std::string style = paint(cr, fill);
    add({"polygon", " points=\"" + text + "\"", fill ? style : "", fill ? "" : style});
}

void SvgWriter::add(Shape shape) {
    // A stroke of the shape just filled (a dot and its rim) is one SVG element: the same picture,
    // as SVG paints the fill before the stroke.
    if (has_pending_ && pending_.stroke.empty() && !pending_.fill.empty() && shape.fill.empty() &&
        pending_.tag == shape.tag && pending_.geometry == shape.geometry) {
        pending_.stroke = std::move(shape.stroke);
        flush_shape();
        return;
    }
    flush_shape();
    pending_ = std::move(shape);
    has_pending_ = true;
}

void SvgWriter::flush_shape() {
    if (!has_pending_) return;
    has_pending_ = false;
    std::string style = pending_.fill.empty()     ? "fill:none;" + pending_.stroke
                        : pending_.stroke.empty() ? pending_.fill
                                                  : pending_.fill + ";" + pending_.stroke;
    std::string name = class_of(style);
    element_ += "<" + pending_.tag +
                (name.empty() ? " style=\"" + style + "\"" : " class=\"" + name + "\"") +
                pending_.geometry + "/>";
}

std::string SvgWriter::class_of(const std::string& style) {
    auto it = classes_.find(style);
    if (it == classes_.end()) {
        if (classes_.size() >= max_classes) return {};
        it = classes_.emplace(style, class_order_.size()).first;
        class_order_.push_back(&it->first);
    }
    std::string name = "s";  // not "s" + to_string(): GCC 12 warns (-Wrestrict) on that at -O3
    name += std::to_string(it->second);
    return name;
}

}  // namespace acanthus::detail
