// Support functions for rule bodies: forward to the environment the engine installed.
#include <acanthus/body.hpp>
#include <stdexcept>
#include <vector>

namespace acanthus::body {
namespace {
Environment& env() {
    Environment* e = Environment::current();
    if (!e) throw std::logic_error("support library used outside a running rule file");
    return *e;
}
RuleCall& call(const char* what) {
    RuleCall* c = RuleCall::current();
    if (!c) throw std::logic_error(std::string(what) + " used outside a rule body");
    return *c;
}
}  // namespace

Circle goal() { return env().goal(); }
bool intersection(const Element& e) { return env().intersects(e); }
bool intersection(const Element* e) {
    if (!e) throw std::invalid_argument("intersection(): null element");
    return env().intersects(*e);
}
bool intersection(const Proxy& p) { return env().intersects(p); }
bool inside(Point p) { return env().inside(p); }
double distance_to_boundary(Point p) { return env().distance_to_boundary(p); }
Element* nearest_element(Point p) { return env().nearest_element(p); }
void clear_exclude_list() { env().clear_exclude_list(); }

const std::vector<Corner>& corners() {
    // Asked for in rule bodies, once per candidate: found once per region (a later region may
    // reuse an address, so its bounds and area tell them apart too).
    struct Key {
        const Region* region = nullptr;
        Rect bounds;
        double area = 0;
        bool operator==(const Key& o) const {
            return region == o.region && bounds.x0 == o.bounds.x0 && bounds.y0 == o.bounds.y0 &&
                   bounds.x1 == o.bounds.x1 && bounds.y1 == o.bounds.y1 && area == o.area;
        }
    };
    static Key of;
    static std::vector<Corner> found;
    const Region* region = env().region();
    const Key key = region ? Key{region, region->bounds(), region->area()} : Key{};
    if (!(key == of)) {
        found = region ? region->corners() : std::vector<Corner>{};
        of = key;
    }
    return found;
}

void new_child(Element& e) { call("new_child()").add_dynamic(e); }
void new_child(Element* e) {
    if (!e) throw std::invalid_argument("new_child(): null element");
    new_child(*e);
}

double RandomSource::uniform() const { return env().random().uniform(); }
double RandomSource::uniform(double lo, double hi) const { return env().random().uniform(lo, hi); }
long long RandomSource::uniform_int(long long lo, long long hi) const {
    return env().random().uniform_int(lo, hi);
}
double RandomSource::normal(double mean, double stddev) const {
    return env().random().normal(mean, stddev);
}
bool RandomSource::chance(double probability) const { return env().random().chance(probability); }

}  // namespace acanthus::body
