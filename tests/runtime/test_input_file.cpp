// The one input-file reader: regular files only, never blocking, a size limit held while reading.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <acanthus/error.hpp>
#include <acanthus/input_file.hpp>
#include <filesystem>
#include <fstream>
#include <string>

#include "fixtures/temp_dir.hpp"

namespace {

namespace fs = std::filesystem;

class InputFileTest : public ::testing::Test {
  protected:
    std::string write(const std::string& name, const std::string& text) {
        return tmp_.write(name, text).string();
    }
    acanthus::test::TempDir tmp_{"input"};
    fs::path dir_ = tmp_.path();
};

TEST_F(InputFileTest, ReadsARegularFile) {
    std::string text;
    EXPECT_EQ(acanthus::read_input_file(write("a.svg", "<svg/>"), text), "");
    EXPECT_EQ(text, "<svg/>");
}

TEST_F(InputFileTest, RefusesADirectory) {
    std::string text;
    EXPECT_EQ(acanthus::read_input_file(dir_.string(), text), "not a regular file (a directory)");
}

TEST_F(InputFileTest, RefusesAFifoWithoutBlocking) {
    const std::string path = (dir_ / "fifo.svg").string();
    ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
    std::string text;
    EXPECT_EQ(acanthus::read_input_file(path, text), "not a regular file (a FIFO)");
}

TEST_F(InputFileTest, RefusesADeviceWithoutReadingIt) {
    std::string text;
    EXPECT_EQ(acanthus::read_input_file("/dev/zero", text),
              "not a regular file (a character device)");
    EXPECT_TRUE(text.empty());
}

TEST_F(InputFileTest, HoldsTheSizeLimit) {
    const std::string path = write("big.acr", std::string(1000, 'x'));
    std::string text;
    EXPECT_EQ(acanthus::read_input_file(path, text, 999), "larger than the 999 bytes limit");
    EXPECT_TRUE(text.empty());
    EXPECT_EQ(acanthus::read_input_file(path, text, 1000), "");
    EXPECT_EQ(text.size(), 1000u);
}

TEST_F(InputFileTest, ReadsFilesThatReportSizeZero) {
    std::string text;
    EXPECT_EQ(acanthus::read_input_file("/proc/self/status", text), "");
    EXPECT_NE(text.find("Name:"), std::string::npos);
}

TEST_F(InputFileTest, ThrowingFormNamesThePathAndWhat) {
    const std::string missing = (dir_ / "missing.svg").string();
    try {
        acanthus::read_input_file_or_throw(missing, "stroke file");
        FAIL() << "no exception";
    } catch (const acanthus::InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  missing + ": cannot read stroke file: No such file or directory");
    }
}

}  // namespace
