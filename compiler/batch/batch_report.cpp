#include "batch/batch_report.hpp"

#include <acanthus/input_file.hpp>
#include <acanthus/output_file.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <pugixml.hpp>
#include <sstream>

namespace acanthus::batch {

namespace fs = std::filesystem;
using nlohmann::json;

const char* run_status_name(RunStatus status) {
    switch (status) {
        case RunStatus::rendered:
            return "rendered";
        case RunStatus::skipped:
            return "up to date";
        case RunStatus::failed:
            return "failed";
    }
    return "?";
}

bool job_passed(const JobResult& result) {
    if (result.status == RunStatus::failed) return false;
    Verdict v = result.check.verdict;
    return v == Verdict::not_checked || v == Verdict::same || v == Verdict::updated;
}

namespace {

// Milliseconds are plenty in a report, and keep it readable.
double rounded_seconds(double seconds) { return std::round(seconds * 1000) / 1000; }

bool copy_file_atomically(const std::string& from, const std::string& to, std::string& error) {
    std::string bytes;
    if (std::string why = read_input_file(from, bytes); !why.empty()) {
        error = from + ": " + why;
        return false;
    }
    std::error_code ec;
    fs::create_directories(fs::path(to).parent_path(), ec);
    return write_file_atomically(to, bytes, error);
}

// Copies `path` into the report as <output>.<role>.<ext>; "" when there is nothing to copy.
std::string picture_in_report(const std::string& path, const std::string& report_directory,
                              const Job& job, const char* role) {
    std::error_code ec;
    if (path.empty() || !fs::is_regular_file(path, ec)) return {};
    std::string name = job.output_relative + "." + role + "." + job.format;
    std::string error;
    return copy_file_atomically(path, (fs::path(report_directory) / name).string(), error) ? name
                                                                                           : "";
}

bool passed(const json& result) { return result.value("passed", false); }

// Failures first (failed runs, then mismatches), each group in job order.
int rank(const json& result) {
    if (result.value("status", "") == "failed") return 0;
    return passed(result) ? 2 : 1;
}

std::string text_of(const pugi::xml_document& doc, unsigned flags) {
    std::ostringstream out;
    doc.save(out, "  ", flags, pugi::encoding_utf8);
    return out.str();
}

std::string junit_xml(const std::string& title, const std::vector<json>& results, double seconds) {
    pugi::xml_document doc;
    auto suites = doc.append_child("testsuites");
    auto suite = suites.append_child("testsuite");
    int failures = 0, errors = 0;
    for (const json& r : results) {
        auto testcase = suite.append_child("testcase");
        testcase.append_attribute("classname") =
            ("acanthus.batch." + r.value("rule", std::string())).c_str();
        testcase.append_attribute("name") = r.value("output", std::string()).c_str();
        testcase.append_attribute("time") = r.value("seconds", 0.0);
        if (r.value("status", "") == "failed") {
            ++errors;
            auto error = testcase.append_child("error");
            error.append_attribute("message") = "the job failed";
            error.text() = r.value("message", std::string()).c_str();
        } else if (!passed(r)) {
            ++failures;
            auto failure = testcase.append_child("failure");
            failure.append_attribute("message") = r.value("verdict", std::string()).c_str();
            std::string text = r.value("check_message", std::string());
            if (!r.value("diff", std::string()).empty())
                text += "\ndiff picture: " + r.value("diff", std::string());
            failure.text() = text.c_str();
        } else {
            testcase.append_child("system-out").text() =
                (r.value("status", std::string()) + ", " + r.value("verdict", std::string()))
                    .c_str();
        }
    }
    for (auto node : {suites, suite}) {
        node.append_attribute("name") = title.c_str();
        node.append_attribute("tests") = static_cast<unsigned long long>(results.size());
        node.append_attribute("failures") = failures;
        node.append_attribute("errors") = errors;
        node.append_attribute("time") = rounded_seconds(seconds);
    }
    auto declaration = doc.prepend_child(pugi::node_declaration);
    declaration.append_attribute("version") = "1.0";
    declaration.append_attribute("encoding") = "UTF-8";
    return text_of(doc, pugi::format_default);
}

void add_text(pugi::xml_node parent, const char* tag, const std::string& text) {
    parent.append_child(tag).text() = text.c_str();
}

void add_picture(pugi::xml_node row, const std::string& name, const char* missing) {
    auto cell = row.append_child("td");
    if (name.empty()) {
        cell.text() = missing;
        return;
    }
    auto link = cell.append_child("a");
    link.append_attribute("href") = name.c_str();
    auto img = link.append_child("img");
    img.append_attribute("src") = name.c_str();
    img.append_attribute("alt") = name.c_str();
}

std::string html_report(const std::string& title, const std::vector<json>& results,
                        double seconds) {
    std::size_t failed = 0, differ = 0;
    for (const json& r : results) {
        if (rank(r) == 0) ++failed;
        if (rank(r) == 1) ++differ;
    }
    pugi::xml_document doc;
    auto html = doc.append_child("html");
    html.append_attribute("lang") = "en";
    auto head = html.append_child("head");
    head.append_child("meta").append_attribute("charset") = "utf-8";
    add_text(head, "title", title);
    add_text(head, "style",
             "body{font-family:sans-serif;margin:1em}table{border-collapse:collapse}"
             "td,th{border:1px solid #ccc;padding:4px;vertical-align:top}"
             "img{max-width:300px;max-height:300px;background:#fff}"
             "tr.failed{background:#fdd}tr.differs{background:#ffe8c0}pre{white-space:pre-wrap;"
             "max-width:40em;margin:0}");
    auto body = html.append_child("body");
    add_text(body, "h1", title);
    std::ostringstream summary;
    summary << results.size() << " jobs: " << results.size() - failed - differ << " passed, "
            << differ << " differ, " << failed << " failed (" << rounded_seconds(seconds) << " s)";
    auto p = body.append_child("p");
    p.append_attribute("id") = "summary";
    p.text() = summary.str().c_str();
    auto table = body.append_child("table");
    auto header = table.append_child("tr");
    for (const char* name : {"output", "result", "reference", "new", "diff"})
        add_text(header, "th", name);
    for (const json& r : results) {
        auto row = table.append_child("tr");
        int group = rank(r);
        row.append_attribute("class") = group == 0 ? "failed" : group == 1 ? "differs" : "passed";
        auto name = row.append_child("td");
        add_text(name, "code", r.value("output", std::string()));
        auto result = row.append_child("td");
        std::string verdict = r.value("status", std::string());
        if (r.value("verdict", std::string()) != "not checked")
            verdict += ", " + r.value("verdict", std::string());
        add_text(result, "strong", verdict);
        std::string message =
            r.value("message", std::string()) + r.value("check_message", std::string());
        if (!message.empty()) add_text(result, "pre", message);
        if (group == 2) {
            for (int i = 0; i < 3; ++i) row.append_child("td").text() = "";
            continue;
        }
        add_picture(row, r.value("reference_picture", std::string()), "none");
        add_picture(row, r.value("new_picture", std::string()), "none");
        add_picture(row, r.value("diff", std::string()), "none");
    }
    return "<!DOCTYPE html>\n" + text_of(doc, pugi::format_indent | pugi::format_no_declaration |
                                                  pugi::format_no_empty_element_tags);
}

}  // namespace

json result_json(const JobResult& result, const std::string& report_directory) {
    const Job& job = result.job;
    json params = json::object();
    for (const auto& [name, value] : job.params) params[name] = value;
    json out{{"index", job.index},
             {"rule", job.rule_name},
             {"rule_file", job.rule},
             {"panel", job.panel},
             {"seed", job.seed},
             {"params", params},
             {"format", job.format},
             {"output", job.output_relative},
             {"status", run_status_name(result.status)},
             {"message", result.message},
             {"seconds", rounded_seconds(result.seconds)},
             {"verdict", verdict_name(result.check.verdict)},
             {"check_message", result.check.message},
             {"passed", job_passed(result)}};
    if (!job_passed(result) && result.status != RunStatus::failed) {
        out["new_picture"] = picture_in_report(job.output, report_directory, job, "new");
        out["reference_picture"] =
            picture_in_report(result.check.reference, report_directory, job, "reference");
        std::error_code ec;
        out["diff"] = result.check.diff_picture.empty()
                          ? std::string()
                          : fs::relative(result.check.diff_picture, report_directory, ec).string();
    }
    return out;
}

bool write_report_files(const std::string& directory, const std::string& title,
                        std::vector<json> results, double seconds, std::string& error) {
    std::stable_sort(results.begin(), results.end(), [](const json& a, const json& b) {
        return a.value("index", 0) < b.value("index", 0);
    });
    std::error_code ec;
    fs::create_directories(directory, ec);
    if (ec) {
        error = "cannot create the report directory '" + directory + "': " + ec.message();
        return false;
    }
    json report{{"title", title}, {"seconds", rounded_seconds(seconds)}, {"results", results}};
    fs::path dir(directory);
    if (!write_file_atomically((dir / "report.json").string(), report.dump(1) + "\n", error) ||
        !write_file_atomically((dir / "junit.xml").string(), junit_xml(title, results, seconds),
                               error))
        return false;
    std::stable_sort(results.begin(), results.end(),
                     [](const json& a, const json& b) { return rank(a) < rank(b); });
    return write_file_atomically((dir / "index.html").string(),
                                 html_report(title, results, seconds), error);
}

bool merge_reports(const std::string& output_directory, const std::vector<std::string>& inputs,
                   std::string& error) {
    std::vector<json> results;
    std::string title;
    double seconds = 0;
    for (const std::string& input : inputs) {
        std::string text;
        fs::path path = fs::path(input) / "report.json";
        if (std::string why = read_input_file(path.string(), text); !why.empty()) {
            error = path.string() + ": " + why;
            return false;
        }
        json report = json::parse(text, nullptr, false);
        if (!report.is_object() || !report.contains("results") || !report["results"].is_array()) {
            error = path.string() + ": not a batch report";
            return false;
        }
        if (title.empty()) title = report.value("title", std::string());
        seconds = std::max(seconds, report.value("seconds", 0.0));  // shards run side by side
        for (json& result : report["results"]) {
            if (!result.is_object()) continue;
            for (const char* key : {"new_picture", "reference_picture", "diff"}) {
                std::string name = result.value(key, std::string());
                if (name.empty()) continue;
                if (!copy_file_atomically((fs::path(input) / name).string(),
                                          (fs::path(output_directory) / name).string(), error))
                    return false;
            }
            results.push_back(std::move(result));
        }
    }
    return write_report_files(output_directory, title, std::move(results), seconds, error);
}

}  // namespace acanthus::batch
