#include "server/settings.hpp"

#include <cstdlib>

namespace acanthus {

namespace {

std::string number_text(double v) {
    std::string s = std::to_string(v);
    s.erase(s.find_last_not_of('0') + 1);
    if (!s.empty() && s.back() == '.') s.pop_back();
    return s;
}

}  // namespace

std::vector<std::string> PreviewSettings::arguments(bool shown) const {
    std::vector<std::string> a = other;
    if (!region.empty()) a.insert(a.end(), {"--region", region});
    for (const std::string& s : seeds) a.insert(a.end(), {"--seed", s});
    if (!rng_seed.empty()) a.insert(a.end(), {"--rng-seed", rng_seed});
    for (const auto& [name, value] : params) a.insert(a.end(), {"--param", name + "=" + value});
    if (!shown || time_limit_given) a.insert(a.end(), {"--time-limit", number_text(time_limit)});
    return a;
}

bool PreviewSettings::take(const std::vector<std::string>& args, std::string& error) {
    for (std::size_t i = 0; i < args.size(); ++i) {
        std::string opt = args[i], value;
        bool inline_value = false;
        if (opt.rfind("--", 0) == 0 && opt.find('=') != std::string::npos) {
            value = opt.substr(opt.find('=') + 1);
            opt = opt.substr(0, opt.find('='));
            inline_value = true;
        }
        auto next = [&](std::string& out) {
            if (inline_value) {
                out = value;
                return true;
            }
            if (i + 1 >= args.size()) {
                error = "'" + opt + "' needs a value";
                return false;
            }
            out = args[++i];
            return true;
        };
        if (opt == "-o" || opt == "--output" || opt == "--metrics" || opt == "--frames" ||
            opt == "--every" || opt == "--debug-frame" || opt == "--json" || opt == "--partial" ||
            opt == "--view" || opt == "--view-size" || opt == "--list-params" || opt == "--help" ||
            opt == "--version") {
            error = "'" + opt + "' is set by the preview itself; leave it out";
            return false;
        }
        std::string v;
        if (opt == "--region") {
            if (!next(region)) return false;
        } else if (opt == "--seed") {
            if (!next(v)) return false;
            seeds.push_back(v);
        } else if (opt == "--rng-seed") {
            if (!next(rng_seed)) return false;
        } else if (opt == "--time-limit") {
            if (!next(v)) return false;
            char* end = nullptr;
            time_limit = std::strtod(v.c_str(), &end);
            time_limit_given = true;
            if (v.empty() || *end != '\0' || !(time_limit > 0) || time_limit > 86400) {
                error = "bad --time-limit '" + v + "' (seconds, more than 0)";
                return false;
            }
        } else if (opt == "--param") {
            if (!next(v)) return false;
            auto eq = v.find('=');
            if (eq == std::string::npos || eq == 0) {
                error = "--param expects NAME=VALUE, not '" + v + "'";
                return false;
            }
            params[v.substr(0, eq)] = v.substr(eq + 1);
        } else {
            other.push_back(args[i]);
        }
    }
    return true;
}

}  // namespace acanthus
