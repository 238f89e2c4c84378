// Boundary curves flattened for Clipper with a record of where every vertex came from, so
// that Clipper's output rings can be turned back into the exact curves they follow: Clipper
// decides which pieces of boundary are kept, lib2geom's curves say what those pieces are.
#pragma once

#include <2geom/path.h>
#include <2geom/pathvector.h>
#include <2geom/rect.h>

#include <cstdint>
#include <deque>
#include <optional>
#include <polyclipping/clipper.hpp>
#include <unordered_map>
#include <vector>

namespace acanthus::detail {

class BoundaryTrace {
  public:
    // `frame` holds every input point; chords stay within `tolerance` (user units) of the
    // curves they replace.
    BoundaryTrace(Geom::Rect frame, double tolerance);

    // Flattens closed subpaths (kept by the trace) into integer rings, one per subpath.
    ClipperLib::Paths add(const Geom::PathVector& paths);

    // The exact closed path that an output ring of Clipper follows: runs of chords become the
    // curve pieces they were cut from, crossings are refined on the exact curves, and a ring
    // that is a whole input subpath comes back as that very subpath.
    Geom::Path rebuild(const ClipperLib::Path& ring) const;

    // The earliest input curve (in the order added) that the ring follows, for a stable
    // order of output rings; UINT64_MAX when it follows none.
    std::uint64_t first_source(const ClipperLib::Path& ring) const;

  private:
    struct Source {                 // one input curve
        std::size_t path;           // index into paths_
        std::size_t index;          // curve index in that path (closing segment included)
        std::vector<double> times;  // curve times of its kept samples, ascending
        std::vector<ClipperLib::IntPoint> points;  // the samples on the integer grid
    };
    struct Tag {
        std::uint32_t source;
        std::uint32_t sample;
    };
    struct Piece {  // a stretch of one input curve, or a straight line when source < 0
        std::int64_t source = -1;
        double t0 = 0, t1 = 0;
        Geom::Point a, b;  // end points (for lines, and as targets for refinement)
    };
    struct KeyHash {
        std::size_t operator()(const ClipperLib::IntPoint& p) const noexcept {
            return std::hash<std::uint64_t>()(static_cast<std::uint64_t>(p.X) *
                                                  0x9E3779B97F4A7C15ULL ^
                                              static_cast<std::uint64_t>(p.Y));
        }
    };
    struct KeyEqual {
        bool operator()(const ClipperLib::IntPoint& a,
                        const ClipperLib::IntPoint& b) const noexcept {
            return a.X == b.X && a.Y == b.Y;
        }
    };

    ClipperLib::IntPoint to_int(Geom::Point p) const;
    Geom::Point to_real(const ClipperLib::IntPoint& p) const;
    const Geom::Curve& curve(const Source& s) const;
    std::vector<Piece> pieces(const ClipperLib::Path& ring) const;
    Piece piece(const ClipperLib::IntPoint& u, const ClipperLib::IntPoint& v) const;
    bool on_chord(const Source& s, std::size_t k, const ClipperLib::IntPoint& v, double& t) const;
    void refine_crossing(Piece& in, Piece& out) const;
    const std::vector<Tag>* tags_at(const ClipperLib::IntPoint& p) const;
    Geom::Point exact_point(const ClipperLib::IntPoint& v) const;
    std::optional<Geom::Path> whole_subpath(const std::vector<Piece>& pieces) const;

    Geom::Point origin_;
    double scale_ = 1;     // integer units per user unit
    bool turned_ = false;  // integer frame turned a quarter: (x, y) -> (y, -x)
    double tolerance_;
    std::deque<Geom::Path> paths_;
    std::vector<std::size_t> first_source_of_path_;
    std::vector<Source> sources_;
    std::unordered_map<ClipperLib::IntPoint, std::vector<Tag>, KeyHash, KeyEqual> tags_;
};

}  // namespace acanthus::detail
