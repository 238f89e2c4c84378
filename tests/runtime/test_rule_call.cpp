// RuleCall: static and dynamic children, commit checks, and freeing what a body abandons.
#include <gtest/gtest.h>

#include <acanthus/body.hpp>
#include <acanthus/error.hpp>
#include <acanthus/rule_call.hpp>
#include <stdexcept>

namespace {
using namespace acanthus;

int live = 0;

struct blob final : Element {
    CircleProxy p0;
    int tag{};
    blob() { ++live; }
    ~blob() override { --live; }
    const ElementType& type() const override;
    std::size_t proxy_count() const override { return 1; }
    Proxy& proxy(std::size_t) override { return p0; }
};
Element* create_blob() { return new blob; }
const ElementType blob_type{"blob", {ProxyKind::circle}, &create_blob, nullptr, 1};
const ElementType& blob::type() const { return blob_type; }

RuleInfo make_rule(Result (*body)(RuleCall&)) {
    return RuleInfo{"blob --> blob", 7, "test.acr", &blob_type, {&blob_type}, body};
}

TEST(RuleCall, SuccessHandsOverStaticsThenDynamics) {
    blob parent;
    RuleInfo rule = make_rule([](RuleCall& call_) -> Result {
        blob* c0 = call_.make_static<blob>();
        c0->p0.set(Point{1, 2}, 3);
        blob* x = new blob;
        x->p0.set(Point{4, 5}, 1);
        x->tag = 9;
        body::new_child(*x);
        new blob;  // abandoned: must be freed
        return SUCCESS;
    });
    const int before = live;
    {
        RuleCall call(rule, parent);
        ASSERT_EQ(call.run(), SUCCESS);
        auto kids = call.take_children();
        ASSERT_EQ(kids.size(), 2u);
        EXPECT_EQ(static_cast<blob&>(*kids[0]).p0.radius, 3);
        EXPECT_EQ(static_cast<blob&>(*kids[1]).tag, 9);
        EXPECT_EQ(live, before + 3);
    }
    EXPECT_EQ(live, before);
}

TEST(RuleCall, FailureFreesEverything) {
    blob parent;
    RuleInfo rule = make_rule([](RuleCall& call_) -> Result {
        call_.make_static<blob>();
        blob* x = new blob;
        body::new_child(x);
        new blob;
        return FAILURE;
    });
    const int before = live;
    {
        RuleCall call(rule, parent);
        EXPECT_EQ(call.run(), FAILURE);
    }
    EXPECT_EQ(live, before);
}

TEST(RuleCall, BodyMayDeleteWhatItCreated) {
    blob parent;
    RuleInfo rule = make_rule([](RuleCall& call_) -> Result {
        call_.make_static<blob>()->p0.set(Point{0, 0}, 1);
        blob* x = new blob;
        body::new_child(x);
        delete x;  // also leaves the child set
        return SUCCESS;
    });
    const int before = live;
    {
        RuleCall call(rule, parent);
        ASSERT_EQ(call.run(), SUCCESS);
        EXPECT_EQ(call.take_children().size(), 1u);
    }
    EXPECT_EQ(live, before);
}

TEST(RuleCall, UnsetProxyNamesTheRuleAndLine) {
    blob parent;
    RuleInfo rule = make_rule([](RuleCall& call_) -> Result {
        call_.make_static<blob>();
        return SUCCESS;
    });
    RuleCall call(rule, parent);
    ASSERT_EQ(call.run(), SUCCESS);
    try {
        call.take_children();
        FAIL() << "expected RuleFailure";
    } catch (const RuleFailure& e) {
        EXPECT_EQ(e.line(), 7);
        EXPECT_NE(std::string(e.what()).find("test.acr:7: rule 'blob --> blob'"),
                  std::string::npos);
        EXPECT_NE(std::string(e.what()).find("never set"), std::string::npos);
    }
}

TEST(RuleCall, NanCoordinatesAreRefused) {
    blob parent;
    RuleInfo rule = make_rule([](RuleCall& call_) -> Result {
        call_.make_static<blob>()->p0.set(Point{0, 0}, std::nan(""));
        return SUCCESS;
    });
    RuleCall call(rule, parent);
    ASSERT_EQ(call.run(), SUCCESS);
    EXPECT_THROW(call.take_children(), RuleFailure);
}

TEST(RuleCall, ExceptionsBecomeRuleFailures) {
    blob parent;
    RuleInfo rule = make_rule([](RuleCall&) -> Result { throw std::runtime_error("boom"); });
    const int before = live;
    {
        RuleCall call(rule, parent);
        EXPECT_THROW(call.run(), RuleFailure);
    }
    EXPECT_EQ(live, before);
}

TEST(RuleCall, InputErrorsStayInputErrors) {
    blob parent;
    RuleInfo rule = make_rule([](RuleCall&) -> Result { throw InputError("ref.json: element 2"); });
    RuleCall call(rule, parent);
    try {
        call.run();
        FAIL() << "expected InputError";
    } catch (const RuleFailure&) {
        FAIL() << "an InputError became a RuleFailure";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "ref.json: element 2");
    }
}

TEST(RuleCall, NewChildOfForeignElementIsAnError) {
    static blob outsider;
    blob parent;
    RuleInfo rule = make_rule([](RuleCall&) -> Result {
        body::new_child(outsider);
        return SUCCESS;
    });
    RuleCall call(rule, parent);
    EXPECT_THROW(call.run(), RuleFailure);
}

TEST(RuleCall, FellOffEndThrows) {
    blob parent;
    RuleInfo rule = make_rule([](RuleCall& call_) -> Result { return call_.fell_off_end(); });
    RuleCall call(rule, parent);
    EXPECT_THROW(call.run(), RuleFailure);
}
}  // namespace
