// Crash handler on an alternate stack (see crash_handler.hpp).
#include "pattern/crash_handler.hpp"

#include <signal.h>

#include <cstring>

#include "pattern/running_body.hpp"

namespace acanthus::detail {

namespace {

// A stack overflow leaves no stack to run a handler on: it runs on this one.
alignas(16) char g_alternate_stack[1 << 16];
bool g_installed = false;

const char* why(int signal) {
    switch (signal) {
        case SIGSEGV:
            return "crashed: stack overflow (endless recursion?) or invalid memory access";
        case SIGBUS:
            return "crashed: invalid memory access (bus error)";
        case SIGFPE:
            return "crashed: arithmetic error (integer division by zero?)";
        case SIGABRT:
            return "aborted (std::abort, a failed assert or an uncaught error in a destructor)";
        default:
            return "crashed";
    }
}

void on_crash(int signal, siginfo_t*, void*) {
    const char* label = RunningBody::label();
    if (label) fatal_body_exit(label, why(signal));
    // Not in user code: the default action (core dump) once this handler returns.
    struct sigaction dfl {};
    dfl.sa_handler = SIG_DFL;
    sigemptyset(&dfl.sa_mask);
    sigaction(signal, &dfl, nullptr);
}

}  // namespace

void install_crash_handler() {
    if (g_installed) return;
    g_installed = true;
    stack_t stack{};
    stack.ss_sp = g_alternate_stack;
    stack.ss_size = sizeof g_alternate_stack;
    stack.ss_flags = 0;
    if (sigaltstack(&stack, nullptr) != 0) return;
    struct sigaction action {};
    action.sa_sigaction = on_crash;
    action.sa_flags = SA_SIGINFO | SA_ONSTACK | SA_NODEFER;
    sigemptyset(&action.sa_mask);
    for (int signal : {SIGSEGV, SIGBUS, SIGFPE, SIGABRT}) sigaction(signal, &action, nullptr);
}

}  // namespace acanthus::detail
