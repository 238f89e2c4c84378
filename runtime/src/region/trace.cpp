#include "region/trace.hpp"

#include <2geom/bezier-curve.h>
#include <2geom/curve.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>

namespace acanthus::detail {
namespace {

using ClipperLib::IntPoint;

// Curve times in [t0, t1] (t0 excluded) where chords stay within `tolerance` of the curve,
// by bisection checked at the quarter points; 2^16 pieces at most per curve.
void flatten(const Geom::Curve& c, double t0, double t1, Geom::Point p0, Geom::Point p1,
             double tolerance, int depth, std::vector<double>& out) {
    const Geom::Point d = p1 - p0;
    const double len = Geom::L2(d);
    auto off_chord = [&](double t) {
        Geom::Point q = c.pointAt(t);
        return len == 0 ? Geom::distance(q, p0) : std::abs(Geom::cross(q - p0, d)) / len;
    };
    const double tm = (t0 + t1) / 2;
    const bool flat = off_chord(t0 + (t1 - t0) / 4) <= tolerance && off_chord(tm) <= tolerance &&
                      off_chord(t1 - (t1 - t0) / 4) <= tolerance;
    if (flat || depth >= 16) {
        out.push_back(t1);
        return;
    }
    const Geom::Point pm = c.pointAt(tm);
    flatten(c, t0, tm, p0, pm, tolerance, depth + 1, out);
    flatten(c, tm, t1, pm, p1, tolerance, depth + 1, out);
}

}  // namespace

BoundaryTrace::BoundaryTrace(Geom::Rect frame, double tolerance)
    : origin_(frame.midpoint()), tolerance_(tolerance) {
    // The frame spans about 1e9 integer units: well inside Clipper's fast 64-bit range.
    const double size = std::max({frame.width(), frame.height(), 1e-300});
    scale_ = 1e9 / size;
    // Clipper sweeps along y, and its cost grows with the number of edges one scanline
    // crosses: a wide frame is turned a quarter (orientation kept) so scanlines run across
    // its short side, where a long row of small features is crossed a few edges at a time.
    turned_ = frame.width() > frame.height();
}

IntPoint BoundaryTrace::to_int(Geom::Point p) const {
    const double x = (p[Geom::X] - origin_[Geom::X]) * scale_;
    const double y = (p[Geom::Y] - origin_[Geom::Y]) * scale_;
    return turned_ ? IntPoint(std::llround(y), -std::llround(x))
                   : IntPoint(std::llround(x), std::llround(y));
}

Geom::Point BoundaryTrace::to_real(const IntPoint& p) const {
    const double x = static_cast<double>(turned_ ? -p.Y : p.X) / scale_;
    const double y = static_cast<double>(turned_ ? p.X : p.Y) / scale_;
    return Geom::Point(x + origin_[Geom::X], y + origin_[Geom::Y]);
}

const Geom::Curve& BoundaryTrace::curve(const Source& s) const { return paths_[s.path][s.index]; }

ClipperLib::Paths BoundaryTrace::add(const Geom::PathVector& paths) {
    ClipperLib::Paths rings;
    for (const Geom::Path& input : paths) {
        paths_.push_back(input);
        paths_.back().close(true);
        const Geom::Path& path = paths_.back();
        const std::size_t path_index = paths_.size() - 1;
        first_source_of_path_.push_back(sources_.size());
        ClipperLib::Path ring;
        for (std::size_t i = 0; i < path.size_closed(); ++i) {
            const Geom::Curve& c = path[i];
            if (c.isDegenerate()) continue;
            std::vector<double> times{0};
            if (!c.isLineSegment())
                flatten(c, 0, 1, c.initialPoint(), c.finalPoint(), tolerance_, 0, times);
            else
                times.push_back(1);
            // Samples that round to the same integer point as the one before are dropped; the
            // end sample is kept since the next curve starts there.
            Source source{path_index, i, {}, {}};
            std::vector<IntPoint>& points = source.points;
            for (double t : times) {
                const IntPoint p = to_int(t == 0   ? c.initialPoint()
                                          : t == 1 ? c.finalPoint()
                                                   : c.pointAt(t));
                if (!points.empty() && points.back() == p) {
                    if (t == 1 && points.size() > 1) {
                        source.times.back() = t;
                        points.back() = p;
                    }
                    continue;
                }
                source.times.push_back(t);
                points.push_back(p);
            }
            if (points.size() < 2) continue;  // shorter than the integer grid
            const auto id = static_cast<std::uint32_t>(sources_.size());
            for (std::size_t k = 0; k < points.size(); ++k)
                tags_[points[k]].push_back(Tag{id, static_cast<std::uint32_t>(k)});
            for (const IntPoint& p : points)
                if (ring.empty() || !(ring.back() == p)) ring.push_back(p);
            sources_.push_back(std::move(source));
        }
        if (ring.size() > 1 && ring.back() == ring.front()) ring.pop_back();
        if (ring.size() >= 3) rings.push_back(std::move(ring));
    }
    first_source_of_path_.push_back(sources_.size());
    return rings;
}

// An input vertex is known exactly (not just on the integer grid): a T-junction lands on
// the curve it meets at the right place.
Geom::Point BoundaryTrace::exact_point(const IntPoint& v) const {
    const std::vector<Tag>* tags = tags_at(v);
    if (!tags) return to_real(v);
    const Source& s = sources_[tags->front().source];
    return curve(s).pointAt(s.times[tags->front().sample]);
}

const std::vector<BoundaryTrace::Tag>* BoundaryTrace::tags_at(const IntPoint& p) const {
    auto it = tags_.find(p);
    return it == tags_.end() ? nullptr : &it->second;
}

// Whether v lies on the chord between samples k and k+1 of s (within the integer rounding of
// a Clipper crossing), and if so the curve time of v's nearest point on that stretch.
bool BoundaryTrace::on_chord(const Source& s, std::size_t k, const IntPoint& v, double& t) const {
    if (k + 1 >= s.times.size()) return false;
    auto real = [](const IntPoint& i) {
        return Geom::Point(static_cast<double>(i.X), static_cast<double>(i.Y));
    };
    const Geom::Point p = real(s.points[k]), w = real(v);
    const Geom::Point d = real(s.points[k + 1]) - p;
    const double len2 = Geom::dot(d, d);
    if (len2 == 0) return false;
    const double along = Geom::dot(w - p, d);
    if (along < -4 * std::sqrt(len2) || along > len2 + 4 * std::sqrt(len2)) return false;
    if (std::abs(Geom::cross(w - p, d)) > 2 * std::sqrt(len2)) return false;
    t = curve(s).nearestTime(exact_point(v), s.times[k], s.times[k + 1]);
    return true;
}

BoundaryTrace::Piece BoundaryTrace::piece(const IntPoint& u, const IntPoint& v) const {
    const std::vector<Tag>* tu = tags_at(u);
    const std::vector<Tag>* tv = tags_at(v);
    Piece out;
    out.a = to_real(u);
    out.b = to_real(v);
    if (tu && tv) {
        for (const Tag& a : *tu)
            for (const Tag& b : *tv)
                if (a.source == b.source &&
                    (a.sample + 1 == b.sample || b.sample + 1 == a.sample)) {
                    const Source& s = sources_[a.source];
                    out.source = a.source;
                    out.t0 = s.times[a.sample];
                    out.t1 = s.times[b.sample];
                    return out;
                }
    }
    double t = 0;
    if (tu) {
        for (const Tag& a : *tu) {
            const Source& s = sources_[a.source];
            for (std::size_t k : {std::size_t(a.sample), std::size_t(a.sample) - 1}) {
                if (k > a.sample && a.sample == 0) continue;
                if (on_chord(s, k, v, t)) {
                    out.source = a.source;
                    out.t0 = s.times[a.sample];
                    out.t1 = t;
                    return out;
                }
            }
        }
    }
    if (tv) {
        for (const Tag& b : *tv) {
            const Source& s = sources_[b.source];
            for (std::size_t k : {std::size_t(b.sample), std::size_t(b.sample) - 1}) {
                if (k > b.sample && b.sample == 0) continue;
                if (on_chord(s, k, u, t)) {
                    out.source = b.source;
                    out.t0 = t;
                    out.t1 = s.times[b.sample];
                    return out;
                }
            }
        }
    }
    return out;  // a straight line: both ends are crossings on one chord, or nothing fits
}

// Where two curve pieces meet at a crossing Clipper found on their chords, moves both ends to
// the exact crossing of the curves when lib2geom finds one close by.
void BoundaryTrace::refine_crossing(Piece& in, Piece& out) const {
    if (in.source < 0 || out.source < 0 || in.source == out.source) return;
    const Geom::Curve& a = curve(sources_[in.source]);
    const Geom::Curve& b = curve(sources_[out.source]);
    std::vector<Geom::CurveIntersection> xs;
    try {
        xs = a.intersect(b);
    } catch (const std::exception&) {
        return;
    }
    const Geom::Point x = in.b;
    double best = 4 * tolerance_ + 8 / scale_;
    for (const Geom::CurveIntersection& ci : xs) {
        const double d = Geom::distance(ci.point(), x);
        if (d < best) {
            best = d;
            in.t1 = ci.first;
            out.t0 = ci.second;
        }
    }
}

std::vector<BoundaryTrace::Piece> BoundaryTrace::pieces(const ClipperLib::Path& ring) const {
    const std::size_t n = ring.size();
    std::vector<Piece> raw;
    raw.reserve(n);
    for (std::size_t i = 0; i < n; ++i) raw.push_back(piece(ring[i], ring[(i + 1) % n]));
    for (std::size_t i = 0; i < n; ++i)
        if (!tags_at(ring[(i + 1) % n])) refine_crossing(raw[i], raw[(i + 1) % n]);

    // Runs of one curve become one piece.
    std::vector<Piece> merged;
    for (const Piece& p : raw) {
        if (!merged.empty() && p.source >= 0 && merged.back().source == p.source &&
            merged.back().t1 == p.t0 && (merged.back().t0 < merged.back().t1) == (p.t0 < p.t1)) {
            merged.back().t1 = p.t1;
            merged.back().b = p.b;
            continue;
        }
        merged.push_back(p);
    }
    if (merged.size() > 1) {
        Piece& first = merged.front();
        const Piece& last = merged.back();
        if (last.source >= 0 && last.source == first.source && last.t1 == first.t0 &&
            (last.t0 < last.t1) == (first.t0 < first.t1)) {
            first.t0 = last.t0;
            first.a = last.a;
            merged.pop_back();
        }
    }
    return merged;
}

// The input subpath itself (or its reverse) when the pieces are all of its curves, whole.
std::optional<Geom::Path> BoundaryTrace::whole_subpath(const std::vector<Piece>& pieces) const {
    if (pieces.empty() || pieces.front().source < 0) return std::nullopt;
    const std::size_t path = sources_[pieces.front().source].path;
    const std::size_t begin = first_source_of_path_[path], end = first_source_of_path_[path + 1];
    if (pieces.size() != end - begin) return std::nullopt;
    const bool forward = pieces.front().t0 < pieces.front().t1;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        const Piece& p = pieces[i];
        if (p.source < 0 || static_cast<std::size_t>(p.source) < begin ||
            static_cast<std::size_t>(p.source) >= end)
            return std::nullopt;
        if (forward ? (p.t0 != 0 || p.t1 != 1) : (p.t0 != 1 || p.t1 != 0)) return std::nullopt;
        // Consecutive pieces are consecutive curves, in the direction of travel.
        const std::size_t next = static_cast<std::size_t>(pieces[(i + 1) % pieces.size()].source);
        const std::size_t here = static_cast<std::size_t>(p.source);
        const std::size_t want =
            forward ? (here + 1 == end ? begin : here + 1) : (here == begin ? end - 1 : here - 1);
        if (next != want) return std::nullopt;
    }
    return forward ? paths_[path] : paths_[path].reversed();
}

Geom::Path BoundaryTrace::rebuild(const ClipperLib::Path& ring) const {
    const std::vector<Piece> list = pieces(ring);
    if (std::optional<Geom::Path> whole = whole_subpath(list)) return *whole;

    std::vector<std::unique_ptr<Geom::Curve>> segments;
    for (const Piece& p : list) {
        if (p.source >= 0)
            segments.emplace_back(curve(sources_[p.source]).portion(p.t0, p.t1));
        else
            segments.emplace_back(std::make_unique<Geom::LineSegment>(p.a, p.b));
    }
    // Ends meet exactly: each segment starts where the one before it ends.
    Geom::Path out(segments.front()->initialPoint());
    for (std::size_t i = 0; i < segments.size(); ++i) {
        Geom::Curve& s = *segments[i];
        s.setInitial(out.finalPoint());
        if (i + 1 == segments.size()) s.setFinal(out.initialPoint());
        if (s.isDegenerate()) continue;
        out.append(s);
    }
    out.close(true);
    return out;
}

std::uint64_t BoundaryTrace::first_source(const ClipperLib::Path& ring) const {
    std::uint64_t best = std::numeric_limits<std::uint64_t>::max();
    for (const IntPoint& p : ring)
        if (const std::vector<Tag>* tags = tags_at(p))
            for (const Tag& t : *tags)
                best = std::min(best, (std::uint64_t(t.source) << 32) | t.sample);
    return best;
}

}  // namespace acanthus::detail
