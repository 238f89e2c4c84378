// --param values: out of the type's range is an error, never inf, 0 or a clamped value.
#include <gtest/gtest.h>

#include <acanthus/param.hpp>
#include <acanthus/pattern.hpp>
#include <string>

namespace {

template <class T>
std::string error_for(const std::string& text) {
    T value{};
    std::string error;
    if (acanthus::parse_param(text, value, error)) return "";
    return error;
}

TEST(ParamRange, FloatOverflowAndUnderflow) {
    EXPECT_NE(error_for<float>("1e39").find("out of range for float"), std::string::npos);
    EXPECT_NE(error_for<float>("-1e39").find("out of range for float"), std::string::npos);
    EXPECT_NE(error_for<float>("1e-50").find("out of range for float"), std::string::npos);
    EXPECT_EQ(error_for<float>("0"), "");
    EXPECT_EQ(error_for<float>("3.4e38"), "");
    EXPECT_EQ(error_for<float>("1e-37"), "");
}

TEST(ParamRange, DoubleOverflowAndUnderflow) {
    EXPECT_NE(error_for<double>("1e400").find("out of range for double"), std::string::npos);
    EXPECT_NE(error_for<double>("1e-400").find("out of range for double"), std::string::npos);
    EXPECT_NE(error_for<double>("inf").find("not a finite number"), std::string::npos);
    EXPECT_EQ(error_for<double>("1e300"), "");
}

TEST(ParamRange, Integers) {
    EXPECT_NE(error_for<int>("2147483648").find("out of range for int"), std::string::npos);
    EXPECT_NE(error_for<int>("-2147483649").find("out of range for int"), std::string::npos);
    EXPECT_EQ(error_for<int>("2147483647"), "");
    EXPECT_NE(error_for<long>("9223372036854775808").find("out of range for long"),
              std::string::npos);
    EXPECT_NE(error_for<int>("1.5").find("is not an int"), std::string::npos);
}

}  // namespace
