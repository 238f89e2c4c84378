// Which user code (rule body, %exhausted, %draw) is running now, readable from the watchdog
// thread and from a signal handler; and the way out when it runs away: one preformatted message
// on stderr, the cleanup hook run (temporary outputs removed), exit status 3.
#pragma once

#include <string>

namespace acanthus::detail {

// Marks a body as running for its scope. `label` ("flowers.acr:31: rule 'flower --> stem'")
// must outlive the scope; body_label() gives such strings.
class RunningBody {
  public:
    explicit RunningBody(const std::string& label) noexcept;
    ~RunningBody();
    RunningBody(const RunningBody&) = delete;
    RunningBody& operator=(const RunningBody&) = delete;

    // The running body's label, or null between bodies.
    static const char* label() noexcept;
    // Counts body entries: the same value twice means the same body is still running.
    static unsigned long sequence() noexcept;

  private:
    const char* previous_;
};

// "file:line: rule 'name'", built once per key and kept for the life of the process (the same
// form RuleFailure gives its messages). Not thread-safe: call from the thread running bodies.
const std::string& body_label(const void* key, const std::string& file, int line,
                              const std::string& name);

// The program name that starts every message ("flowers"); set once at start.
void set_program_name_for_fatal_exit(const std::string& name);

// What fatal_body_exit runs before it exits (the output stage removes its temporary files);
// async-signal-safe, set once at start.
void set_fatal_exit_cleanup(void (*cleanup)() noexcept);

// Whether a progress line is drawn on the terminal without its newline (the program stage says
// so as it draws): fatal_body_exit then starts its message on a fresh line.
void set_fatal_exit_line_open(bool open) noexcept;

// Async-signal-safe: writes "<program>: error: <label>: <why>\n" to stderr, runs the cleanup hook
// and ends the process with status 3.
[[noreturn]] void fatal_body_exit(const char* label, const char* why) noexcept;

}  // namespace acanthus::detail
