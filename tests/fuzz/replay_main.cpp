// Runs a libFuzzer target's LLVMFuzzerTestOneInput on the files named on the command line, in
// an ordinary build: the crash inputs the fuzzers found stay regression tests, and the targets
// keep compiling. Exit 0 when every input went through; a crash is the failure.
#include <acanthus/input_file.hpp>
#include <cstddef>
#include <cstdint>
#include <iostream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

int main(int argc, char** argv) {
    if (argc < 2) {
        std::cerr << "usage: " << argv[0] << " INPUT...\n";
        return 2;
    }
    for (int i = 1; i < argc; ++i) {
        std::string text;
        if (std::string why = acanthus::read_input_file(argv[i], text); !why.empty()) {
            std::cerr << argv[i] << ": " << why << "\n";
            return 1;
        }
        std::cout << argv[i] << " (" << text.size() << " bytes)" << std::endl;
        LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
    }
    std::cout << "ok: " << argc - 1 << " inputs" << std::endl;
    return 0;
}
