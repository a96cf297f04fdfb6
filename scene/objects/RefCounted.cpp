// Which M3G objects their count may free (api/m3g/Ref.h): operator new
// records the block it returns on a per-thread list, and RefCounted's
// constructor, which runs on the same thread, claims the block that contains
// it. The list holds more than one block because C++ allocates before it
// evaluates the constructor's arguments: in `new Mesh(new VertexBuffer(),
// ...)` the Mesh's block is handed out before the VertexBuffer's, whose
// constructor claims its own block first.
#include <m3g/Ref.h>

#include <new>
#include <vector>

namespace m3g {

namespace {

struct Block {
    const char* begin;
    std::size_t size;
};

/// This thread's blocks not yet claimed; a few at most (one per `new` whose
/// constructor has not yet run).
std::vector<Block>& pending() noexcept {
    thread_local std::vector<Block> blocks;
    return blocks;
}

}  // namespace

void* RefCounted::operator new(std::size_t size) {
    void* block = ::operator new(size);
    try {
        pending().push_back({static_cast<const char*>(block), size});
    } catch (...) {
        ::operator delete(block);
        throw;
    }
    return block;
}

void RefCounted::operator delete(void* block) noexcept {
    // Construction failed (the block is still listed) or the object is
    // deleted after its life on the heap (it is not).
    auto& blocks = pending();
    for (auto it = blocks.rbegin(); it != blocks.rend(); ++it)
        if (it->begin == block) {
            blocks.erase(std::next(it).base());
            break;
        }
    ::operator delete(block);
}

std::size_t RefCounted::pendingAllocations() noexcept { return pending().size(); }

bool RefCounted::claimAllocation(const void* self) noexcept {
    const auto* p = static_cast<const char*>(self);
    auto& blocks = pending();
    // Newest first: the innermost `new` is constructed first.
    for (auto it = blocks.rbegin(); it != blocks.rend(); ++it)
        if (p >= it->begin && p < it->begin + it->size) {
            blocks.erase(std::next(it).base());
            return true;
        }
    return false;
}

}  // namespace m3g
