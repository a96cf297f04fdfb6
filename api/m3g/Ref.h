// Intrusive reference counting for M3G objects.
//
// M3G objects are shared everywhere (one Appearance used by many Meshes) and a
// Java port expects "hold a reference, never delete". Every Object3D derives
// from RefCounted; Ref<T> holds one strong reference; WeakRef<T> observes an
// object without keeping it alive (used for back references that would
// otherwise form cycles, such as alignment references to an ancestor).
#pragma once

#include <m3g/Export.h>

#include <atomic>
#include <cstddef>
#include <functional>
#include <utility>

namespace m3g {

class RefCounted;

namespace detail {
// Shared between an object and its weak references; outlives the object.
struct WeakControl {
    std::atomic<int> refs{1};
    RefCounted* object = nullptr;
    void addRef() noexcept { refs.fetch_add(1, std::memory_order_relaxed); }
    void release() noexcept {
        if (refs.fetch_sub(1, std::memory_order_acq_rel) == 1) delete this;
    }
};
}  // namespace detail

/// Base of every reference-counted M3G object. A new object starts with a
/// count of zero; the first Ref<T> that takes it owns it.
///
/// Only an object made with `new` is freed by its count. One that lives on
/// the stack, as a member, a static or in an array (`Graphics g(320, 240);
/// g3d.bindTarget(&g);`) is never deleted when its last Ref goes: its owner
/// destroys it, as C++ does for any such object. The class's operator new
/// records each block it hands out, and the constructor claims the block it
/// lies in (docs/porting.md, "Objects and ownership").
class M3G_API RefCounted {
public:
    void addRef() const noexcept { refs_.fetch_add(1, std::memory_order_relaxed); }
    void release() const noexcept {
        if (refs_.fetch_sub(1, std::memory_order_acq_rel) == 1 && heap_) delete this;
    }
    /// Current number of strong references (diagnostics and tests).
    int getRefCount() const noexcept { return refs_.load(std::memory_order_relaxed); }
    /// Whether this object was made with `new`, so its last Ref frees it.
    bool isHeapAllocated() const noexcept { return heap_; }

    /// The weak control block of this object, created on first use.
    detail::WeakControl* weakControl() const {
        if (!weak_) {
            weak_ = new detail::WeakControl;
            weak_->object = const_cast<RefCounted*>(this);
        }
        return weak_;
    }

    /// Allocation of every M3G object: records the block until the object's
    /// constructor claims it (or, if construction fails, operator delete).
    static void* operator new(std::size_t size);
    static void operator delete(void* block) noexcept;
    /// Blocks allocated on this thread whose object has not been constructed
    /// yet (diagnostics and tests: 0 between statements).
    static std::size_t pendingAllocations() noexcept;

protected:
    RefCounted() noexcept : heap_(claimAllocation(this)) {}
    // A copy is a new object: it starts unowned and with no weak observers.
    RefCounted(const RefCounted&) noexcept : heap_(claimAllocation(this)) {}
    RefCounted& operator=(const RefCounted&) noexcept { return *this; }
    virtual ~RefCounted() {
        if (weak_) {
            weak_->object = nullptr;
            weak_->release();
        }
    }

private:
    /// True when `self` lies in a block operator new handed out on this
    /// thread and no object has claimed yet; the block is then claimed.
    static bool claimAllocation(const void* self) noexcept;

    mutable std::atomic<int> refs_{0};
    mutable detail::WeakControl* weak_ = nullptr;
    bool heap_ = false;
};

/// A strong, nullable reference. Converts implicitly from and to T* so that
/// ported Java code reads naturally: `Ref<Mesh> m = new Mesh(vb, ib, ap);
/// group->addChild(m);`.
template <class T>
class M3G_API Ref {
public:
    Ref() noexcept = default;
    Ref(std::nullptr_t) noexcept {}
    Ref(T* p) noexcept : p_(p) { if (p_) p_->addRef(); }
    Ref(const Ref& o) noexcept : p_(o.p_) { if (p_) p_->addRef(); }
    Ref(Ref&& o) noexcept : p_(std::exchange(o.p_, nullptr)) {}
    template <class U>
    Ref(const Ref<U>& o) noexcept : p_(o.get()) { if (p_) p_->addRef(); }
    ~Ref() { if (p_) p_->release(); }

    // Takes the new reference before releasing the old one, so self-assignment
    // and assignment of an object reachable only through the old one are safe.
    Ref& operator=(const Ref& o) noexcept { reset(o.p_); return *this; }
    Ref& operator=(Ref&& o) noexcept {
        T* old = std::exchange(p_, std::exchange(o.p_, nullptr));
        if (old) old->release();
        return *this;
    }
    Ref& operator=(T* p) noexcept { reset(p); return *this; }

    void reset(T* p = nullptr) noexcept {
        if (p) p->addRef();
        T* old = std::exchange(p_, p);
        if (old) old->release();
    }

    T* get() const noexcept { return p_; }
    T* operator->() const noexcept { return p_; }
    T& operator*() const noexcept { return *p_; }
    operator T*() const noexcept { return p_; }
    explicit operator bool() const noexcept { return p_ != nullptr; }

private:
    T* p_ = nullptr;
};

/// Creates a T with `new` and returns it already owned.
template <class T, class... Args>
Ref<T> make(Args&&... args) {
    return Ref<T>(new T(std::forward<Args>(args)...));
}

/// A weak reference: does not keep the object alive; get() becomes null once
/// the object is destroyed.
template <class T>
class M3G_API WeakRef {
public:
    WeakRef() noexcept = default;
    WeakRef(T* p) { assign(p); }
    WeakRef(const WeakRef& o) noexcept : c_(o.c_) { if (c_) c_->addRef(); }
    WeakRef& operator=(const WeakRef& o) noexcept {
        if (o.c_) o.c_->addRef();
        if (c_) c_->release();
        c_ = o.c_;
        return *this;
    }
    WeakRef& operator=(T* p) { WeakRef tmp(p); std::swap(c_, tmp.c_); return *this; }
    ~WeakRef() { if (c_) c_->release(); }

    /// The object, or null if it was never set or has been destroyed.
    T* get() const noexcept { return c_ && c_->object ? static_cast<T*>(c_->object) : nullptr; }
    /// True if this reference was set to an object that no longer exists.
    bool expired() const noexcept { return c_ && !c_->object; }

private:
    void assign(T* p) {
        if (p) { c_ = p->weakControl(); c_->addRef(); }
    }
    detail::WeakControl* c_ = nullptr;
};

template <class T, class U>
bool operator==(const Ref<T>& a, const Ref<U>& b) noexcept { return a.get() == b.get(); }

}  // namespace m3g

template <class T>
struct std::hash<m3g::Ref<T>> {
    std::size_t operator()(const m3g::Ref<T>& r) const noexcept { return std::hash<T*>()(r.get()); }
};
