// libFuzzer target for the SVG region loader: any input is either a region or an InputError.
#include <acanthus/error.hpp>
#include <acanthus/region.hpp>
#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view svg(reinterpret_cast<const char*>(data), size);
    try {
        acanthus::Region region = acanthus::Region::from_svg_string(svg, "fuzz.svg");
        // Exercise the queries the engine makes on every loaded region.
        acanthus::Rect b = region.bounds();
        (void)region.contains(b.center());
        (void)region.distance_to_boundary(b.center());
        (void)region.rings(0.01 * (b.width() + b.height()));
    } catch (const acanthus::InputError&) {
    }
    return 0;
}
