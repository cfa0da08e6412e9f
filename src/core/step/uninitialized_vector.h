// A std::vector whose resize leaves new elements uninitialized (default-initialized) instead of
// zero-filling them, for work arrays that are written before they are read. Internal to the core.
#pragma once
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace clothtear {

// std::allocator but for construct() without arguments, which default-initializes. The limit's
// expand makes room for every spring it may list and writes only those it takes (limit.cpp), and
// std::allocator zero-filled all that room first: 1.1 % of the instructions of a tearing drag at
// 128 a side (bench/README.md, "Where the tearing drag's instructions go").
template <class T>
struct UninitializedAllocator : std::allocator<T> {
    template <class U>
    struct rebind {
        using other = UninitializedAllocator<U>;
    };
    UninitializedAllocator() = default;
    template <class U>
    UninitializedAllocator(const UninitializedAllocator<U>&) noexcept {}
    template <class U>
    void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
        ::new (static_cast<void*>(p)) U;
    }
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        std::construct_at(p, std::forward<Args>(args)...);
    }
};

template <class T>
using UninitializedVector = std::vector<T, UninitializedAllocator<T>>;

} // namespace clothtear
