// The run's output files, renamed together at the end (see output_transaction.hpp).
#include "output/transaction.hpp"

#include <unistd.h>

#include <acanthus/error.hpp>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <stdexcept>
#include <vector>

namespace acanthus::detail {

namespace {

std::atomic<OutputTransaction*> g_active{nullptr};
thread_local int t_bypass = 0;

void remove_entry_files(const char* path, bool directory) noexcept {
    if (!path) return;
    if (directory)
        ::rmdir(path);
    else
        ::unlink(path);
}

}  // namespace

OutputTransaction::OutputTransaction() {
    OutputTransaction* expected = nullptr;
    if (!g_active.compare_exchange_strong(expected, this))
        throw std::logic_error("an output transaction is already open");
}

OutputTransaction::~OutputTransaction() {
    g_active.store(nullptr);
    for (Entry* e = head_.load(); e; e = e->next)
        remove_entry_files(e->temporary, e->target.empty());
    clear();
}

OutputTransaction* OutputTransaction::active() { return t_bypass > 0 ? nullptr : g_active.load(); }

OutputTransaction::Bypass::Bypass() { ++t_bypass; }
OutputTransaction::Bypass::~Bypass() { --t_bypass; }

void OutputTransaction::add_file(const std::string& temporary, const std::string& target) {
    if (target.empty()) throw std::logic_error("OutputTransaction::add_file: no target");
    Entry* e = new Entry;
    e->temporary = ::strdup(temporary.c_str());
    e->target = target;
    e->next = head_.load();
    head_.store(e);
}

void OutputTransaction::add_created_directory(const std::string& path) {
    Entry* e = new Entry;
    e->temporary = ::strdup(path.c_str());
    e->next = head_.load();
    head_.store(e);
}

void OutputTransaction::publish(const std::string& target) {
    for (Entry* e = head_.load(); e; e = e->next) {
        if (e->target != target || e->renamed || !e->temporary) continue;
        // The entry names the target from now on: removed if the run fails, as the temporary
        // was. (The old name is freed only by clear(): a signal handler may be reading it.)
        char* published = ::strdup(target.c_str());
        if (!published) throw std::bad_alloc();
        if (std::rename(e->temporary, target.c_str()) != 0) {
            const int error = errno;
            std::free(published);
            throw InputError("cannot write '" + target + "': " + std::strerror(error));
        }
        e->renamed = e->temporary;
        e->temporary = published;
        return;
    }
    throw std::logic_error("OutputTransaction::publish: no file for '" + target + "'");
}

void OutputTransaction::commit() {
    std::vector<Entry*> files;  // oldest first
    for (Entry* e = head_.load(); e; e = e->next)
        if (!e->target.empty() && !e->renamed) files.insert(files.begin(), e);
    for (Entry* e : files) {
        if (std::rename(e->temporary, e->target.c_str()) != 0) {
            const int error = errno;
            throw InputError("cannot write '" + e->target + "': " + std::strerror(error));
        }
        std::free(e->temporary);
        e->temporary = nullptr;  // renamed: nothing to remove any more
    }
    // Created directories now hold the outputs: keep them.
    for (Entry* e = head_.load(); e; e = e->next) {
        std::free(e->temporary);
        e->temporary = nullptr;
    }
}

void OutputTransaction::abandon_from_signal() noexcept {
    OutputTransaction* t = g_active.load();
    if (!t) return;
    // Files first (newest first), so that created directories are empty when their turn comes.
    for (Entry* e = t->head_.load(); e; e = e->next)
        if (!e->target.empty()) remove_entry_files(e->temporary, false);
    for (Entry* e = t->head_.load(); e; e = e->next)
        if (e->target.empty()) remove_entry_files(e->temporary, true);
}

void OutputTransaction::clear() noexcept {
    Entry* e = head_.exchange(nullptr);
    while (e) {
        Entry* next = e->next;
        std::free(e->temporary);
        std::free(e->renamed);
        delete e;
        e = next;
    }
}

}  // namespace acanthus::detail
