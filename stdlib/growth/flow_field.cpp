#include "flow_field.hpp"

#include <Eigen/Dense>
#include <acanthus/error.hpp>
#include <algorithm>
#include <cmath>

namespace acanthus::growth::detail {
namespace {

double thin_plate(double r) { return r > 0 ? r * r * std::log(r) : 0.0; }

double length(const std::vector<Point>& stroke) {
    double total = 0;
    for (std::size_t k = 1; k < stroke.size(); ++k) total += distance(stroke[k - 1], stroke[k]);
    return total;
}

}  // namespace

FlowField::FlowField(const std::vector<std::vector<Point>>& strokes, double spacing,
                     const std::string& source, std::size_t max_samples) {
    double total = 0;
    for (std::size_t s = 0; s < strokes.size(); ++s) {
        for (Point p : strokes[s])
            if (!p.finite())
                throw InputError(source + ": flow stroke " + std::to_string(s) +
                                 ": a point is not finite");
        double l = length(strokes[s]);
        if (!(l > 0))
            throw InputError(source + ": flow stroke " + std::to_string(s) + " has no length");
        total += l;
    }
    if (strokes.empty()) throw InputError(source + ": flow mode needs at least one flow stroke");
    max_samples = std::max<std::size_t>(max_samples, 1);
    if (!(spacing > 0)) spacing = total / 100;
    spacing = std::max(spacing, total / static_cast<double>(max_samples));
    // Walk each stroke by arc length, one sample per `spacing`, at least one per stroke.
    for (const auto& stroke : strokes) {
        double next = 0, walked = 0;
        for (std::size_t k = 1; k < stroke.size(); ++k) {
            Vector d = stroke[k] - stroke[k - 1];
            double seg = d.length();
            if (seg == 0) continue;
            while (next <= walked + seg) {
                samples_.push_back(stroke[k - 1] + d * ((next - walked) / seg));
                directions_.push_back(d / seg);
                next += spacing;
            }
            walked += seg;
        }
    }
    // Every stroke gives at least one sample, so thousands of short strokes would give thousands
    // of them, and the dense solve below grows with their cube: thinned evenly to the budget.
    if (samples_.size() > max_samples) {
        const std::size_t all = samples_.size();
        for (std::size_t k = 0; k < max_samples; ++k) {
            const std::size_t from = k * all / max_samples;
            samples_[k] = samples_[from];
            directions_[k] = directions_[from];
        }
        samples_.resize(max_samples);
        directions_.resize(max_samples);
    }
    // Centre and scale the samples so that the system is well conditioned at any unit.
    double sx = 0, sy = 0;
    for (Point p : samples_) sx += p.x, sy += p.y;
    const double n_d = static_cast<double>(samples_.size());
    origin_ = {sx / n_d, sy / n_d};
    double extent = 0;
    for (Point p : samples_) extent = std::max(extent, distance(p, origin_));
    scale_ = extent > 0 ? extent : 1.0;

    const int n = static_cast<int>(samples_.size());
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n + 3, n + 3);
    Eigen::MatrixXd b = Eigen::MatrixXd::Zero(n + 3, 2);
    auto local = [&](Point p) { return (p - origin_) / scale_; };
    for (int i = 0; i < n; ++i) {
        Vector pi = local(samples_[i]);
        for (int j = 0; j < n; ++j) a(i, j) = thin_plate((pi - local(samples_[j])).length());
        a(i, i) += 1e-9;  // coincident samples (crossing strokes) stay solvable
        a(i, n) = a(n, i) = 1;
        a(i, n + 1) = a(n + 1, i) = pi.x;
        a(i, n + 2) = a(n + 2, i) = pi.y;
        b(i, 0) = directions_[i].x;
        b(i, 1) = directions_[i].y;
    }
    Eigen::MatrixXd x = a.fullPivLu().solve(b);
    for (int i = 0; i < n; ++i) weights_.push_back({x(i, 0), x(i, 1)});
    constant_ = {x(n, 0), x(n, 1)};
    along_x_ = {x(n + 1, 0), x(n + 1, 1)};
    along_y_ = {x(n + 2, 0), x(n + 2, 1)};
}

Vector FlowField::vector(Point p) const {
    Vector q = (p - origin_) / scale_;
    Vector v = constant_ + along_x_ * q.x + along_y_ * q.y;
    for (std::size_t i = 0; i < samples_.size(); ++i)
        v += weights_[i] * thin_plate((q - (samples_[i] - origin_) / scale_).length());
    return v;
}

double FlowField::angle(Point p) const {
    Vector v = vector(p);
    return v.x == 0 && v.y == 0 ? 0.0 : std::atan2(v.y, v.x);
}

}  // namespace acanthus::growth::detail
