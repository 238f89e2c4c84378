// Watches the rule file and the files it imports by content: looks at them as soon as their
// folder reports a file closed after writing or renamed into it (inotify), and every 0.5 s
// besides (every 25 ms where a folder cannot be watched), and reports when any one's bytes
// changed (an editor's rename-on-save and touch without change both behave: only content
// counts).
#pragma once

#include <atomic>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace acanthus {

class FileWatcher {
  public:
    explicit FileWatcher(std::function<void()> on_change);
    ~FileWatcher();
    FileWatcher(const FileWatcher&) = delete;
    FileWatcher& operator=(const FileWatcher&) = delete;

    // The files to watch from now on, with their content as the compiler read it.
    void watch(const std::vector<std::string>& paths);
    void stop();

  private:
    void loop();
    static std::string fingerprint(const std::string& path);

    std::function<void()> on_change_;
    std::mutex mutex_;
    std::vector<std::pair<std::string, std::string>> files_;  // path, fingerprint
    int inotify_ = -1;                                        // -1: polling only
    std::map<std::string, int> folders_;                      // watched folder, its watch
    std::atomic<bool> all_watched_{false};
    std::atomic<bool> stopping_{false};
    std::thread thread_;
};

}  // namespace acanthus
