// Relaxation (section 5.5, eq. 5) against a dense least-squares solve of the same objective:
// one row per spring and coordinate over the free unknowns, solved by Householder QR.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <acanthus/random.hpp>
#include <acanthus/region.hpp>
#include <acanthus/stdlib/growth.hpp>
#include <cmath>
#include <map>
#include <vector>

#include "growth_fixtures.hpp"
#include "relaxation.hpp"

using namespace acanthus;
using namespace acanthus::growth::detail;

namespace {

struct Problem {
    std::vector<Point> positions;
    std::vector<Spring> springs;
    std::vector<int> free_nodes;
};

// A jittered grid of nodes, each linked to its right and upper neighbours (and some diagonals),
// desired offsets near the true ones, some nodes held.
Problem random_problem(Random& random, int w, int h) {
    Problem p;
    auto id = [&](int i, int j) { return j * w + i; };
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            p.positions.push_back({i + random.uniform(-0.3, 0.3), j + random.uniform(-0.3, 0.3)});
    auto spring = [&](int a, int b, Vector ideal) {
        p.springs.push_back({a, b, ideal + Vector{random.normal(0, 0.1), random.normal(0, 0.1)}});
    };
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            if (i + 1 < w) spring(id(i, j), id(i + 1, j), {1, 0});
            if (j + 1 < h) spring(id(i, j), id(i, j + 1), {0, 1});
            if (i + 1 < w && j + 1 < h && random.chance(0.5))
                spring(id(i + 1, j + 1), id(i, j), {-1, -1});
        }
    for (int k = 0; k < w * h; ++k)
        if (!random.chance(0.15) && k != 0) p.free_nodes.push_back(k);
    return p;
}

// Dense least squares: rows sqrt(weight) * (x_to - x_from - d) per spring, plus the stiffness rows.
std::vector<Point> dense_solve(const Problem& p, double stiffness) {
    std::map<int, int> col;
    for (int n : p.free_nodes) col.emplace(n, static_cast<int>(col.size()));
    const int n = static_cast<int>(col.size());
    std::vector<Point> out = p.positions;
    for (int axis = 0; axis < 2; ++axis) {
        std::vector<std::vector<double>> rows;
        std::vector<double> rhs;
        auto coord = [&](Point q) { return axis == 0 ? q.x : q.y; };
        for (const Spring& s : p.springs) {
            bool f = col.count(s.from), t = col.count(s.to);
            if (!f && !t) continue;
            std::vector<double> row(n, 0.0);
            double b = axis == 0 ? s.desired.x : s.desired.y;
            if (t)
                row[col[s.to]] += 1;
            else
                b -= coord(p.positions[s.to]);
            if (f)
                row[col[s.from]] -= 1;
            else
                b += coord(p.positions[s.from]);
            rows.push_back(row);
            rhs.push_back(b);
        }
        if (stiffness > 0)
            for (auto [node, c] : col) {
                std::vector<double> row(n, 0.0);
                row[c] = std::sqrt(stiffness);
                rows.push_back(row);
                rhs.push_back(std::sqrt(stiffness) * coord(p.positions[node]));
            }
        Eigen::MatrixXd a(rows.size(), n);
        Eigen::VectorXd b(rows.size());
        for (std::size_t r = 0; r < rows.size(); ++r) {
            for (int c = 0; c < n; ++c) a(static_cast<long>(r), c) = rows[r][c];
            b[static_cast<long>(r)] = rhs[r];
        }
        Eigen::VectorXd x = a.colPivHouseholderQr().solve(b);
        for (auto [node, c] : col) (axis == 0 ? out[node].x : out[node].y) = x[c];
    }
    return out;
}

TEST(GrowthRelaxation, MatchesDenseLeastSquares) {
    for (std::uint64_t seed : {1u, 2u, 3u, 4u}) {
        Random random(seed);
        Problem p = random_problem(random, 6, 5);
        for (double stiffness : {0.0, 0.3}) {
            std::vector<Point> got = p.positions;
            relax(got, p.springs, p.free_nodes, stiffness);
            std::vector<Point> want = dense_solve(p, stiffness);
            for (std::size_t k = 0; k < got.size(); ++k) {
                EXPECT_NEAR(got[k].x, want[k].x, 1e-8) << "seed " << seed << " node " << k;
                EXPECT_NEAR(got[k].y, want[k].y, 1e-8) << "seed " << seed << " node " << k;
            }
        }
    }
}

TEST(GrowthRelaxation, HeldNodesStayAndConsistentOffsetsAreReached) {
    // Springs that agree with one layout: relaxation must reach it exactly from a distorted start,
    // with the held node (0) as the anchor.
    Random random(9);
    std::vector<Point> truth;
    for (int k = 0; k < 12; ++k) truth.push_back({random.uniform(0, 5), random.uniform(0, 5)});
    std::vector<Spring> springs;
    for (int k = 0; k + 1 < 12; ++k) springs.push_back({k, k + 1, truth[k + 1] - truth[k]});
    springs.push_back({11, 0, truth[0] - truth[11]});
    std::vector<Point> positions = truth;
    for (int k = 1; k < 12; ++k)
        positions[k] += Vector{random.uniform(-1, 1), random.uniform(-1, 1)};
    std::vector<int> free_nodes;
    for (int k = 1; k < 12; ++k) free_nodes.push_back(k);
    relax(positions, springs, free_nodes, 0.0);
    EXPECT_EQ(positions[0], truth[0]);
    for (int k = 0; k < 12; ++k) {
        EXPECT_NEAR(positions[k].x, truth[k].x, 1e-9);
        EXPECT_NEAR(positions[k].y, truth[k].y, 1e-9);
    }
}

TEST(GrowthRelaxation, UnanchoredGroupStaysPutWithStiffness) {
    std::vector<Point> positions{{0, 0}, {1, 0}};
    std::vector<Spring> springs{{0, 1, {2, 0}}};
    relax(positions, springs, {0, 1}, 1e-6);
    // The pair stretches symmetrically about its old centre instead of drifting away.
    EXPECT_NEAR(positions[1].x - positions[0].x, 2.0, 1e-4);
    EXPECT_NEAR(positions[0].x + positions[1].x, 1.0, 1e-6);
}

// In a whole synthesis: relaxation, windowed or global, brings the result nearer the reference's
// offsets (bench/growth.cpp measures by how much, and at what cost).
TEST(GrowthRelaxation, SynthesisLinkErrorFallsWithRelaxation) {
    using namespace acanthus::growth;
    Reference ref =
        Reference::from_elements(growth_fixtures::jittered_lattice(6, 6, 10, 1.5, {"a", "b"}));
    acanthus::Region panel = acanthus::Region::from_spec("rect:120,90");
    Options o;
    o.relax_slack = 0;  // every link pulled to its offset, as the paper's eq. 5
    o.relax = false;
    double none = synthesize(ref, panel, o, {}, 2).stats.link_error;
    o.relax = true;
    double window = synthesize(ref, panel, o, {}, 2).stats.link_error;
    o.relax_global = true;
    double global = synthesize(ref, panel, o, {}, 2).stats.link_error;
    EXPECT_GT(none, 0);
    EXPECT_LT(window, none);
    EXPECT_LT(global, none);
}

// The slack keeps a near-regular reference's jitter: pulling every link to one ring's offset
// (slack 0) evens the spacing out, so the nearest neighbours stand wider apart than the
// reference's; with the default slack the NN median stays the reference's, as without relaxation.
TEST(GrowthRelaxation, SlackKeepsTheReferencesJitter) {
    using namespace acanthus::growth;
    Reference ref =
        Reference::from_elements(growth_fixtures::jittered_lattice(12, 12, 10, 2.0, {"a", "b"}));
    acanthus::Region panel = acanthus::Region::from_spec("rect:200,150");
    auto nn = [&](bool relax, double slack) {
        Options o;
        o.relax = relax;
        o.relax_slack = slack;
        o.fit_to_ring = false;  // the slack alone (the fit keeps this reference's rings too)
        double sum = 0;
        for (std::uint64_t seed : {1, 2, 3}) {
            Fidelity f = synthesize(ref, panel, o, {}, seed).fidelity;
            sum += f.nn_median / f.reference_nn_median;
        }
        return sum / 3;
    };
    const double off = nn(false, 0), full = nn(true, 0), slack = nn(true, Options{}.relax_slack);
    EXPECT_NEAR(off, 1.0, 0.05);
    EXPECT_NEAR(slack, 1.0, 0.05);
    // Measured: without relaxation 1.018, slack 0 1.041, the default slack 1.005.
    EXPECT_GT(full, slack + 0.02) << "slack 0 should even the jitter out";
}

}  // namespace
