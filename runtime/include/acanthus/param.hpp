// Reading and writing a rule file's %param values as text (--param name=value, --list-params);
// the generated assign/current functions call these.
#pragma once

#include <string>
#include <string_view>

namespace acanthus {

// False with `error` set when `text` is not a value of the type, or out of its range.
bool parse_param(std::string_view text, int& out, std::string& error);
bool parse_param(std::string_view text, long& out, std::string& error);
bool parse_param(std::string_view text, double& out, std::string& error);
bool parse_param(std::string_view text, float& out, std::string& error);
bool parse_param(std::string_view text, bool& out, std::string& error);
bool parse_param(std::string_view text, std::string& out, std::string& error);
std::string format_param(int v);
std::string format_param(long v);
std::string format_param(double v);
std::string format_param(float v);
std::string format_param(bool v);
std::string format_param(const std::string& v);

}  // namespace acanthus
