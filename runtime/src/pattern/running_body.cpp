// The running body's label and the fatal way out (see running_body.hpp).
#include "pattern/running_body.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstring>
#include <unordered_map>

namespace acanthus::detail {

namespace {

std::atomic<const char*> g_label{nullptr};
std::atomic<unsigned long> g_sequence{0};
char g_program[256] = "acanthus";
std::atomic<void (*)() noexcept> g_cleanup{nullptr};
std::atomic<bool> g_line_open{false};

void write_text(const char* text) noexcept {
    std::size_t left = std::strlen(text);
    while (left > 0) {
        const ssize_t n = ::write(STDERR_FILENO, text, left);
        if (n <= 0) return;  // nothing more we can do on the way out
        text += n;
        left -= static_cast<std::size_t>(n);
    }
}

}  // namespace

RunningBody::RunningBody(const std::string& label) noexcept
    : previous_(g_label.load(std::memory_order_relaxed)) {
    g_sequence.fetch_add(1, std::memory_order_relaxed);
    g_label.store(label.c_str(), std::memory_order_release);
}

RunningBody::~RunningBody() { g_label.store(previous_, std::memory_order_release); }

const char* RunningBody::label() noexcept { return g_label.load(std::memory_order_acquire); }

unsigned long RunningBody::sequence() noexcept {
    return g_sequence.load(std::memory_order_relaxed);
}

const std::string& body_label(const void* key, const std::string& file, int line,
                              const std::string& name) {
    struct Entry {
        std::string file, name;
        int line = 0;
        std::string label;
    };
    // Node-based, so a label's characters stay put while its body runs. A key whose object was
    // replaced by another (same address, other rule) gets its label rebuilt.
    static std::unordered_map<const void*, Entry> labels;
    Entry& e = labels[key];
    if (e.label.empty() || e.line != line || e.name != name || e.file != file) {
        e.file = file;
        e.name = name;
        e.line = line;
        e.label = file + ":" + std::to_string(line) + ": rule '" + name + "'";
    }
    return e.label;
}

void set_program_name_for_fatal_exit(const std::string& name) {
    const std::size_t n = std::min(name.size(), sizeof g_program - 1);
    std::memcpy(g_program, name.data(), n);
    g_program[n] = '\0';
}

void set_fatal_exit_cleanup(void (*cleanup)() noexcept) { g_cleanup.store(cleanup); }

void set_fatal_exit_line_open(bool open) noexcept { g_line_open.store(open); }

void fatal_body_exit(const char* label, const char* why) noexcept {
    if (g_line_open.load()) write_text("\n");
    write_text(g_program);
    write_text(": error: ");
    write_text(label ? label : "a rule body");
    write_text(": ");
    write_text(why);
    write_text("\n");
    if (auto* cleanup = g_cleanup.load()) cleanup();
    ::_exit(3);
}

}  // namespace acanthus::detail
