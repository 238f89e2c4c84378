// dartfill exclusive regions: validation, triangulation, transformation and exact overlap.
#include <gtest/gtest.h>

#include <acanthus/error.hpp>
#include <acanthus/random.hpp>
#include <acanthus/stdlib/dartfill.hpp>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <string>

#include "dartfill_oracle.hpp"
#include "fixtures/temp_dir.hpp"
#include "placed_shape.hpp"
#include "shape.hpp"

using namespace acanthus;
using namespace acanthus::dartfill;

namespace {

std::vector<Point> star(int spikes, double outer, double inner) {
    std::vector<Point> pts;
    for (int k = 0; k < 2 * spikes; ++k) {
        double a = M_PI * k / spikes;
        double r = k % 2 ? inner : outer;
        pts.push_back({r * std::cos(a), r * std::sin(a)});
    }
    return pts;
}

// A "C": concave with a deep notch.
std::vector<Point> c_shape() {
    return {{0, 0}, {10, 0}, {10, 2}, {2, 2}, {2, 8}, {10, 8}, {10, 10}, {0, 10}};
}

const char* leaf_path = "M 0 0 C 5 -8 15 -8 20 0 C 15 8 5 8 0 0 Z";

double triangles_area(const Shape& s) {
    double a = 0;
    for (const Triangle& t : s.triangles()) a += std::abs((t[1] - t[0]).cross(t[2] - t[0])) / 2;
    return a;
}

std::string message_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(DartfillShape, TriangulationCoversExactlyTheConcavePolygon) {
    for (const auto& [name, pts] : {std::pair{"star", star(7, 10, 3)}, std::pair{"c", c_shape()}}) {
        Shape s = Shape::from_points(name, pts);
        EXPECT_EQ(s.triangles().size(), pts.size() - 2) << name;
        EXPECT_NEAR(triangles_area(s), std::abs(signed_area(pts)), 1e-9) << name;
        EXPECT_NEAR(s.area(), std::abs(signed_area(pts)), 1e-9) << name;
        // No triangle pokes out of a concave notch: every centroid is inside the outline.
        for (const Triangle& t : s.triangles()) {
            Point c{(t[0].x + t[1].x + t[2].x) / 3, (t[0].y + t[1].y + t[2].y) / 3};
            EXPECT_TRUE(dartfill_oracle::in_ring(pts, c)) << name;
        }
    }
}

TEST(DartfillShape, PathDataIsFlattenedAndTriangulated) {
    Shape leaf = Shape::from_path_data("leaf", leaf_path, 0.01);
    EXPECT_GT(leaf.outline().size(), 16u);
    EXPECT_NEAR(triangles_area(leaf), leaf.area(), 1e-9);
    // The lens's exact area is 2 * 84 = 168 (each cubic bounds 84 with its chord); flattening
    // to 0.01 cuts off less than the chords' sagitta times the perimeter.
    EXPECT_NEAR(leaf.area(), 168.0, 0.5);
    EXPECT_LT(leaf.area(), 168.0);
    EXPECT_NEAR(leaf.center().x, 10, 1e-9);
    EXPECT_NEAR(leaf.center().y, 0, 1e-9);
    EXPECT_NEAR(leaf.radius(), 10, 1e-9);
    // The pole lies inside, well away from the outline.
    EXPECT_TRUE(dartfill_oracle::in_ring(leaf.outline(), leaf.pole()));
    EXPECT_GT(dartfill_oracle::distance_to_ring(leaf.outline(), leaf.pole()), 4.0);
}

TEST(DartfillShape, ClockwiseInputIsNormalized) {
    auto pts = c_shape();
    std::reverse(pts.begin(), pts.end());
    Shape s = Shape::from_points("cw", pts);
    EXPECT_GT(signed_area(s.outline()), 0);
    EXPECT_NEAR(triangles_area(s), 10 * 10 - 8 * 6, 1e-9);
}

TEST(DartfillShape, BadShapesAreRefusedNamingThem) {
    std::string m = message_of([] {
        Shape::from_points("bowtie", {{0, 0}, {10, 10}, {10, 0}, {0, 10}});
    });
    EXPECT_NE(m.find("'bowtie'"), std::string::npos) << m;
    EXPECT_NE(m.find("intersects itself"), std::string::npos) << m;

    m = message_of([] { Shape::from_points("flat", {{0, 0}, {5, 5}, {10, 10}}); });
    EXPECT_NE(m.find("'flat'"), std::string::npos) << m;
    EXPECT_NE(m.find("zero area"), std::string::npos) << m;

    m = message_of([] { Shape::from_points("tiny", {{0, 0}, {1, 1}, {0, 0}}); });
    EXPECT_NE(m.find("'tiny'"), std::string::npos) << m;
    EXPECT_NE(m.find("at least 3"), std::string::npos) << m;

    m = message_of([] { Shape::from_points("nan", {{0, 0}, {1, NAN}, {0, 1}}); });
    EXPECT_NE(m.find("'nan'"), std::string::npos) << m;

    // Touching itself at a vertex (a pinched figure eight) is not simple either.
    m = message_of([] {
        Shape::from_points("pinch", {{0, 0}, {4, 0}, {2, 2}, {4, 4}, {0, 4}, {2, 2}});
    });
    EXPECT_NE(m.find("'pinch'"), std::string::npos) << m;

    m = message_of([] { Shape::from_path_data("garbage", "M 0 0 L 10 frog", -1); });
    EXPECT_NE(m.find("'garbage'"), std::string::npos) << m;
    EXPECT_NE(m.find("cannot parse"), std::string::npos) << m;

    m = message_of([] { Shape::from_path_data("two", "M 0 0 H 1 V 1 Z M 5 5 H 6 V 6 Z", -1); });
    EXPECT_NE(m.find("'two'"), std::string::npos) << m;

    m = message_of([] { ShapeSet().add_svg_file("/nonexistent/pebbles.svg"); });
    EXPECT_NE(m.find("/nonexistent/pebbles.svg"), std::string::npos) << m;
}

TEST(DartfillShape, SvgFileOutlinesBecomeShapes) {
    const acanthus::test::TempDir dir("dartfill");
    std::string file = dir / "dartfill_shapes.svg";
    std::ofstream(file) << R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100">
  <path d="M 0 0 H 10 V 2 H 2 V 8 H 10 V 10 H 0 Z"/>
  <g transform="translate(50 50)"><polygon points="0,0 10,0 5,8"/></g>
</svg>)svg";
    ShapeSet set;
    set.add_svg_file(file);
    ASSERT_EQ(set.size(), 2u);
    EXPECT_NEAR(set.area(0) + set.area(1), 52.0 + 40.0, 1e-6);

    std::string holed = dir / "dartfill_holed.svg";
    std::ofstream(holed) << R"(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100">
  <path fill-rule="evenodd" d="M 0 0 H 10 V 10 H 0 Z M 3 3 H 6 V 6 H 3 Z"/></svg>)";
    std::string m = message_of([&] { ShapeSet().add_svg_file(holed); });
    EXPECT_NE(m.find(holed), std::string::npos) << m;
    EXPECT_NE(m.find("holes"), std::string::npos) << m;
}

TEST(DartfillOverlap, TouchingIsNotOverlap) {
    Shape square = Shape::from_points("square", {{0, 0}, {1, 0}, {1, 1}, {0, 1}});
    PlacedShape a(square, 0, {{0.5, 0.5}, 0, 1});
    PlacedShape b(square, 0, {{1.5, 0.5}, 0, 1});
    PlacedShape c(square, 0, {{1.49, 0.5}, 0, 1});
    EXPECT_FALSE(shapes_overlap(a, b, 1e-9));
    EXPECT_TRUE(shapes_overlap(a, c, 1e-9));
}

TEST(DartfillOverlap, NestedConcaveShapesDoNotOverlapInTheNotch) {
    // A small square sits inside the notch of the C without touching it.
    Shape c = Shape::from_points("c", c_shape());
    Shape square = Shape::from_points("square", {{0, 0}, {1, 0}, {1, 1}, {0, 1}});
    PlacedShape placed_c(c, 0, {c.center(), 0, 1});
    PlacedShape inside_notch(square, 1, {{6, 5}, 0.3, 2});
    PlacedShape across_arm(square, 1, {{6, 1.5}, 0.3, 2});
    EXPECT_FALSE(shapes_overlap(placed_c, inside_notch, 1e-9));
    EXPECT_TRUE(shapes_overlap(placed_c, across_arm, 1e-9));
}

TEST(DartfillOverlap, AgreesWithPointSamplingOnTransformedConcaveShapes) {
    Shape s1 = Shape::from_points("star", star(5, 6, 2));
    Shape s2 = Shape::from_points("c", c_shape());
    Shape s3 = Shape::from_path_data("leaf", leaf_path, 0.05);
    const Shape* shapes[] = {&s1, &s2, &s3};
    Random rng(42);
    int overlapping = 0, apart = 0;
    for (int trial = 0; trial < 400; ++trial) {
        const Shape& a = *shapes[trial % 3];
        const Shape& b = *shapes[(trial / 3) % 3];
        PlacedShape pa(a, 0, {{0, 0}, rng.uniform(0, 2 * M_PI), rng.uniform(0.5, 1.5)});
        PlacedShape pb(b, 1,
                       {{rng.uniform(-14, 14), rng.uniform(-14, 14)},
                        rng.uniform(0, 2 * M_PI),
                        rng.uniform(0.5, 1.5)});
        bool exact = shapes_overlap(pa, pb, 1e-9);
        bool sampled = dartfill_oracle::sampled_overlap(pa.outline(), pb.outline(), 120, 1e-7);
        double shared = dartfill_oracle::intersection_area(pa.outline(), pb.outline());
        // A sampled common interior point proves overlap; an overlap claim needs shared area.
        if (sampled) {
            EXPECT_TRUE(exact) << "trial " << trial;
        }
        if (exact) {
            EXPECT_GT(shared, 0.0) << "trial " << trial;
        }
        if (shared > 1e-6) {
            EXPECT_TRUE(exact) << "trial " << trial << " area " << shared;
        }
        (exact ? overlapping : apart)++;
    }
    // The placements exercise both outcomes.
    EXPECT_GT(overlapping, 50);
    EXPECT_GT(apart, 50);
}

TEST(DartfillOverlap, TransformRotatesAndScalesAboutTheBoxCentre) {
    Shape c = Shape::from_points("c", c_shape());
    PlacedShape p(c, 0, {{100, 50}, M_PI / 2, 2});
    // The box centre (5, 5) goes to the position; offsets turn a quarter (x, y) -> (-y, x) and
    // double.
    EXPECT_NEAR(p.bounds().x0, 90, 1e-9);
    EXPECT_NEAR(p.bounds().x1, 110, 1e-9);
    EXPECT_NEAR(p.bounds().y0, 40, 1e-9);
    EXPECT_NEAR(p.bounds().y1, 60, 1e-9);
    EXPECT_NEAR(p.area(), 4 * 52, 1e-9);
    EXPECT_TRUE(p.contains({100, 42}));   // the C's back (1, 5) -> offset (-4, 0) -> (0, -8)
    EXPECT_FALSE(p.contains({100, 54}));  // the notch (7, 5)
    EXPECT_TRUE(p.contains({92, 54}));    // the lower arm (7, 9)
}
