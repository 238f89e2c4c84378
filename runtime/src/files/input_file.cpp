// The one input-file reader of the compiler and the runtime (see input_file.hpp).
// It needs only header-only runtime headers, so the compiler links it without the runtime.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <acanthus/error.hpp>
#include <acanthus/input_file.hpp>
#include <cerrno>
#include <cstring>

namespace acanthus {

namespace {

std::string file_kind(mode_t mode) {
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a plain file";
}

std::string size_text(std::size_t bytes) {
    if (bytes >= (std::size_t{1} << 20) && bytes % (std::size_t{1} << 20) == 0)
        return std::to_string(bytes >> 20) + " MiB";
    return std::to_string(bytes) + " bytes";
}

class FileDescriptor {
  public:
    explicit FileDescriptor(int fd) : fd_(fd) {}
    ~FileDescriptor() {
        if (fd_ >= 0) ::close(fd_);
    }
    FileDescriptor(const FileDescriptor&) = delete;
    FileDescriptor& operator=(const FileDescriptor&) = delete;
    int get() const { return fd_; }

  private:
    int fd_;
};

}  // namespace

std::string read_input_file(const std::string& path, std::string& text, std::size_t max_bytes) {
    text.clear();
    if (path.empty()) return "empty file name";
    // Refuse what is not a regular file before opening it at all (opening a device can act).
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
        return "not a regular file (" + file_kind(st.st_mode) + ")";
    // O_NONBLOCK: a FIFO swapped in since stat() must not block the open; fstat refuses it.
    FileDescriptor fd(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY));
    if (fd.get() < 0) return std::strerror(errno);
    if (::fstat(fd.get(), &st) != 0) return std::strerror(errno);
    if (!S_ISREG(st.st_mode)) return "not a regular file (" + file_kind(st.st_mode) + ")";
    const auto limit_error = [&] { return "larger than the " + size_text(max_bytes) + " limit"; };
    if (st.st_size > 0 && static_cast<unsigned long long>(st.st_size) > max_bytes)
        return limit_error();
    // The size may be 0 (/proc) or change while reading: the limit holds for what is read.
    text.reserve(static_cast<std::size_t>(st.st_size));
    char buffer[1 << 16];
    for (;;) {
        const ssize_t n = ::read(fd.get(), buffer, sizeof buffer);
        if (n < 0) {
            if (errno == EINTR) continue;
            const std::string why = std::strerror(errno);
            text.clear();
            return why;
        }
        if (n == 0) break;
        if (text.size() + static_cast<std::size_t>(n) > max_bytes) {
            text.clear();
            text.shrink_to_fit();
            return limit_error();
        }
        text.append(buffer, static_cast<std::size_t>(n));
    }
    return {};
}

std::string read_input_file_or_throw(const std::string& path, const std::string& what,
                                     std::size_t max_bytes) {
    std::string text;
    const std::string why = read_input_file(path, text, max_bytes);
    if (!why.empty()) throw InputError(path + ": cannot read " + what + ": " + why);
    return text;
}

}  // namespace acanthus
