// Atomic output: temporary file in the target's directory, then rename(2).
#include "output/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <acanthus/error.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <vector>

#include "output/transaction.hpp"

namespace acanthus::detail {

namespace {

[[noreturn]] void fail(const std::string& path, int error) {
    throw InputError("cannot write '" + path + "': " + std::strerror(error));
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

}  // namespace

void write_file_atomically(const std::string& path, std::string_view bytes) {
    if (path.empty()) throw InputError("cannot write '': empty output file name");
    std::filesystem::path target(path);
    std::filesystem::path dir = target.parent_path();
    if (dir.empty()) dir = ".";
    std::string name = (dir / ("." + target.filename().string() + ".tmp-XXXXXX")).string();
    std::vector<char> temp(name.begin(), name.end());
    temp.push_back('\0');

    int fd = ::mkstemp(temp.data());
    if (fd < 0) fail(path, errno);
    int error = 0;
    if (!write_all(fd, bytes)) error = errno;
    if (!error && ::fchmod(fd, created_file_mode()) != 0) error = errno;
    if (::close(fd) != 0 && !error) error = errno;
    if (error) {
        ::unlink(temp.data());
        fail(path, error);
    }
    if (OutputTransaction* transaction = OutputTransaction::active()) {
        try {
            transaction->add_file(temp.data(), path);
        } catch (...) {
            ::unlink(temp.data());
            throw;
        }
        return;  // renamed with the run's other outputs
    }
    if (std::rename(temp.data(), path.c_str()) != 0) {
        error = errno;
        ::unlink(temp.data());
        fail(path, error);
    }
}

void write_stdout(std::string_view bytes) {
    if (!bytes.empty() && std::fwrite(bytes.data(), 1, bytes.size(), stdout) != bytes.size())
        fail("-", errno);
    if (std::fflush(stdout) != 0) fail("-", errno);
}

}  // namespace acanthus::detail
