#include "output_file.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

namespace acanthus {

std::string temporary_sibling(const std::string& path, std::string& error) {
    std::filesystem::path p(path);
    std::string dir = p.has_parent_path() ? p.parent_path().string() : ".";
    std::string templ = dir + "/." + p.filename().string() + ".tmp.XXXXXX";
    int fd = mkstemp(templ.data());
    if (fd < 0) {
        error = std::string("cannot create a file in '") + dir + "': " + std::strerror(errno);
        return {};
    }
    close(fd);
    return templ;
}

void remove_if_present(const std::string& path) {
    if (!path.empty()) std::remove(path.c_str());
}

bool write_file_atomically(const std::string& path, std::string_view content, std::string& error) {
    std::string temp = temporary_sibling(path, error);
    if (temp.empty()) return false;
    std::FILE* f = std::fopen(temp.c_str(), "wb");
    bool ok = f && std::fwrite(content.data(), 1, content.size(), f) == content.size();
    if (f && std::fclose(f) != 0) ok = false;
    if (!ok) {
        error = std::string("cannot write '") + path + "': " + std::strerror(errno);
        remove_if_present(temp);
        return false;
    }
    // mkstemp makes 0600; give the file the usual permissions.
    mode_t mask = umask(0);
    umask(mask);
    chmod(temp.c_str(), 0666 & ~mask);
    if (std::rename(temp.c_str(), path.c_str()) != 0) {
        error = std::string("cannot write '") + path + "': " + std::strerror(errno);
        remove_if_present(temp);
        return false;
    }
    return true;
}

}  // namespace acanthus
