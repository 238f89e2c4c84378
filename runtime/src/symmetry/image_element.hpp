// An image of a placed element under a symmetry transformation: the original's type, its
// proxies carried over by the transformation. The growth loop places images beside the
// fundamental elements so that the field, the exclude list and intersection() see them; they are
// sterile, and drawn as their original under the transformation.
#pragma once

#include <acanthus/element.hpp>
#include <type_traits>
#include <typeinfo>
#include <variant>
#include <vector>

#include "symmetry/isometry.hpp"

namespace acanthus::detail {

// The proxy `in` carried over by `g` into `out`, a proxy of the same kind.
void transform_proxy(const Proxy& in, const Isometry& g, Proxy& out);

class ImageElement final : public Element {
  public:
    ImageElement(const Element& original, const Isometry& transform);

    const ElementType& type() const override { return original_->type(); }
    std::size_t proxy_count() const override { return count_; }
    Proxy& proxy(std::size_t k) override;

    // Images come by the thousand, each built and freed once: they are carved out of shared
    // chunks (freed when the last image is), with the tracking Element's own operator new does.
    static void* operator new(std::size_t size);
    static void operator delete(void* p) noexcept;

    // Carries the original's proxies over by another transformation, in place.
    void set_transform(const Isometry& transform);

    const Element& original() const { return *original_; }
    const Isometry& transform() const { return transform_; }

  private:
    using AnyProxy = std::variant<PointProxy, CircleProxy, ArcProxy, LineSegmentProxy, BezierProxy,
                                  PolygonProxy>;
    AnyProxy& slot(std::size_t k) { return k == 0 ? first_ : more_[k - 1]; }
    const Element* original_;
    Isometry transform_;
    // The first proxy inline (most elements have one): an image costs one allocation, not two.
    std::size_t count_ = 0;
    AnyProxy first_;
    std::vector<AnyProxy> more_;
};

static_assert(std::is_final_v<ImageElement>, "as_image() compares exact types");

// The element as an image, or null for a fundamental element. ImageElement is final, so its
// type is the element's exact type: a type_info comparison, cheaper than a dynamic_cast (the
// growth loop asks of every element near C and the output of every element).
inline const ImageElement* as_image(const Element& e) {
    return typeid(e) == typeid(ImageElement) ? static_cast<const ImageElement*>(&e) : nullptr;
}
// The fundamental element e stands for (e itself when it is one).
inline const Element& original_of(const Element& e) {
    const ImageElement* image = as_image(e);
    return image ? image->original() : e;
}

}  // namespace acanthus::detail
