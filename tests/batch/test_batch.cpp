// The batch's pure pieces: manifest errors with their line and column, the job product and
// its file names, shards, and the PNG comparison with its diff picture.
#include <cairo.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include "batch/job_list.hpp"
#include "batch/manifest.hpp"
#include "batch/reference_check.hpp"

namespace {

namespace fs = std::filesystem;
using namespace acanthus::batch;

const std::string kSource = ACANTHUS_SOURCE_DIR;

// A manifest "<source>/tests/batch/m.toml": relative paths reach rules/ and examples/.
Manifest parse(const std::string& text) {
    return parse_manifest(text, kSource + "/tests/batch/m.toml");
}

// The error's "line:col: error: message" part.
std::string error_of(const std::string& text) {
    try {
        Manifest manifest = parse(text);
        expand_jobs(manifest, "/tmp/out");
    } catch (const ManifestError& e) {
        return std::to_string(e.where().line) + ":" + std::to_string(e.where().column) + ": " +
               e.message();
    }
    return "no error";
}

const char* kDots = "rules = \"../../rules/dots.acr\"\n";

TEST(BatchManifest, UnknownKeyInAJob) {
    EXPECT_EQ(error_of(std::string("[[job]]\n") + kDots + "panels = \"rect:10,10\"\nseed = [1]\n"),
              "4:1: unknown key 'seed' in [[job]] (the keys are rules, panels, seeds, params, "
              "args, formats, output)");
}

TEST(BatchManifest, UnknownTopLevelKey) {
    EXPECT_EQ(error_of("jobs = 1\n"), "1:1: unknown key 'jobs' (a manifest holds [[job]] tables)");
}

TEST(BatchManifest, WrongTypes) {
    EXPECT_EQ(error_of(std::string("[[job]]\n") + kDots +
                       "panels = \"rect:10,10\"\nseeds = [1, \"2\"]\n"),
              "4:13: a seed must be an integer, not a string");
    EXPECT_EQ(error_of(std::string("[[job]]\n") + kDots + "panels = 3\n"),
              "3:10: 'panels' must be a string or a list of strings, not an integer");
    EXPECT_EQ(
        error_of(std::string("[[job]]\n") + kDots + "panels = \"rect:10,10\"\nparams = [1]\n"),
        "4:10: 'params' must be a table of lists, not a list");
    EXPECT_EQ(error_of(std::string("[[job]]\n") + kDots +
                       "panels = \"rect:10,10\"\n[job.params]\nrim = [[1]]\n"),
              "5:8: parameter 'rim' takes strings, numbers or booleans, not a list");
    EXPECT_EQ(error_of(std::string("[[job]]\n") + kDots + "panels = \"rect:10,10\"\nseeds = -1\n"),
              "4:9: a seed must not be negative (an --rng-seed)");
    EXPECT_EQ(error_of(std::string("[[job]]\n") + kDots +
                       "panels = \"rect:10,10\"\nformats = [\"gif\"]\n"),
              "4:12: unknown format 'gif' (use svg, png, pdf, ps or eps)");
}

TEST(BatchManifest, MissingFiles) {
    std::string error = error_of(
        "[[job]]\nrules = [\"../../rules/dots.acr\", \"nowhere.acr\"]\npanels = \"rect:9,9\"\n");
    EXPECT_EQ(error.rfind("2:34: missing rule file 'nowhere.acr' (", 0), 0u) << error;
    error = error_of(std::string("[[job]]\n") + kDots +
                     "panels = [\"../../examples/panels/none.svg\"]\n");
    EXPECT_EQ(error.rfind("3:11: missing panel file '../../examples/panels/none.svg'", 0), 0u)
        << error;
    EXPECT_EQ(error_of("[[job]]\npanels = \"rect:9,9\"\n"), "1:1: [[job]] needs 'rules'");
}

TEST(BatchManifest, EmptyProduct) {
    EXPECT_EQ(error_of(std::string("[[job]]\n") + kDots + "panels = []\n"),
              "3:10: empty product: 'panels' is an empty list");
    EXPECT_EQ(error_of(std::string("[[job]]\n") + kDots + "panels = \"rect:9,9\"\nseeds = []\n"),
              "4:9: empty product: 'seeds' is an empty list");
    EXPECT_EQ(error_of(std::string("[[job]]\n") + kDots +
                       "panels = \"rect:9,9\"\nparams = { rim = [] }\n"),
              "4:18: empty product: parameter 'rim' has no values");
    EXPECT_EQ(error_of("# nothing\n"), "1:1: the manifest has no [[job]] table");
}

TEST(BatchManifest, TomlSyntaxError) {
    std::string error = error_of(std::string("[[job]]\n") + kDots + "panels = [\"rect:9,9\"\n");
    EXPECT_EQ(error.rfind("3:", 0), 0u) << error;
}

TEST(BatchManifest, OutputTemplateErrors) {
    std::string job = std::string("[[job]]\n") + kDots + "panels = \"rect:9,9\"\n";
    EXPECT_EQ(error_of(job + "output = \"out/{pattern}.svg\"\n"),
              "4:10: unknown placeholder '{pattern}' in 'output' (use {rule}, {panel}, {seed}, "
              "{params}, {ext})");
    EXPECT_EQ(error_of(job + "seeds = [1, 2]\noutput = \"out/{rule}.{ext}\"\n"),
              "5:10: two jobs write 'out/dots.svg' (the 'output' at line 5 too); add {params}, "
              "{seed}, {panel} or {ext} to it");
    EXPECT_EQ(error_of(job + "output = \"../{rule}.svg\"\n"),
              "4:10: 'output' gives '../dots.svg', which is not below the output directory");
    EXPECT_EQ(error_of(job + "output = \"/tmp/{rule}.svg\"\n"),
              "4:10: 'output' must be a relative path (outputs go below --output-dir)");
}

TEST(BatchJobs, ProductInManifestOrder) {
    Manifest manifest = parse(R"([[job]]
rules = ["../../rules/dots.acr", "../../rules/spiral.acr"]
panels = ["../../examples/panels/heart.svg", "rect:200,150"]
seeds = [1, 7]
params = { max_radius = [2.5, 3], rim = [true] }
args = ["--resolution", "64"]
formats = ["svg", "png"]

[[job]]
rules = "../../rules/dots.acr"
panels = "circle:40"
output = "extra/{rule}-{panel}.{ext}"
)");
    std::vector<Job> jobs = expand_jobs(manifest, "/tmp/out");
    ASSERT_EQ(jobs.size(), 2u * 2 * 2 * 2 * 2 + 1);
    EXPECT_EQ(jobs[0].rule, kSource + "/rules/dots.acr");
    EXPECT_EQ(jobs[0].panel, kSource + "/examples/panels/heart.svg");
    EXPECT_EQ(jobs[0].output_relative, "out/dots/heart-1-max_radius-2.5_rim-true.svg");
    EXPECT_EQ(jobs[1].output_relative, "out/dots/heart-1-max_radius-2.5_rim-true.png");
    EXPECT_EQ(jobs[2].seed, 7u);
    EXPECT_EQ(jobs[4].params[0].second, "3");
    EXPECT_EQ(jobs[8].panel, "rect:200,150");
    EXPECT_EQ(jobs[8].output_relative, "out/dots/rect-200x150-1-max_radius-2.5_rim-true.svg");
    EXPECT_EQ(jobs[8].output, "/tmp/out/out/dots/rect-200x150-1-max_radius-2.5_rim-true.svg");
    EXPECT_EQ(jobs[16].rule_name, "spiral");
    EXPECT_EQ(jobs.back().output_relative, "extra/dots-circle-40.svg");
    EXPECT_EQ(jobs.back().seed, 1u);  // the default seed
    EXPECT_EQ(jobs[0].args, (std::vector<std::string>{"--resolution", "64"}));
    std::set<std::string> outputs;
    for (const Job& job : jobs) outputs.insert(job.output);
    EXPECT_EQ(outputs.size(), jobs.size());
}

TEST(BatchJobs, FileSafeNames) {
    EXPECT_EQ(file_safe("rect:200,150"), "rect-200x150");
    EXPECT_EQ(file_safe("ellipse:30.5,20"), "ellipse-30.5x20");
    EXPECT_EQ(file_safe("a b/c"), "a_b_c");
    EXPECT_EQ(file_safe(".."), "_..");
    EXPECT_EQ(params_name({{"reference", "refs/fish.svg"}, {"n", "2"}}),
              "reference-refs_fish.svg_n-2");
}

TEST(BatchShards, SplitEveryJobOnce) {
    Manifest manifest = parse(std::string("[[job]]\n") + kDots +
                              "panels = \"rect:9,9\"\nseeds = [1,2,3,4,5,6,7]\n");
    std::vector<Job> jobs = expand_jobs(manifest, "/tmp/out");
    std::map<std::size_t, int> seen;
    for (std::size_t k = 0; k < 3; ++k)
        for (const Job& job : select_shard(jobs, {k, 3})) ++seen[job.index];
    ASSERT_EQ(seen.size(), jobs.size());
    for (const auto& [index, count] : seen) EXPECT_EQ(count, 1);
    EXPECT_EQ(select_shard(jobs, {1, 3}).front().seed, 2u);
}

TEST(BatchOnly, GlobsOverOutputs) {
    Manifest manifest = parse(std::string("[[job]]\n") + kDots +
                              "panels = [\"rect:9,9\", \"circle:5\"]\nformats = [\"svg\", "
                              "\"png\"]\n\n[[job]]\nrules = \"../../rules/spiral.acr\"\n"
                              "panels = \"rect:9,9\"\n");
    const std::vector<Job> all = expand_jobs(manifest, "/tmp/out");
    std::vector<Job> jobs = all;
    std::string error;
    ASSERT_TRUE(select_outputs(jobs, {}, error));
    EXPECT_EQ(jobs.size(), all.size());
    ASSERT_TRUE(select_outputs(jobs, {"out/dots/*"}, error)) << error;
    EXPECT_EQ(jobs.size(), 4u);
    jobs = all;
    ASSERT_TRUE(select_outputs(jobs, {"out/*/rect-*.svg", "out/dots/circle-5-1.png"}, error));
    ASSERT_EQ(jobs.size(), 3u);
    EXPECT_EQ(jobs[2].index, all.back().index);  // in job order, indices kept for the shards
    jobs = all;
    EXPECT_FALSE(select_outputs(jobs, {"out/*"}, error));  // '*' does not cross a '/'
    EXPECT_FALSE(select_outputs(jobs, {"out/dots/*", "out/dot/*"}, error));
    EXPECT_EQ(error, "--only 'out/dot/*' matches no job's output");
    EXPECT_EQ(jobs.size(), all.size());
}

TEST(BatchShards, ParseAndEnvironment) {
    Shard shard;
    std::string error;
    EXPECT_TRUE(parse_shard("1/4", shard, error));
    EXPECT_EQ(shard.index, 1u);
    EXPECT_EQ(shard.count, 4u);
    for (const char* bad : {"4/4", "1/0", "-1/2", "1", "a/b", "1/2/3"})
        EXPECT_FALSE(parse_shard(bad, shard, error)) << bad;

    std::map<std::string, std::string> env{{"SLURM_ARRAY_TASK_ID", "3"},
                                           {"SLURM_ARRAY_TASK_MIN", "1"},
                                           {"SLURM_ARRAY_TASK_COUNT", "3"}};
    auto lookup = [&env](const char* name) -> const char* {
        auto it = env.find(name);
        return it == env.end() ? nullptr : it->second.c_str();
    };
    ASSERT_TRUE(shard_from_environment(lookup, 0, shard, error)) << error;
    EXPECT_EQ(shard.index, 2u);
    EXPECT_EQ(shard.count, 3u);
    env = {{"JOB_COMPLETION_INDEX", "1"}};
    EXPECT_FALSE(shard_from_environment(lookup, 0, shard, error));  // needs --shards
    ASSERT_TRUE(shard_from_environment(lookup, 2, shard, error));
    EXPECT_EQ(shard.index, 1u);
    EXPECT_FALSE(shard_from_environment(lookup, 1, shard, error));  // index beyond the count
    env = {};
    EXPECT_FALSE(shard_from_environment(lookup, 2, shard, error));
}

void write_png(const std::string& path, int width, int height, double red, double x0) {
    cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height);
    cairo_t* cr = cairo_create(surface);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_set_source_rgb(cr, red, 0.2, 0.2);
    cairo_rectangle(cr, x0, 2, 4, 4);
    cairo_fill(cr);
    cairo_destroy(cr);
    cairo_surface_write_to_png(surface, path.c_str());
    cairo_surface_destroy(surface);
}

TEST(BatchReferences, PngWithinToleranceAndDiffPicture) {
    fs::path dir = fs::temp_directory_path() / ("test_batch_png_" + std::to_string(getpid()));
    fs::create_directories(dir);
    write_png(dir / "ref.png", 16, 10, 0.5, 2);
    write_png(dir / "close.png", 16, 10, 0.52, 2);  // 5 of 255 off
    write_png(dir / "moved.png", 16, 10, 0.5, 8);
    write_png(dir / "small.png", 12, 10, 0.5, 2);
    std::string diff = (dir / "d" / "x.diff.png").string();

    PixelComparison same = compare_png(dir / "ref.png", dir / "close.png", 8, diff);
    EXPECT_TRUE(same.readable);
    EXPECT_EQ(same.differing_pixels, 0u);
    EXPECT_FALSE(fs::exists(diff));
    EXPECT_GT(compare_png(dir / "ref.png", dir / "close.png", 2, "").differing_pixels, 0u);

    PixelComparison moved = compare_png(dir / "ref.png", dir / "moved.png", 8, diff);
    EXPECT_EQ(moved.differing_pixels, 32u);  // two 4 x 4 squares
    ASSERT_TRUE(fs::exists(diff));
    cairo_surface_t* picture = cairo_image_surface_create_from_png(diff.c_str());
    EXPECT_EQ(cairo_image_surface_get_width(picture), 16);
    cairo_surface_destroy(picture);

    PixelComparison small = compare_png(dir / "ref.png", dir / "small.png", 8, "");
    EXPECT_FALSE(small.same_size);
    EXPECT_EQ(small.differing_pixels, 4u * 10);

    std::ofstream(dir / "bad.png") << "not a png";
    PixelComparison bad = compare_png(dir / "ref.png", dir / "bad.png", 8, "");
    EXPECT_FALSE(bad.readable);
    EXPECT_NE(bad.error.find("bad.png"), std::string::npos);
    fs::remove_all(dir);
}

}  // namespace
