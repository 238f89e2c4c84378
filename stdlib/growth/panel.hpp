// Where synthesis may place motifs: a whole region (tests, benchmarks) or the room the running
// ornament leaves (the Environment of a rule body: its region and placed elements).
#pragma once

#include <acanthus/region.hpp>

namespace acanthus {
class Environment;
}

namespace acanthus::growth::detail {

class Panel {
  public:
    virtual ~Panel() = default;
    // Seeds outside are dropped.
    virtual bool contains(Point p) const = 0;
    // The motif circle lies inside (touching within `tolerance` allowed) and clear of obstacles.
    virtual bool admits(Circle motif, double tolerance) const = 0;
    // Growth may step from `from` to `to` (no boundary stroke between them).
    virtual bool reaches(Point /*from*/, Point /*to*/) const { return true; }
    // A box around the room (empty: unknown, and growth does not restart in holes).
    virtual Rect bounds() const = 0;
    // Distance from p to the panel's edge (for choosing the middle of an empty lobe).
    virtual double clearance(Point p) const = 0;
    // Under a symmetry group: the first motif stays on the seed it is given (a lattice moved
    // off it would no longer mesh with its images across mirrors and tile edges).
    virtual bool symmetric() const { return false; }
    // The room's area, at most (for the estimate of how many motifs it holds).
    virtual double area() const {
        Rect b = bounds();
        return b.width() * b.height();
    }
};

class RegionPanel : public Panel {
  public:
    explicit RegionPanel(const Region& region) : region_(region) {}
    bool contains(Point p) const override { return region_.contains(p); }
    bool admits(Circle motif, double tolerance) const override;
    Rect bounds() const override { return region_.bounds(); }
    double clearance(Point p) const override { return region_.distance_to_boundary(p); }
    double area() const override { return region_.area(); }

  private:
    const Region& region_;
};

// Inside a rule body: the running engine answers for its region and its placed elements. A
// point proxy (the seed synthesis starts on) does not block a motif.
class EnvironmentPanel : public Panel {
  public:
    explicit EnvironmentPanel(Environment& env) : env_(env) {}
    bool contains(Point p) const override;
    bool admits(Circle motif, double tolerance) const override;
    Rect bounds() const override;
    double clearance(Point p) const override;
    double area() const override;
    bool symmetric() const override;

  private:
    Environment& env_;
};

}  // namespace acanthus::growth::detail
