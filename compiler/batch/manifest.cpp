#include "batch/manifest.hpp"

#include <toml++/toml.h>

#include <acanthus/input_file.hpp>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>

namespace acanthus::batch {

namespace fs = std::filesystem;

ManifestError::ManifestError(std::string file, ManifestPosition where, const std::string& message)
    : std::runtime_error(
          file +
          (where.line > 0 ? ":" + std::to_string(where.line) + ":" + std::to_string(where.column)
                          : std::string()) +
          ": error: " + message),
      file_(std::move(file)),
      where_(where),
      message_(message) {}

const std::vector<std::string>& known_formats() {
    static const std::vector<std::string> formats{"svg", "png", "pdf", "ps", "eps"};
    return formats;
}

bool is_builtin_panel(const std::string& panel) {
    for (const char* kind : {"rect:", "circle:", "ellipse:"})
        if (panel.rfind(kind, 0) == 0) return true;
    return false;
}

namespace {

const char* const kJobKeys[] = {"rules", "panels", "seeds", "params", "args", "formats", "output"};

ManifestPosition position_of(const toml::source_region& source) {
    return {static_cast<int>(source.begin.line), static_cast<int>(source.begin.column)};
}

const char* type_name(toml::node_type type) {
    switch (type) {
        case toml::node_type::table:
            return "a table";
        case toml::node_type::array:
            return "a list";
        case toml::node_type::string:
            return "a string";
        case toml::node_type::integer:
            return "an integer";
        case toml::node_type::floating_point:
            return "a number";
        case toml::node_type::boolean:
            return "a boolean";
        default:
            return "a date or time";
    }
}

// Reads one [[job]] table; `fail` throws at a position with a message.
class JobReader {
  public:
    JobReader(const Manifest& manifest, const toml::table& table)
        : manifest_(manifest), table_(table) {}

    JobSpec read() {
        JobSpec spec;
        spec.where = position_of(table_.source());
        for (auto&& [key, node] : table_) {
            if (std::find(std::begin(kJobKeys), std::end(kJobKeys), key.str()) !=
                std::end(kJobKeys))
                continue;
            fail(position_of(key.source()),
                 "unknown key '" + std::string(key.str()) +
                     "' in [[job]] (the keys are rules, panels, seeds, params, args, formats, "
                     "output)");
        }
        for (auto& text : strings("rules", true))
            spec.rules.push_back({existing_file(text, "rule file"), text.where});
        for (auto& text : strings("panels", true)) {
            std::string panel =
                is_builtin_panel(text.value) ? text.value : existing_file(text, "panel file");
            spec.panels.push_back({panel, text.where});
        }
        spec.seeds = seeds();
        spec.params = params();
        for (auto& text : strings("args", false)) spec.args.push_back(text.value);
        spec.formats = strings("formats", false);
        if (!table_.contains("formats")) spec.formats.push_back({"svg", spec.where});
        for (const auto& format : spec.formats) {
            const auto& known = known_formats();
            if (std::find(known.begin(), known.end(), format.value) == known.end())
                fail(format.where,
                     "unknown format '" + format.value + "' (use svg, png, pdf, ps or eps)");
        }
        spec.output = output(spec.params.empty());
        return spec;
    }

  private:
    [[noreturn]] void fail(ManifestPosition where, const std::string& message) const {
        throw ManifestError(manifest_.path, where, message);
    }

    // A string or a list of strings; an empty list leaves nothing to multiply.
    std::vector<Placed<std::string>> strings(const char* key, bool required) const {
        const toml::node* node = table_.get(key);
        if (!node) {
            if (required)
                fail(position_of(table_.source()), "[[job]] needs '" + std::string(key) + "'");
            return {};
        }
        std::vector<Placed<std::string>> out;
        auto take = [&](const toml::node& item) {
            if (!item.is_string())
                fail(position_of(item.source()),
                     "'" + std::string(key) + "' must hold strings, not " + type_name(item.type()));
            out.push_back({*item.value<std::string>(), position_of(item.source())});
        };
        if (const toml::array* list = node->as_array()) {
            if (list->empty() && std::string_view(key) != "args")
                fail(position_of(node->source()),
                     "empty product: '" + std::string(key) + "' is an empty list");
            for (const toml::node& item : *list) take(item);
        } else if (node->is_string()) {
            take(*node);
        } else {
            fail(position_of(node->source()), "'" + std::string(key) +
                                                  "' must be a string or a list of strings, not " +
                                                  type_name(node->type()));
        }
        return out;
    }

    std::string existing_file(const Placed<std::string>& text, const char* what) const {
        if (text.value.empty()) fail(text.where, std::string("empty ") + what + " path");
        fs::path path = fs::path(manifest_.directory) / text.value;
        std::error_code ec;
        auto status = fs::status(path, ec);
        if (ec || !fs::exists(status))
            fail(text.where, std::string("missing ") + what + " '" + text.value + "' (" +
                                 path.lexically_normal().string() + ")");
        if (!fs::is_regular_file(status))
            fail(text.where, std::string(what) + " '" + text.value + "' is not a regular file");
        return path.lexically_normal().string();
    }

    std::vector<Placed<std::uint64_t>> seeds() const {
        const toml::node* node = table_.get("seeds");
        if (!node) return {{1, position_of(table_.source())}};
        std::vector<Placed<std::uint64_t>> out;
        auto take = [&](const toml::node& item) {
            if (!item.is_integer())
                fail(position_of(item.source()),
                     std::string("a seed must be an integer, not ") + type_name(item.type()));
            auto value = item.value_exact<std::int64_t>();
            if (*value < 0)
                fail(position_of(item.source()), "a seed must not be negative (an --rng-seed)");
            out.push_back({static_cast<std::uint64_t>(*value), position_of(item.source())});
        };
        if (const toml::array* list = node->as_array()) {
            if (list->empty())
                fail(position_of(node->source()), "empty product: 'seeds' is an empty list");
            for (const toml::node& item : *list) take(item);
        } else {
            take(*node);
        }
        return out;
    }

    // A parameter value as `--param` text: numbers in their shortest exact spelling.
    std::string scalar_text(const std::string& name, const toml::node& item) const {
        if (auto s = item.value_exact<std::string>()) return *s;
        if (auto b = item.value_exact<bool>()) return *b ? "true" : "false";
        if (auto i = item.value_exact<std::int64_t>()) return std::to_string(*i);
        if (auto d = item.value_exact<double>()) {
            if (!std::isfinite(*d))
                fail(position_of(item.source()), "parameter '" + name + "' must be finite");
            char buffer[64];
            auto result = std::to_chars(buffer, buffer + sizeof buffer, *d);
            return std::string(buffer, result.ptr);
        }
        fail(position_of(item.source()), "parameter '" + name +
                                             "' takes strings, numbers or booleans, not " +
                                             type_name(item.type()));
    }

    std::vector<ParamValues> params() const {
        const toml::node* node = table_.get("params");
        if (!node) return {};
        const toml::table* table = node->as_table();
        if (!table)
            fail(position_of(node->source()),
                 std::string("'params' must be a table of lists, not ") + type_name(node->type()));
        std::vector<ParamValues> out;
        for (auto&& [key, value] : *table) {
            ParamValues param{std::string(key.str()), {}, position_of(key.source())};
            if (const toml::array* list = value.as_array()) {
                if (list->empty())
                    fail(position_of(value.source()),
                         "empty product: parameter '" + param.name + "' has no values");
                for (const toml::node& item : *list)
                    param.values.push_back(scalar_text(param.name, item));
            } else {
                param.values.push_back(scalar_text(param.name, value));
            }
            out.push_back(std::move(param));
        }
        return out;
    }

    Placed<std::string> output(bool no_params) const {
        const toml::node* node = table_.get("output");
        if (!node)
            return {no_params ? "out/{rule}/{panel}-{seed}.{ext}"
                              : "out/{rule}/{panel}-{seed}-{params}.{ext}",
                    position_of(table_.source())};
        if (!node->is_string())
            fail(position_of(node->source()),
                 std::string("'output' must be a string, not ") + type_name(node->type()));
        Placed<std::string> out{*node->value<std::string>(), position_of(node->source())};
        if (out.value.empty() || fs::path(out.value).is_absolute())
            fail(out.where, "'output' must be a relative path (outputs go below --output-dir)");
        return out;
    }

    const Manifest& manifest_;
    const toml::table& table_;
};

}  // namespace

Manifest parse_manifest(const std::string& text, const std::string& path) {
    Manifest manifest;
    manifest.path = path;
    std::error_code ec;
    manifest.directory = fs::absolute(fs::path(path), ec).parent_path().lexically_normal().string();
    toml::table root;
    try {
        root = toml::parse(text, path);
    } catch (const toml::parse_error& e) {
        throw ManifestError(path, position_of(e.source()), std::string(e.description()));
    }
    for (auto&& [key, node] : root) {
        if (key.str() != "job")
            throw ManifestError(
                path, position_of(key.source()),
                "unknown key '" + std::string(key.str()) + "' (a manifest holds [[job]] tables)");
    }
    const toml::node* jobs = root.get("job");
    if (!jobs) throw ManifestError(path, {1, 1}, "the manifest has no [[job]] table");
    const toml::array* list = jobs->as_array();
    if (!list || !list->is_array_of_tables())
        throw ManifestError(path, position_of(jobs->source()),
                            "'job' must be written as [[job]] tables");
    for (const toml::node& job : *list)
        manifest.jobs.push_back(JobReader(manifest, *job.as_table()).read());
    return manifest;
}

Manifest load_manifest(const std::string& path) {
    std::string text;
    if (std::string why = read_input_file(path, text); !why.empty())
        throw ManifestError(path, {0, 0}, "cannot read the manifest: " + why);
    return parse_manifest(text, path);
}

}  // namespace acanthus::batch
