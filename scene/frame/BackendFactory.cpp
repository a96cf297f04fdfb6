// The back end a Graphics3D makes at its first draw (frame/FrameBackend.h).
#include <atomic>

#include <m3g/frame/FrameBackend.h>

namespace m3g::frame {

namespace {
// Constant-initialised, so a back end library may install its factory from
// a static initialiser in any order.
std::atomic<BackendFactory> gFactory{nullptr};
}  // namespace

void setBackendFactory(BackendFactory factory) noexcept { gFactory.store(factory); }

BackendFactory backendFactory() noexcept { return gFactory.load(); }

}  // namespace m3g::frame
