// What a rule body can ask of the growing ornament. The engine installs one while it runs.
#pragma once

#include <acanthus/element.hpp>
#include <acanthus/random.hpp>
#include <acanthus/region.hpp>

namespace acanthus {

class Environment {
  public:
    virtual ~Environment() = default;
    // The empty circle C of the current iteration.
    virtual Circle goal() const = 0;
    // True if any proxy of `e` overlaps a proxy of a placed element or leaves the region.
    // Touching within a small tolerance is not overlap.
    virtual bool intersects(const Element& e) const = 0;
    virtual bool intersects(const Proxy& p) const = 0;
    virtual bool inside(Point p) const = 0;
    virtual double distance_to_boundary(Point p) const = 0;
    // Placed element with a proxy nearest to p, or null if none.
    virtual Element* nearest_element(Point p) const = 0;
    virtual void clear_exclude_list() = 0;
    virtual Random& random() = 0;
    // The region being filled, or null when the environment has none (libraries such as
    // dartfill use it for their own exact containment tests).
    virtual const Region* region() const { return nullptr; }
    // True while the ornament grows under a symmetry group: where a body puts its first
    // element relative to the seed it was given then places the group's images too.
    virtual bool symmetric() const { return false; }

    // The environment installed for the running body, or null.
    static Environment* current();

    // Installs `env` for the lifetime of the scope.
    class Scope {
      public:
        explicit Scope(Environment* env);
        ~Scope();
        Scope(const Scope&) = delete;
        Scope& operator=(const Scope&) = delete;

      private:
        Environment* previous_;
    };
};

}  // namespace acanthus
