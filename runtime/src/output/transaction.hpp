// All the output files of one run, published together: while a transaction is open,
// write_output_file() leaves each file under its temporary name; commit() renames them all
// once the whole run has succeeded. A run that fails (exception, watchdog, crash) leaves none.
#pragma once

#include <atomic>
#include <string>

namespace acanthus::detail {

class OutputTransaction {
  public:
    // Opens the transaction (at most one at a time) for the writes of this process.
    OutputTransaction();
    // Without commit(): removes every temporary file and the directories it created.
    ~OutputTransaction();
    OutputTransaction(const OutputTransaction&) = delete;
    OutputTransaction& operator=(const OutputTransaction&) = delete;

    // The open transaction, or null (then writes are renamed at once).
    static OutputTransaction* active();

    // While one lives, this thread's writes are renamed at once, outside the open transaction:
    // a picture of the growth so far (--partial) is shown while the run goes on, whatever the
    // run's end.
    class Bypass {
      public:
        Bypass();
        ~Bypass();
        Bypass(const Bypass&) = delete;
        Bypass& operator=(const Bypass&) = delete;
    };

    // A complete temporary file that becomes `target` on commit.
    void add_file(const std::string& temporary, const std::string& target);
    // A directory this run created; removed (if still empty) when the run fails.
    void add_created_directory(const std::string& path);
    // Renames the temporary of `target` (added before) into place now, ahead of the others: a
    // viewer may show it while the run goes on. It stays the run's: a run that fails afterwards
    // removes it. Throws InputError naming the file if the rename fails.
    void publish(const std::string& target);
    // Renames every temporary to its target, in the order they were added. Throws InputError
    // naming the file if a rename fails (the remaining temporaries are removed).
    void commit();

    // Async-signal-safe: removes the temporaries and created directories of the open transaction.
    // For the watchdog and the crash handler, just before _exit().
    static void abandon_from_signal() noexcept;

  private:
    struct Entry {
        char* temporary = nullptr;  // malloc'd, so a signal handler can read it
        std::string target;         // empty for a created directory
        char* renamed = nullptr;    // publish(): the temporary's name before (freed by clear)
        Entry* next = nullptr;
    };
    void clear() noexcept;

    std::atomic<Entry*> head_{nullptr};  // newest first
};

}  // namespace acanthus::detail
