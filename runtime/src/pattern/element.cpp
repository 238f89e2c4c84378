// Element allocation goes through the running RuleCall so that whatever a body creates and
// does not add is freed when the call ends.
#include <acanthus/element.hpp>
#include <acanthus/rule_call.hpp>
#include <new>

namespace acanthus {

void* Element::operator new(std::size_t size) {
    void* p = ::operator new(size);
    if (RuleCall* call = RuleCall::current()) call->track(static_cast<Element*>(p));
    return p;
}

void Element::operator delete(void* p) noexcept {
    if (!p) return;
    if (RuleCall* call = RuleCall::current()) call->untrack(static_cast<Element*>(p));
    ::operator delete(p);
}

}  // namespace acanthus
