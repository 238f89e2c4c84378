#include "server/routes.hpp"

#include <httplib.h>

#include <acanthus/int_pair.hpp>
#include <acanthus/output_file.hpp>
#include <algorithm>
#include <cmath>
#include <deque>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <nlohmann/json.hpp>
#include <sstream>

#include "server/child.hpp"
#include "server/diagnostics.hpp"
#include "server/guides.hpp"
#include "server/limits.hpp"
#include "server/render_job.hpp"
#include "server/status.hpp"

namespace acanthus {

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

std::string read_file(const fs::path& path, bool& ok) {
    std::ifstream in(path, std::ios::binary);
    ok = static_cast<bool>(in);
    std::ostringstream s;
    if (ok) s << in.rdbuf();
    return s.str();
}

void send_file(httplib::Response& res, const fs::path& path, const char* type) {
    bool ok = false;
    std::string body = read_file(path, ok);
    if (!ok) {
        res.status = 404;
        res.set_content("not found\n", "text/plain");
        return;
    }
    res.set_content(body, type);
}

// Writes `text` to a new temporary file beside `path` (mkstemp: never an existing name, so
// never through a link planted there), then renames it over `path` (a link of that name is
// replaced, not followed).
bool write_whole_file(const fs::path& path, const std::string& text) {
    std::string error;
    return write_file_atomically(path.string(), text, error);
}

// Responses go out as they are: the library compresses a text body with Brotli (at its slowest
// quality: 0.07 s to 9 s for a render) or gzip whenever the browser accepts it, and on loopback
// sending the bytes takes less time than compressing them (docs/preview.md#speed). A body sent
// by a content provider of known length is never compressed.
void send_uncompressed(httplib::Response& res) {
    if (res.body.empty()) return;
    auto body = std::make_shared<const std::string>(std::move(res.body));
    res.body.clear();
    const std::string type = res.get_header_value("Content-Type");
    res.headers.erase("Content-Type");  // set_content_provider adds it again
    res.set_content_provider(
        body->size(), type,
        [body](std::size_t offset, std::size_t length, httplib::DataSink& sink) {
            return sink.write(body->data() + offset, length);
        });
}

httplib::Server::Handler uncompressed(httplib::Server::Handler handler) {
    return [handler = std::move(handler)](const httplib::Request& req, httplib::Response& res) {
        handler(req, res);
        send_uncompressed(res);
    };
}

void bad_request(httplib::Response& res, const std::string& message) {
    res.status = 400;
    res.set_content(json{{"error", message}}.dump(), "application/json");
}

bool parse_json(const httplib::Request& req, httplib::Response& res, json& out) {
    try {
        out = json::parse(req.body);
        if (!out.is_object()) throw std::runtime_error("not an object");
        return true;
    } catch (const std::exception&) {
        bad_request(res, "the body must be a JSON object");
        return false;
    }
}

void send_picture(httplib::Response& res, std::string png, const char* missing) {
    if (png.empty()) {
        res.status = 404;
        res.set_content(missing, "text/plain");
        return;
    }
    res.set_header("Cache-Control", "no-store");
    res.set_content(std::move(png), "image/png");
}

// A file the server wrote last, read and replaced by the request threads.
class LatestFile {
  public:
    std::string get() const {
        std::lock_guard lock(mutex_);
        return path_;
    }
    void set(const std::string& path) {
        std::lock_guard lock(mutex_);
        path_ = path;
    }

  private:
    mutable std::mutex mutex_;
    std::string path_;
};

LatestFile latest_upload;  // the latest panel dropped onto the page

// Panels dropped onto the page: the latest two are kept (the last good render, which downloads
// run again, may still use the one before), older ones are removed, not left to pile up until
// the server stops.
class UploadedPanels {
  public:
    void add(const std::string& path) {
        std::lock_guard lock(mutex_);
        kept_.push_back(path);
        while (kept_.size() > 2) {
            std::error_code ec;
            fs::remove(kept_.front(), ec);
            kept_.pop_front();
        }
    }

  private:
    std::mutex mutex_;
    std::deque<std::string> kept_;
};
UploadedPanels uploaded_panels;
LatestFile latest_guides;  // the guides file written last

// The Host header's name (no port, no brackets) is an IP address, localhost or `listen_host`.
bool served_host(const std::string& host_header, const std::string& listen_host) {
    std::string name = host_header;
    if (!name.empty() && name.front() == '[') {
        const std::size_t close = name.find(']');
        if (close == std::string::npos) return false;
        name = name.substr(1, close - 1);
        return !name.empty() && name.find_first_not_of("0123456789abcdefABCDEF:.") ==
                                    std::string::npos;  // an IPv6 literal
    }
    const std::size_t colon = name.rfind(':');
    if (colon != std::string::npos) name.resize(colon);
    if (name.empty()) return false;
    if (name == "localhost" || name == listen_host) return true;
    return name.find_first_not_of("0123456789.") == std::string::npos;  // an IPv4 literal
}

bool finite_number(const json& v) { return v.is_number() && std::isfinite(v.get<double>()); }

std::string coordinate(double v) {
    std::ostringstream s;
    s.precision(10);
    s << v;
    return s.str();
}

// POST /settings: {"params": {...}, "rng_seed": "7", "panel": "heart.svg", "seeds": [[x, y]]}.
// Each field is optional; what is given replaces the current setting.
// A parameter value from the page that names a file (it has a '/' or names one that exists)
// must lie, links resolved, in the rule file's folder, the examples or the server's own folder:
// the page cannot have the program read any file the server's user can.
bool inside(const fs::path& file, const fs::path& dir) {
    std::error_code ec;
    const fs::path d = fs::weakly_canonical(fs::absolute(dir, ec), ec);
    if (ec || d.empty()) return false;
    auto f = file.begin();
    for (auto it = d.begin(); it != d.end(); ++it, ++f)
        if (f == file.end() || *f != *it) return false;
    return true;
}

bool allowed_path_value(const PreviewSite& site, const std::string& value) {
    std::error_code ec;
    const bool names_file = value.find('/') != std::string::npos || fs::exists(value, ec);
    if (!names_file) return true;
    const fs::path file = fs::weakly_canonical(fs::absolute(value, ec), ec);
    if (ec) return false;
    const fs::path rules_dir = fs::absolute(site.file, ec).parent_path();
    return inside(file, rules_dir) || inside(file, fs::path(site.panels_dir).parent_path()) ||
           inside(file, site.work_dir);
}

bool apply_settings(PreviewSite& site, const json& body, PreviewSettings& s, std::string& error) {
    if (body.contains("params")) {
        if (!body["params"].is_object()) return error = "params must be an object", false;
        for (const auto& [name, value] : body["params"].items()) {
            if (name.empty() || name.find('=') != std::string::npos)
                return error = "bad parameter name", false;
            if (value.is_null())
                s.params.erase(name);
            else if (value.is_string() && !allowed_path_value(site, value.get<std::string>()))
                return error = "parameter '" + name +
                               "' names a file outside the rule file's folder and the examples",
                       false;
            else if (value.is_string())
                s.params[name] = value.get<std::string>();
            else if (value.is_boolean())
                s.params[name] = value.get<bool>() ? "true" : "false";
            else if (finite_number(value))
                s.params[name] = value.dump();
            else
                return error = "bad value for parameter '" + name + "'", false;
        }
    }
    if (body.contains("rng_seed")) {
        const json& v = body["rng_seed"];
        std::string seed = v.is_string()            ? v.get<std::string>()
                           : v.is_number_unsigned() ? std::to_string(v.get<unsigned long long>())
                                                    : "x";
        if (seed.size() > 20 || seed.find_first_not_of("0123456789") != std::string::npos)
            return error = "rng_seed must be a decimal integer", false;
        s.rng_seed = seed;
    }
    if (body.contains("panel")) {
        if (!body["panel"].is_string()) return error = "panel must be a name", false;
        const std::string panel = body["panel"];
        if (panel.empty()) {
            s.region.clear();
        } else if (panel == "uploaded") {
            const std::string up = latest_upload.get();
            if (up.empty()) return error = "no panel was uploaded", false;
            s.region = up;
        } else if (std::find(site.panels.begin(), site.panels.end(), panel) != site.panels.end()) {
            s.region = (fs::path(site.panels_dir) / panel).string();
        } else {
            return error = "unknown panel '" + panel + "'", false;
        }
    }
    if (body.contains("seeds")) {
        const json& seeds = body["seeds"];
        if (!seeds.is_array() || seeds.size() > 100)
            return error = "seeds must be a list of at most 100 [x, y] pairs", false;
        s.seeds.clear();
        for (const json& p : seeds) {
            if (!p.is_array() || p.size() != 2 || !finite_number(p[0]) || !finite_number(p[1]))
                return error = "each seed is [x, y]", false;
            s.seeds.push_back(coordinate(p[0]) + "," + coordinate(p[1]));
        }
    }
    return true;
}

void settings_json(const PreviewSettings& s, const PreviewSite& site, json& out) {
    out["params"] = s.params;
    out["rng_seed"] = s.rng_seed;
    std::string panel;
    if (!s.region.empty()) {
        fs::path r(s.region);
        if (r.parent_path() == fs::path(site.panels_dir))
            panel = r.filename().string();
        else if (r.parent_path() == fs::path(site.work_dir))
            panel = "uploaded";
        else
            panel = s.region;
    }
    out["panel"] = panel;
    out["seeds"] = s.seeds;
    out["time_limit"] = s.time_limit;
}

RunSlots request_runs(kRequestRunsAtOnce, kRequestRunsQueued);
std::atomic<int> open_streams{0};

// Calls `run` (which runs the program) in one of the few slots for requests' programs, or
// answers 503 when as many already run and wait: twenty downloads at once started twenty
// programs before, on two cores beside the live render.
template <class Run>
void in_run_slot(httplib::Response& res, Run&& run) {
    if (request_runs.take(std::chrono::seconds(60)) != RunSlots::Outcome::taken) {
        res.status = 503;
        res.set_header("Retry-After", "2");
        res.set_content("busy: other downloads or frames are being made; try again\n",
                        "text/plain");
        return;
    }
    struct GiveBack {
        ~GiveBack() { request_runs.give_back(); }
    } give_back;
    run();
}

// Requests that change the preview or run its program are taken only from the page itself.
// A browser names the requesting page in Origin (fetch, forms) and says on every request,
// an <img> of another site's page included, whether it comes from the same origin
// (Sec-Fetch-Site; "none" is an address typed or a bookmark). Scripts send neither.
bool changes_or_runs(const httplib::Request& req) {
    return req.method == "POST" || (req.path == "/status.json" && req.has_param("view")) ||
           req.path == "/render.png" || req.path == "/render.pdf" ||
           req.path == "/debug-frame.png" || req.path == "/variation.png";
}

bool from_the_page(const httplib::Request& req) {
    if (req.has_header("Origin") &&
        req.get_header_value("Origin") != "http://" + req.get_header_value("Host"))
        return false;
    const std::string site = req.get_header_value("Sec-Fetch-Site");
    return site.empty() || site == "same-origin" || site == "none";
}

// A program output made on request (a download, a debug frame) in the server's directory.
void send_rerun(PreviewSite& site, httplib::Response& res, const std::vector<std::string>& extra,
                const fs::path& file, const char* type, const std::string& download,
                const std::string& rng_seed = {}) {
    ExtraRun run;
    bool ran = false;
    in_run_slot(res, [&] {
        run = site.job.run_again(extra, 120, rng_seed);
        ran = true;
    });
    if (!ran) return;
    if (!run.ok) {
        res.status = 409;
        res.set_content(run.message + "\n", "text/plain");
        return;
    }
    send_file(res, file, type);
    if (!download.empty())
        res.set_header("Content-Disposition", "attachment; filename=\"" + download + "\"");
    std::error_code ec;
    fs::remove(file, ec);
}

}  // namespace

void add_routes(httplib::Server& server, PreviewSite& site) {
    const auto get = [&server](const std::string& pattern, httplib::Server::Handler handler) {
        server.Get(pattern, uncompressed(std::move(handler)));
    };
    const auto post = [&server](const std::string& pattern, httplib::Server::Handler handler) {
        server.Post(pattern, uncompressed(std::move(handler)));
    };
    static const std::pair<const char*, const char*> assets[] = {
        {"/", "text/html; charset=utf-8"},
        {"/preview.js", "text/javascript; charset=utf-8"},
        {"/preview.css", "text/css; charset=utf-8"}};
    for (const auto& [path, type] : assets) {
        const std::string file = std::string(path) == "/" ? "index.html" : path + 1;
        const std::string mime = type;
        get(path, [&site, file, mime](const httplib::Request&, httplib::Response& res) {
            send_file(res, fs::path(site.assets_dir) / file, mime.c_str());
            res.set_header("Cache-Control", "no-store");
        });
    }

    // ?view=WxH: the picture's room on the page in device pixels (from the page only).
    get("/status.json", [&site](const httplib::Request& req, httplib::Response& res) {
        if (req.has_param("view")) {
            const auto size = read_view_size(req.get_param_value("view"));
            if (!size) {
                bad_request(res, "view must be WxH, " + std::to_string(view_size_min) + " to " +
                                     std::to_string(view_size_max) + " pixels each");
                return;
            }
            site.job.set_view_size(size->first, size->second);
        }
        json status = site.status.to_json();
        settings_json(site.job.settings(), site, status["settings"]);
        status["file"] = site.file;
        status["event_streams"] = open_streams.load();  // how many /events are open now
        res.set_header("Cache-Control", "no-store");
        res.set_content(status.dump(), "application/json");
    });

    get("/render.svg", [&site](const httplib::Request&, httplib::Response& res) {
        std::string svg = site.status.svg();
        if (svg.empty()) {
            res.status = 404;
            res.set_content("no good render yet\n", "text/plain");
            return;
        }
        res.set_header("Cache-Control", "no-store");
        res.set_content(svg, "image/svg+xml");
    });

    // An earlier good render, for the page to show beside the current one (the page shows
    // its PNG: parsing each revision's SVG took the browser as long as the live picture's).
    for (const bool png : {false, true}) {
        get(png ? "/revision.png" : "/revision.svg",
            [&site, png](const httplib::Request& req, httplib::Response& res) {
                const std::string n = req.get_param_value("n");
                std::string picture;
                if (!n.empty() && n.size() < 10 &&
                    n.find_first_not_of("0123456789") == std::string::npos)
                    picture = png ? site.status.revision_png(std::stol(n))
                                  : site.status.revision_svg(std::stol(n));
                if (picture.empty()) {
                    res.status = 404;
                    res.set_content("no such revision kept\n", "text/plain");
                    return;
                }
                res.set_header("Cache-Control", "no-store");
                res.set_content(picture, png ? "image/png" : "image/svg+xml");
            });
    }

    // The latest good render at the page's size: what the page shows.
    get("/view.png", [&site](const httplib::Request&, httplib::Response& res) {
        send_picture(res, site.status.view_png(), "no good render yet\n");
    });

    // The growth so far, while a render grows (the program's --partial); 404 otherwise.
    get("/partial.png", [&site](const httplib::Request&, httplib::Response& res) {
        send_picture(res, site.status.partial_png(), "no partial picture now\n");
    });

    for (const char* ext : {"pdf", "png"}) {
        const std::string e = ext;
        get("/render." + e, [&site, e](const httplib::Request&, httplib::Response& res) {
            static std::atomic<long> n{0};
            const fs::path file =
                fs::path(site.work_dir) / ("download-" + std::to_string(++n) + "." + e);
            send_rerun(site, res, {"-o", file.string(), "--quiet"}, file,
                       e == "pdf" ? "application/pdf" : "image/png", site.stem + "." + e);
        });
    }

    get("/debug-frame.png", [&site](const httplib::Request& req, httplib::Response& res) {
        const std::string it = req.get_param_value("iteration");
        if (it.empty() || it.size() > 9 ||
            it.find_first_not_of("0123456789") != std::string::npos || std::stol(it) < 1) {
            bad_request(res, "iteration must be a positive integer");
            return;
        }
        static std::atomic<long> n{0};
        const std::string tag = std::to_string(++n);
        const fs::path file = fs::path(site.work_dir) / ("debug-" + tag + ".png");
        const fs::path svg = fs::path(site.work_dir) / ("debug-" + tag + ".svg");
        send_rerun(site, res,
                   {"--debug-frame", it, file.string(), "--max-iterations", it, "-o", svg.string(),
                    "--quiet"},
                   file, "image/png", "");
        std::error_code ec;
        fs::remove(svg, ec);
    });

    // The variations sheet: the render with another rng seed, small.
    get("/variation.png", [&site](const httplib::Request& req, httplib::Response& res) {
        const std::string rng = req.get_param_value("rng");
        if (rng.empty() || rng.size() > 19 ||
            rng.find_first_not_of("0123456789") != std::string::npos)
            return bad_request(res, "rng must be a decimal number");
        static std::atomic<long> n{0};
        const std::string tag = std::to_string(++n);
        const fs::path file = fs::path(site.work_dir) / ("variation-" + tag + ".png");
        send_rerun(site, res, {"-o", file.string(), "--width", "240", "--quiet"}, file, "image/png",
                   "", rng);
        res.set_header("Cache-Control", "no-store");
    });

    // Frames of the growth: POST /frames {"every": K} makes them, GET /frames/N.png serves them.
    static std::mutex frames_mutex;
    post("/frames", [&site](const httplib::Request& req, httplib::Response& res) {
        json body;
        if (!parse_json(req, res, body)) return;
        long every = body.value("every", 1L);
        if (every < 1 || every > 1000000) return bad_request(res, "every must be 1 or more");
        std::lock_guard lock(frames_mutex);
        const fs::path dir = fs::path(site.work_dir) / "frames";
        const fs::path last = fs::path(site.work_dir) / "frames-final.svg";
        std::error_code ec;
        ExtraRun run;
        bool ran = false;
        in_run_slot(res, [&] {
            fs::remove_all(dir, ec);
            run = site.job.run_again({"--frames", dir.string(), "--every", std::to_string(every),
                                      "-o", last.string(), "--quiet"},
                                     300);
            ran = true;
        });
        if (!ran) return;
        fs::remove(last, ec);
        if (!run.ok) {
            res.status = 409;
            res.set_content(json{{"error", run.message}}.dump(), "application/json");
            return;
        }
        long count = 0;
        for (const auto& entry : fs::directory_iterator(dir, ec)) count += entry.is_regular_file();
        res.set_content(json{{"count", count}}.dump(), "application/json");
    });
    get(R"(/frames/(\d{1,6})\.png)", [&site](const httplib::Request& req, httplib::Response& res) {
        char name[32];
        std::snprintf(name, sizeof name, "frame-%06ld.png", std::stol(req.matches[1].str()));
        std::lock_guard lock(frames_mutex);
        send_file(res, fs::path(site.work_dir) / "frames" / name, "image/png");
    });

    get("/panels.json", [&site](const httplib::Request&, httplib::Response& res) {
        res.set_content(json(site.panels).dump(), "application/json");
    });
    get(R"(/panels/([A-Za-z0-9_.-]{1,64}))",
        [&site](const httplib::Request& req, httplib::Response& res) {
            const std::string name = req.matches[1];
            if (std::find(site.panels.begin(), site.panels.end(), name) == site.panels.end()) {
                res.status = 404;
                res.set_content("not found\n", "text/plain");
                return;
            }
            send_file(res, fs::path(site.panels_dir) / name, "image/svg+xml");
        });

    // file:line in the page opens the user's editor there (--editor or $VISUAL); only the rule
    // file and the files it imports can be named.
    post("/open", [&site](const httplib::Request& req, httplib::Response& res) {
        json body;
        if (!parse_json(req, res, body)) return;
        const std::string file = body.value("file", std::string());
        const long line = body.value("line", 1L), column = body.value("column", 1L);
        if (line < 1 || line > 100000000 || column < 0 || column > 100000000)
            return bad_request(res, "line and column must be positive numbers");
        bool known = false;
        for (const std::string& f : site.job.source_files())
            known = known || (!file.empty() && same_file_key(f) == same_file_key(file));
        if (!known) {
            res.status = 403;
            res.set_content(json{{"error", "only the rule file and its imports open"}}.dump(),
                            "application/json");
            return;
        }
        if (site.editor.empty()) {
            res.status = 409;
            res.set_content(json{{"error",
                                  "no editor: start the preview with --editor "
                                  "'code -g {file}:{line}:{column}' or set $VISUAL"}}
                                .dump(),
                            "application/json");
            return;
        }
        const std::vector<std::string> argv = editor_command(
            site.editor, same_file_key(file), static_cast<int>(line), static_cast<int>(column));
        std::string error;
        if (!spawn_detached(argv, error)) {
            res.status = 500;
            res.set_content(json{{"error", error}}.dump(), "application/json");
            return;
        }
        res.set_content(json{{"opened", argv}}.dump(), "application/json");
    });

    post("/settings", [&site](const httplib::Request& req, httplib::Response& res) {
        json body;
        if (!parse_json(req, res, body)) return;
        PreviewSettings s = site.job.settings();
        std::string error;
        if (!apply_settings(site, body, s, error)) return bad_request(res, error);
        site.job.set_settings(s);
        json out;
        settings_json(s, site, out);
        res.set_content(out.dump(), "application/json");
    });

    // A panel dropped onto the page: saved in the server's own directory, used from now on.
    post("/panel", [&site](const httplib::Request& req, httplib::Response& res) {
        if (req.body.size() > kMaxRequestBody) {
            res.status = 413;
            return;
        }
        if (req.body.find("<svg") == std::string::npos)
            return bad_request(res, "the panel must be an SVG file");
        // A new name for each upload: a render knows its panel by its path.
        static std::atomic<long> uploads{0};
        const fs::path file =
            fs::path(site.work_dir) / ("uploaded-" + std::to_string(++uploads) + ".svg");
        if (!write_whole_file(file, req.body)) {
            res.status = 500;
            res.set_content(json{{"error", "cannot write " + file.string()}}.dump(),
                            "application/json");
            return;
        }
        uploaded_panels.add(file.string());
        latest_upload.set(file.string());
        PreviewSettings s = site.job.settings();
        s.region = file.string();
        s.seeds.clear();
        site.job.set_settings(s);
        res.set_content(json{{"panel", "uploaded"}}.dump(), "application/json");
    });

    // Strokes drawn with a library's stroke tools, saved as the SVG its file parameter names.
    post("/guides", [&site](const httplib::Request& req, httplib::Response& res) {
        json body;
        if (!parse_json(req, res, body)) return;
        const std::vector<StrokeTool> tools = site.status.stroke_tools();
        const std::string library = body.contains("library") && body["library"].is_string()
                                        ? body["library"].get<std::string>()
                                        : "";
        const auto tool = std::find_if(tools.begin(), tools.end(), [&](const StrokeTool& t) {
            return library.empty() || t.library == library;
        });
        if (tool == tools.end()) {
            res.status = 409;
            res.set_content(
                json{{"error", library.empty()
                                   ? "the program uses no library with stroke tools"
                                   : "the program does not use " + library + "'s stroke tools"}}
                    .dump(),
                "application/json");
            return;
        }
        std::string svg, error;
        std::vector<std::string> kinds_drawn;
        if (!guides_svg(body, *tool, svg, kinds_drawn, error)) return bad_request(res, error);
        // Beside the rule file, so that the command the page shows still works after the
        // preview stops; in the server's own folder when that one cannot be written.
        fs::path file = site.guides_file;
        PreviewSettings s = site.job.settings();
        if (svg.empty()) {
            s.params.erase(tool->file_param);
        } else {
            if (!write_whole_file(file, svg)) file = fs::path(site.work_dir) / "guides.svg";
            if (!write_whole_file(file, svg)) {
                res.status = 500;
                res.set_content(json{{"error", "cannot write " + file.string()}}.dump(),
                                "application/json");
                return;
            }
            s.params[tool->file_param] = file.string();
            latest_guides.set(file.string());
        }
        // The mode goes with the strokes: without one of its strokes ("Clear strokes") the
        // rule file's own default again, not a flow without guides.
        if (!tool->mode_param.empty()) {
            const std::string mode = tool->mode_for(kinds_drawn);
            if (mode.empty())
                s.params.erase(tool->mode_param);
            else
                s.params[tool->mode_param] = mode;
        }
        site.job.set_settings(s);
        res.set_content(json{{"guides", svg.empty() ? "" : file.string()}}.dump(),
                        "application/json");
    });
    get("/guides.svg", [&site](const httplib::Request&, httplib::Response& res) {
        // Only the file this server wrote, whatever the settings name.
        const std::string written = latest_guides.get();
        if (written.empty()) {
            res.status = 404;
            return;
        }
        send_file(res, written, "image/svg+xml");
        res.set_header("Content-Disposition", "attachment; filename=\"guides.svg\"");
    });

    // Server-sent events: the status, each time it changes (and every 15 s to keep it open).
    get("/events", [&site](const httplib::Request&, httplib::Response& res) {
        if (open_streams.fetch_add(1) >= kMaxEventStreams) {
            --open_streams;
            res.status = 503;
            res.set_content("too many pages open on this preview\n", "text/plain");
            return;
        }
        res.set_header("Cache-Control", "no-store");
        auto seen = std::make_shared<long>(-1);
        res.set_chunked_content_provider(
            "text/event-stream",
            [&site, seen](std::size_t, httplib::DataSink& sink) {
                if (*seen >= 0) {
                    long now = *seen;
                    for (int i = 0; i < 15 && now == *seen && !site.stopping; ++i)
                        now = site.status.wait_for_change(*seen, 1000);
                }
                if (site.stopping) return false;
                json status = site.status.to_json();
                *seen = status["version"].get<long>();
                settings_json(site.job.settings(), site, status["settings"]);
                status["file"] = site.file;
                const std::string event = "data: " + status.dump() + "\n\n";
                return sink.write(event.data(), event.size());
            },
            [](bool) { --open_streams; });
    });

    // Another web site open in the same browser must not read or drive the preview. A site
    // that rebinds its own name to 127.0.0.1 sends that name as Host: only an address,
    // localhost or the --host name is served. A POST, or a GET that runs the program, is
    // accepted only from the page itself (from_the_page), whatever address the server listens on.
    server.set_pre_routing_handler([&site](const httplib::Request& req, httplib::Response& res) {
        if (!served_host(req.get_header_value("Host"), site.listen_host)) {
            res.status = 403;
            res.set_content("requests must name the server by its address\n", "text/plain");
            return httplib::Server::HandlerResponse::Handled;
        }
        if (!changes_or_runs(req) || from_the_page(req))
            return httplib::Server::HandlerResponse::Unhandled;
        res.status = 403;
        res.set_content("cross-origin request refused\n", "text/plain");
        return httplib::Server::HandlerResponse::Handled;
    });

    // On every answer: the page runs only its own script and style, loads pictures only from
    // here (and the blob: URLs it makes of them), cannot be framed by another page (a click
    // there would draw strokes here), and no answer is read as another type than it says.
    server.set_default_headers({
        {"Content-Security-Policy",
         "default-src 'none'; script-src 'self'; style-src 'self'; img-src 'self' blob: data:; "
         "connect-src 'self'; base-uri 'none'; form-action 'none'; frame-ancestors 'none'"},
        {"X-Content-Type-Options", "nosniff"},
        {"X-Frame-Options", "DENY"},
        {"Referrer-Policy", "no-referrer"},
    });

    // Also the answers of the pre-routing handler and the library's own errors (>= 400).
    server.set_error_handler([](const httplib::Request&, httplib::Response& res) {
        if (res.body.empty() && !res.has_header("Content-Type")) {
            res.set_content(res.status == 404   ? "not found\n"
                            : res.status == 413 ? "request body too large\n"
                                                : "error\n",
                            "text/plain");
        }
        send_uncompressed(res);
    });
}

}  // namespace acanthus
