// All outputs of a run or none: files written while a transaction is open appear only on commit.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "fixtures/temp_dir.hpp"
#include "output/output_writer.hpp"
#include "output/transaction.hpp"

namespace {

namespace fs = std::filesystem;

class OutputTransactionTest : public ::testing::Test {
  protected:
    std::size_t entries() const {
        return static_cast<std::size_t>(
            std::distance(fs::directory_iterator(dir_), fs::directory_iterator{}));
    }
    std::string read(const fs::path& p) { return acanthus::test::slurp(p.string()); }
    acanthus::test::TempDir tmp_{"outputs"};
    fs::path dir_ = tmp_.path();
};

TEST_F(OutputTransactionTest, CommitPublishesEveryFile) {
    {
        acanthus::detail::OutputTransaction t;
        acanthus::detail::write_output_file((dir_ / "a.svg").string(), "a");
        acanthus::detail::write_output_file((dir_ / "b.json").string(), "b");
        EXPECT_FALSE(fs::exists(dir_ / "a.svg"));
        EXPECT_EQ(entries(), 2u);  // the two temporaries
        t.commit();
    }
    EXPECT_EQ(read(dir_ / "a.svg"), "a");
    EXPECT_EQ(read(dir_ / "b.json"), "b");
    EXPECT_EQ(entries(), 2u);
}

TEST_F(OutputTransactionTest, WithoutCommitNothingIsLeftAndOldFilesStay) {
    std::ofstream(dir_ / "a.svg") << "old";
    fs::create_directory(dir_ / "frames");
    {
        acanthus::detail::OutputTransaction t;
        t.add_created_directory((dir_ / "frames").string());
        acanthus::detail::write_output_file((dir_ / "a.svg").string(), "new");
        acanthus::detail::write_output_file((dir_ / "frames" / "f.png").string(), "f");
    }
    EXPECT_EQ(read(dir_ / "a.svg"), "old");
    EXPECT_FALSE(fs::exists(dir_ / "frames"));
    EXPECT_EQ(entries(), 1u);
}

TEST_F(OutputTransactionTest, WithoutTransactionFilesAppearAtOnce) {
    acanthus::detail::write_output_file((dir_ / "a.svg").string(), "a");
    EXPECT_EQ(read(dir_ / "a.svg"), "a");
}

}  // namespace
