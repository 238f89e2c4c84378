#include "server/watcher.hpp"

#include <chrono>
#include <cstdint>
#include <fstream>
#include <iterator>

namespace acanthus {

FileWatcher::FileWatcher(std::function<void()> on_change)
    : on_change_(std::move(on_change)), thread_([this] { loop(); }) {}

FileWatcher::~FileWatcher() { stop(); }

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
}

void FileWatcher::loop() {
    while (!stopping_) {
        std::this_thread::sleep_for(std::chrono::milliseconds(25));
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
