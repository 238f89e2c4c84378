// Reading and writing a rule file's %param values as text (--param name=value, --list-params);
// the generated assign/current functions call these.
#pragma once

#include <string>
#include <string_view>
#include <vector>

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

// A library's own command-line option: `--FLAG VALUE` sets the %param `param`, as
// `--param PARAM=VALUE` would (after every --param, so the flag wins). A library registers it in
// its rule file's %source, at namespace scope, so that it is known before main() runs:
//     inline const bool my_flag = acanthus::register_param_flag({"--cut-list", "cells_cut_list",
//                                                               "FILE.csv|FILE.json", "..."});
// A program lists and accepts the flags whose parameter it has (docs/cli.md).
struct ParamFlag {
    std::string flag;       // "--cut-list"
    std::string param;      // the %param it sets
    std::string type_name;  // shown in --help, e.g. "FILE.csv|FILE.json"
    std::string help;
};
bool register_param_flag(ParamFlag flag);  // true; a flag registered twice is kept once
const std::vector<ParamFlag>& param_flags();

}  // namespace acanthus
