#include <acanthus/error.hpp>
#include <acanthus/rule_call.hpp>
#include <algorithm>
#include <exception>
#include <string>

#include "pattern/running_body.hpp"
#include "proxy/proxy_range.hpp"

namespace acanthus {
namespace {
thread_local RuleCall* current_call = nullptr;

template <class T>
bool erase_value(std::vector<T>& v, T x) {
    auto it = std::find(v.begin(), v.end(), x);
    if (it == v.end()) return false;
    v.erase(it);
    return true;
}

std::string describe(const Element& e, std::size_t k) {
    return "'" + e.type().name + "' proxy " + std::to_string(k) + " (" +
           std::string(to_string(e.type().proxies.at(k))) + ")";
}
}  // namespace

RuleCall::RuleCall(const RuleInfo& rule, Element& parent)
    : rule_(rule), parent_(parent), previous_(current_call) {
    current_call = this;
}

RuleCall::~RuleCall() {
    current_call = previous_;
    // Not current any more, so these deletes do not call back into untrack().
    std::unordered_map<void*, Role> leftovers;
    leftovers.swap(created_);
    for (const auto& [p, role] : leftovers) delete static_cast<Element*>(p);
}

RuleCall* RuleCall::current() { return current_call; }

void RuleCall::track(Element* e) { created_[e] = Role::created; }

void RuleCall::add_static(Element* e) {
    created_[e] = Role::static_child;
    statics_.push_back(e);
}

void RuleCall::untrack(Element* e) {
    const auto it = created_.find(e);
    if (it == created_.end()) return;
    if (it->second == Role::static_child) erase_value(statics_, e);
    if (it->second == Role::dynamic_child) erase_value(dynamics_, e);
    created_.erase(it);
}

void RuleCall::add_dynamic(Element& e) {
    const auto it = created_.find(&e);
    if (it == created_.end())
        throw std::logic_error("new_child(): the element was not created with new in this rule");
    if (it->second == Role::static_child)
        throw std::logic_error("new_child(): a static child is already a child of this rule");
    if (it->second == Role::dynamic_child)
        throw std::logic_error("new_child(): the element was already added");
    it->second = Role::dynamic_child;
    dynamics_.push_back(&e);
}

Result RuleCall::fell_off_end() {
    throw RuleFailure(rule_.file, rule_.line, rule_.name,
                      "the body ended without returning SUCCESS or FAILURE");
}

Result RuleCall::run() {
    Result r;
    try {
        const detail::RunningBody running(
            detail::body_label(&rule_, rule_.file, rule_.line, rule_.name));
        r = rule_.body(*this);
    } catch (const RuleFailure&) {
        throw;
    } catch (const InputError&) {
        throw;  // a library's input file (a reference, a shape file) is bad input: exit 1
    } catch (const std::exception& e) {
        throw RuleFailure(rule_.file, rule_.line, rule_.name,
                          std::string("exception thrown: ") + e.what());
    } catch (...) {
        throw RuleFailure(rule_.file, rule_.line, rule_.name, "unknown exception thrown");
    }
    if (r != SUCCESS && r != FAILURE)
        throw RuleFailure(rule_.file, rule_.line, rule_.name,
                          "the body returned " + std::to_string(static_cast<int>(r)) +
                              ", not SUCCESS or FAILURE");
    return r;
}

std::vector<std::unique_ptr<Element>> RuleCall::take_children() {
    std::vector<Element*> all = statics_;
    all.insert(all.end(), dynamics_.begin(), dynamics_.end());
    for (std::size_t i = 0; i < all.size(); ++i) {
        const Element& e = *all[i];
        const std::string which =
            i < statics_.size() ? "static child " + std::to_string(i) : "dynamic child";
        for (std::size_t k = 0; k < e.proxy_count(); ++k) {
            if (!e.proxy(k).is_set())
                throw RuleFailure(rule_.file, rule_.line, rule_.name,
                                  which + " " + describe(e, k) + " was never set");
            if (!e.proxy(k).finite())
                throw RuleFailure(
                    rule_.file, rule_.line, rule_.name,
                    which + " " + describe(e, k) + " has NaN or infinite coordinates");
            if (const std::string problem = detail::proxy_range_problem(e.proxy(k));
                !problem.empty())
                throw RuleFailure(rule_.file, rule_.line, rule_.name,
                                  which + " " + describe(e, k) + " has " + problem);
        }
    }
    std::vector<std::unique_ptr<Element>> out;
    out.reserve(all.size());
    for (Element* e : all) {
        created_.erase(e);
        out.emplace_back(e);
    }
    statics_.clear();
    dynamics_.clear();
    return out;
}

}  // namespace acanthus
