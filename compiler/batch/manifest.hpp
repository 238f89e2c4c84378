// The batch manifest (TOML): [[job]] tables whose rules, panels, seeds and params multiply out.
// Loading checks everything a job needs before any work starts (docs/batch.md).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace acanthus::batch {

// Where a value was written in the manifest (1-based; 0 when unknown).
struct ManifestPosition {
    int line = 0;
    int column = 0;
};

// A bad manifest: printed as "file:line:col: error: message", exit status 2.
class ManifestError : public std::runtime_error {
  public:
    ManifestError(std::string file, ManifestPosition where, const std::string& message);
    const std::string& file() const { return file_; }
    ManifestPosition where() const { return where_; }
    const std::string& message() const { return message_; }

  private:
    std::string file_;
    ManifestPosition where_;
    std::string message_;
};

// A value and where it was written, so later checks (the product, output clashes) can point at it.
template <typename T>
struct Placed {
    T value;
    ManifestPosition where;
};

// One pattern parameter and the values it takes, as `--param NAME=VALUE` text.
struct ParamValues {
    std::string name;
    std::vector<std::string> values;
    ManifestPosition where;
};

// One [[job]] table, validated: rule and panel files exist, formats are known.
struct JobSpec {
    ManifestPosition where;
    std::vector<Placed<std::string>> rules;   // absolute paths
    std::vector<Placed<std::string>> panels;  // absolute paths, or built-in shapes (rect:W,H)
    std::vector<Placed<std::uint64_t>> seeds;
    std::vector<ParamValues> params;
    std::vector<std::string> args;
    std::vector<Placed<std::string>> formats;
    Placed<std::string> output;
};

struct Manifest {
    std::string path;       // as given
    std::string directory;  // absolute: where relative paths in it start
    std::vector<JobSpec> jobs;
};

// Output formats a generated program writes, by extension.
const std::vector<std::string>& known_formats();

// True for the panels the program builds in (rect:W,H, circle:R, ellipse:RX,RY).
bool is_builtin_panel(const std::string& panel);

// Reads and checks the manifest; throws ManifestError.
Manifest load_manifest(const std::string& path);

// Parses manifest text (`path` names it in errors and anchors relative paths).
Manifest parse_manifest(const std::string& text, const std::string& path);

}  // namespace acanthus::batch
