// Streaming output through the same temporary-file-and-rename as write_output_file().
#include "output/output_stream.hpp"

#include <acanthus/error.hpp>
#include <acanthus/output_file.hpp>
#include <cerrno>
#include <cstring>

#include "output/transaction.hpp"

namespace acanthus::detail {

OutputStream::OutputStream(const std::string& path) : path_(path) {
    if (path == "-") {
        file_ = stdout;
        return;
    }
    std::string error;
    temporary_ = create_temporary_sibling(path, error);
    if (temporary_.empty()) throw InputError(error);
    file_ = std::fopen(temporary_.c_str(), "wb");
    if (!file_) {
        const int why = errno;
        remove_if_present(temporary_);
        throw InputError("cannot write '" + path_ + "': " + std::strerror(why));
    }
    // Registered now, so that the watchdog or the crash handler removes it mid-way too.
    if (OutputTransaction* transaction = OutputTransaction::active()) {
        transaction->add_file(temporary_, path_);
        in_transaction_ = true;
    }
}

OutputStream::~OutputStream() {
    if (committed_ || file_ == stdout) return;
    if (file_) std::fclose(file_);
    remove_if_present(temporary_);
}

void OutputStream::fail(int error) {
    throw InputError("cannot write '" + path_ + "': " + std::strerror(error));
}

void OutputStream::write(std::string_view bytes) {
    if (!bytes.empty() && std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size())
        fail(errno);
}

void OutputStream::commit() {
    if (file_ == stdout) {
        if (std::fflush(stdout) != 0) fail(errno);
        committed_ = true;
        return;
    }
    std::FILE* file = file_;
    file_ = nullptr;
    if (std::fclose(file) != 0) fail(errno);
    if (!in_transaction_) {
        std::string error;
        if (!replace_with_temporary(temporary_, path_, error)) throw InputError(error);
    }
    committed_ = true;  // renamed, or the transaction's to rename
}

}  // namespace acanthus::detail
