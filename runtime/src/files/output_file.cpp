// Atomic writes: mkstemp(3) next to the target, write(2) all, rename(2).
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <acanthus/output_file.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <vector>

namespace acanthus {

namespace {

std::string cannot_write(const std::string& path, int error) {
    return "cannot write '" + path + "': " + std::strerror(error);
}

// mkstemp creates files 0600; a finished output gets the mode a plain open() would give it.
mode_t created_file_mode() {
    mode_t mask = ::umask(0);
    ::umask(mask);
    return 0666 & ~mask;
}

bool write_all(int fd, std::string_view bytes) {
    while (!bytes.empty()) {
        ssize_t n = ::write(fd, bytes.data(), bytes.size());
        if (n < 0) {
            if (errno == EINTR) continue;
            return false;
        }
        bytes.remove_prefix(static_cast<std::size_t>(n));
    }
    return true;
}

// Opens a new temporary sibling of `path`; -1 with `error` set on failure.
int open_temporary_sibling(const std::string& path, std::string& name, std::string& error) {
    if (path.empty()) {
        error = "cannot write '': empty output file name";
        return -1;
    }
    std::filesystem::path target(path);
    std::filesystem::path dir = target.parent_path();
    if (dir.empty()) dir = ".";
    // Appended piecewise: GCC 12 at -O3 misreads "." + string as an overlapping copy.
    std::string hidden = ".";
    hidden += target.filename().string();
    hidden += ".tmp-XXXXXX";
    std::string pattern = (dir / hidden).string();
    std::vector<char> temp(pattern.begin(), pattern.end());
    temp.push_back('\0');
    int fd = ::mkstemp(temp.data());
    if (fd < 0) {
        error = cannot_write(path, errno);
        return -1;
    }
    name = temp.data();
    return fd;
}

}  // namespace

std::string create_temporary_sibling(const std::string& path, std::string& error) {
    return write_temporary_sibling(path, {}, error);
}

std::string write_temporary_sibling(const std::string& path, std::string_view bytes,
                                    std::string& error) {
    std::string name;
    int fd = open_temporary_sibling(path, name, error);
    if (fd < 0) return {};
    int failure = 0;
    if (!write_all(fd, bytes)) failure = errno;
    if (!failure && ::fchmod(fd, created_file_mode()) != 0) failure = errno;
    if (::close(fd) != 0 && !failure) failure = errno;
    if (failure) {
        ::unlink(name.c_str());
        error = cannot_write(path, failure);
        return {};
    }
    return name;
}

bool replace_with_temporary(const std::string& temporary, const std::string& path,
                            std::string& error) {
    if (std::rename(temporary.c_str(), path.c_str()) == 0) return true;
    error = cannot_write(path, errno);
    ::unlink(temporary.c_str());
    return false;
}

bool write_file_atomically(const std::string& path, std::string_view bytes, std::string& error) {
    std::string temporary = write_temporary_sibling(path, bytes, error);
    return !temporary.empty() && replace_with_temporary(temporary, path, error);
}

void remove_if_present(const std::string& path) {
    if (!path.empty()) ::unlink(path.c_str());
}

}  // namespace acanthus
