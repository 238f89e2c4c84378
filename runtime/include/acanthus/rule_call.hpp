// One invocation of a rule body on a parent: owns every element the body creates until commit.
#pragma once

#include <acanthus/pattern.hpp>
#include <memory>
#include <unordered_map>
#include <vector>

namespace acanthus {

class RuleCall {
  public:
    RuleCall(const RuleInfo& rule, Element& parent);
    // Frees every element created during the call that was not taken by commit.
    ~RuleCall();
    RuleCall(const RuleCall&) = delete;
    RuleCall& operator=(const RuleCall&) = delete;

    const RuleInfo& rule() const { return rule_; }
    template <class T>
    T& parent() {
        return static_cast<T&>(parent_);
    }
    Element& parent_element() { return parent_; }

    // Static children are constructed before the body runs.
    template <class T>
    T* make_static() {
        T* e = new T;
        add_static(e);
        return e;
    }
    // make_static()'s bookkeeping, out of line: instantiated in every rule file's code, the
    // hash map's insertion was a sixth of the build of a pattern's rule code.
    void add_static(Element* e);
    // new_child(): adds a dynamic child (created by the body during this call).
    void add_dynamic(Element& e);
    // Called when control reaches the end of a body without a return; throws.
    [[noreturn]] Result fell_off_end();

    // Runs the body; exceptions from the body become RuleFailure.
    Result run();
    // After SUCCESS: checks every child proxy is set and finite (throws RuleFailure), then
    // hands over statics followed by dynamics, in order. Ownership passes to the caller.
    std::vector<std::unique_ptr<Element>> take_children();

    // The rule call whose body is running on this thread, or null.
    static RuleCall* current();
    // Allocation bookkeeping used by Element::operator new/delete.
    void track(Element* e);
    void untrack(Element* e);

  private:
    const RuleInfo& rule_;
    Element& parent_;
    RuleCall* previous_;
    std::vector<Element*> statics_;
    std::vector<Element*> dynamics_;
    // Raw allocations made through Element::operator new and what each has become: a body may
    // create hundreds of thousands (a library's whole arrangement), so no list is searched.
    enum class Role : unsigned char { created, static_child, dynamic_child };
    std::unordered_map<void*, Role> created_;
};

}  // namespace acanthus
