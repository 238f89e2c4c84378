// Output files through the shared atomic writer, joined to the run's transaction when one is open.
#include "output/output_writer.hpp"

#include <acanthus/error.hpp>
#include <acanthus/output_file.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "output/transaction.hpp"

namespace acanthus::detail {

void write_output_file(const std::string& path, std::string_view bytes) {
    std::string error;
    const std::string temporary = write_temporary_sibling(path, bytes, error);
    if (temporary.empty()) throw InputError(error);
    if (OutputTransaction* transaction = OutputTransaction::active()) {
        try {
            transaction->add_file(temporary, path);
        } catch (...) {
            remove_if_present(temporary);
            throw;
        }
        return;  // renamed with the run's other outputs
    }
    if (!replace_with_temporary(temporary, path, error)) throw InputError(error);
}

void write_stdout(std::string_view bytes) {
    if (!bytes.empty() && std::fwrite(bytes.data(), 1, bytes.size(), stdout) != bytes.size())
        throw InputError(std::string("cannot write '-': ") + std::strerror(errno));
    if (std::fflush(stdout) != 0)
        throw InputError(std::string("cannot write '-': ") + std::strerror(errno));
}

void write_output(const std::string& path, std::string_view bytes) {
    if (path == "-")
        write_stdout(bytes);
    else
        write_output_file(path, bytes);
}

}  // namespace acanthus::detail
