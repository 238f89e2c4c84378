#include "server/watcher.hpp"

#include <poll.h>
#include <sys/inotify.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>

namespace acanthus {

FileWatcher::FileWatcher(std::function<void()> on_change)
    : on_change_(std::move(on_change)),
      inotify_(inotify_init1(IN_NONBLOCK | IN_CLOEXEC)),
      thread_([this] { loop(); }) {}

FileWatcher::~FileWatcher() {
    stop();
    if (inotify_ >= 0) ::close(inotify_);
}

void FileWatcher::stop() {
    stopping_ = true;
    if (thread_.joinable()) thread_.join();
}

std::string FileWatcher::fingerprint(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return "missing";
    // FNV-1a over the bytes and the size: rule files are small, reading them is cheap.
    std::uint64_t h = 0xcbf29ce484222325ULL, size = 0;
    char buffer[65536];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
        for (std::streamsize i = 0; i < in.gcount(); ++i) {
            h ^= static_cast<unsigned char>(buffer[i]);
            h *= 0x100000001b3ULL;
        }
        size += static_cast<std::uint64_t>(in.gcount());
        if (size > (64u << 20)) break;  // the compiler refuses larger files anyway
    }
    return std::to_string(h) + ":" + std::to_string(size);
}

void FileWatcher::watch(const std::vector<std::string>& paths) {
    std::lock_guard lock(mutex_);
    // A file already watched keeps its last fingerprint, so a save that came while the
    // compiler ran is still noticed on the next poll.
    std::vector<std::pair<std::string, std::string>> files;
    for (const std::string& p : paths) {
        std::string print;
        for (const auto& [known, known_print] : files_)
            if (known == p) print = known_print;
        files.emplace_back(p, print.empty() ? fingerprint(p) : print);
    }
    files_ = std::move(files);
    if (inotify_ < 0) return;
    // The folders, not the files: a save by rename replaces the file a watch would follow.
    std::set<std::string> wanted;
    for (const auto& [path, print] : files_) {
        std::string folder = std::filesystem::path(path).parent_path().string();
        wanted.insert(folder.empty() ? "." : folder);
    }
    for (auto it = folders_.begin(); it != folders_.end();) {
        if (wanted.count(it->first)) {
            ++it;
            continue;
        }
        inotify_rm_watch(inotify_, it->second);
        it = folders_.erase(it);
    }
    for (const std::string& folder : wanted) {
        if (folders_.count(folder)) continue;
        const int wd = inotify_add_watch(inotify_, folder.c_str(),
                                         IN_CLOSE_WRITE | IN_MOVED_TO | IN_CREATE | IN_DELETE);
        if (wd >= 0) folders_[folder] = wd;
    }
    // A folder that cannot be watched: its files are looked at every 25 ms.
    all_watched_ = folders_.size() == wanted.size();
}

void FileWatcher::loop() {
    while (!stopping_) {
        if (inotify_ >= 0) {
            // Between events, a look every half second only: an editor writing in place (the
            // file emptied, then written) is looked at once it closed the file, not halfway.
            pollfd p{inotify_, POLLIN, 0};
            if (::poll(&p, 1, all_watched_ ? 500 : 25) > 0) {
                // What changed does not matter: the fingerprints below tell.
                alignas(inotify_event) char events[4096];
                while (::read(inotify_, events, sizeof events) > 0) {
                }
            }
        } else {
            std::this_thread::sleep_for(std::chrono::milliseconds(25));
        }
        bool changed = false;
        {
            std::lock_guard lock(mutex_);
            for (auto& [path, print] : files_) {
                std::string now = fingerprint(path);
                if (now != print) {
                    print = now;
                    changed = true;
                }
            }
        }
        if (changed && !stopping_) on_change_();
    }
}

}  // namespace acanthus
