#include "symmetry/image_element.hpp"

#include <acanthus/rule_call.hpp>
#include <atomic>
#include <memory>
#include <mutex>
#include <thread>

namespace acanthus::detail {

void transform_proxy(const Proxy& in, const Isometry& g, Proxy& out) {
    switch (in.kind()) {
        case ProxyKind::point:
            static_cast<PointProxy&>(out).set(g.apply(static_cast<const PointProxy&>(in).point()));
            break;
        case ProxyKind::circle: {
            const auto& c = static_cast<const CircleProxy&>(in);
            static_cast<CircleProxy&>(out).set(g.apply(c.center), c.radius);
            break;
        }
        case ProxyKind::arc: {
            // A reflection turns the counter-clockwise arc s..e into one from e's image to s's.
            const auto& a = static_cast<const ArcProxy&>(in);
            const double sweep = a.end - a.start;
            const double start = g.apply_angle(g.reverses() ? a.end : a.start);
            static_cast<ArcProxy&>(out).set(g.apply(a.center), a.radius, start, start + sweep);
            break;
        }
        case ProxyKind::linesegment: {
            const auto& l = static_cast<const LineSegmentProxy&>(in);
            static_cast<LineSegmentProxy&>(out).set(g.apply(l.p0), g.apply(l.p1));
            break;
        }
        case ProxyKind::bezier: {
            const auto& b = static_cast<const BezierProxy&>(in);
            static_cast<BezierProxy&>(out).set(g.apply(b.c[0]), g.apply(b.c[1]), g.apply(b.c[2]),
                                               g.apply(b.c[3]));
            break;
        }
        case ProxyKind::polygon: {
            const auto& p = static_cast<const PolygonProxy&>(in);
            std::vector<Point> points;
            points.reserve(p.points.size());
            for (Point q : p.points) points.push_back(g.apply(q));
            static_cast<PolygonProxy&>(out).set(std::move(points));
            break;
        }
    }
}

ImageElement::ImageElement(const Element& original, const Isometry& transform)
    : original_(&original), transform_(transform) {
    sterile = true;
    depth = original.depth;
    count_ = original.proxy_count();
    if (count_ > 1) more_.resize(count_ - 1);
    for (std::size_t k = 0; k < count_; ++k) {
        const Proxy& p = original.proxy(k);
        AnyProxy& out = slot(k);
        switch (p.kind()) {
            case ProxyKind::point:
                out.emplace<PointProxy>();
                break;
            case ProxyKind::circle:
                out.emplace<CircleProxy>();
                break;
            case ProxyKind::arc:
                out.emplace<ArcProxy>();
                break;
            case ProxyKind::linesegment:
                out.emplace<LineSegmentProxy>();
                break;
            case ProxyKind::bezier:
                out.emplace<BezierProxy>();
                break;
            case ProxyKind::polygon:
                out.emplace<PolygonProxy>();
                break;
        }
        transform_proxy(p, transform, proxy(k));
    }
}

void ImageElement::set_transform(const Isometry& transform) {
    transform_ = transform;
    for (std::size_t k = 0; k < count_; ++k)
        transform_proxy(original_->proxy(k), transform, proxy(k));
}

namespace {

// The pool's lock: taken for a few instructions, by one growth at a time but for rare overlaps
// (a mutex's lock and unlock cost more than the pool's own work).
class SpinLock {
  public:
    void lock() {
        while (flag_.test_and_set(std::memory_order_acquire)) std::this_thread::yield();
    }
    void unlock() { flag_.clear(std::memory_order_release); }

  private:
    std::atomic_flag flag_ = ATOMIC_FLAG_INIT;
};

// Blocks of one size carved out of chunks; a freed block goes back on the free list. The
// chunks are freed together when no block is in use (a growth's images all go at its end).
class BlockPool {
  public:
    explicit BlockPool(std::size_t size)
        : size_((size + alignof(std::max_align_t) - 1) / alignof(std::max_align_t) *
                alignof(std::max_align_t)) {}
    void* take() {
        const std::lock_guard<SpinLock> lock(lock_);
        ++live_;
        if (free_) {
            void* p = free_;
            free_ = *static_cast<void**>(p);
            return p;
        }
        if (chunks_.empty() || used_ == kBlocks) {
            // Not value-initialised: each block is constructed when handed out.
            chunks_.push_back(std::unique_ptr<std::max_align_t[]>(
                new std::max_align_t[size_ * kBlocks / sizeof(std::max_align_t)]));
            used_ = 0;
        }
        return reinterpret_cast<char*>(chunks_.back().get()) + size_ * used_++;
    }
    void give(void* p) {
        const std::lock_guard<SpinLock> lock(lock_);
        if (--live_ == 0) {  // nothing in use: no chunk is needed any more
            chunks_.clear();
            free_ = nullptr;
            used_ = 0;
            return;
        }
        *static_cast<void**>(p) = free_;
        free_ = p;
    }

  private:
    static constexpr std::size_t kBlocks = 512;
    const std::size_t size_;
    SpinLock lock_;
    std::vector<std::unique_ptr<std::max_align_t[]>> chunks_;
    std::size_t used_ = 0;  // blocks of the last chunk handed out
    std::size_t live_ = 0;
    void* free_ = nullptr;
};

BlockPool& image_pool() {
    static BlockPool* pool = new BlockPool(sizeof(ImageElement));  // outlives every image
    return *pool;
}

}  // namespace

void* ImageElement::operator new(std::size_t size) {
    (void)size;  // sizeof(ImageElement): the class is final
    void* p = image_pool().take();
    if (RuleCall* call = RuleCall::current()) call->track(static_cast<Element*>(p));
    return p;
}

void ImageElement::operator delete(void* p) noexcept {
    if (!p) return;
    if (RuleCall* call = RuleCall::current()) call->untrack(static_cast<Element*>(p));
    image_pool().give(p);
}

Proxy& ImageElement::proxy(std::size_t k) {
    return std::visit([](auto& p) -> Proxy& { return p; }, slot(k));
}

}  // namespace acanthus::detail
