// A program outside the m3g-vk tree, built against an installed package
// (tests/package/run.sh, with find_package and with pkg-config): loads
// SCENE.m3g, renders its World at time 0 into an RGBA Image2D the size of
// REFERENCE.png, and compares the two. REFERENCE.png is the build tree's
// `m3g render` of the same file, so the installed library must draw what the
// tree draws. Exit 0 when every channel is within 2 and the render is not
// one flat colour (a blank frame must not pass), 1 otherwise.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <vector>

#include <m3g/m3g.h>

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: %s SCENE.m3g REFERENCE.png\n", argv[0]);
        return 2;
    }
    try {
        m3g::World* world = nullptr;
        const auto objects = m3g::Loader::load(argv[1]);
        for (const auto& o : objects)
            if (auto* w = dynamic_cast<m3g::World*>(o.get())) world = w;
        const auto loaded = m3g::Loader::load(argv[2]);
        auto* reference = loaded.empty() ? nullptr : dynamic_cast<m3g::Image2D*>(loaded[0].get());
        if (!world || !reference) {
            std::fprintf(stderr, "render_check: no World in %s or no image in %s\n", argv[1], argv[2]);
            return 1;
        }
        m3g::Ref<m3g::Image2D> target(new m3g::Image2D(m3g::Image2D::RGBA, reference->getWidth(), reference->getHeight()));
        world->animate(0);
        m3g::Graphics3D* g = m3g::Graphics3D::getInstance();
        g->bindTarget(target.get(), true, 0);
        g->render(world);
        g->releaseTarget();

        std::vector<std::uint8_t> got, want;
        target->getPixelsRGBA8(got);
        reference->getPixelsRGBA8(want);
        int worst = 0;
        std::size_t distinct = 0;
        for (std::size_t i = 0; i < got.size(); i += 4) {
            for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(got[i + c]) - int(want[i + c])));
            if (got[i] != got[0] || got[i + 1] != got[1] || got[i + 2] != got[2]) ++distinct;
        }
        std::printf("render_check: %dx%d, largest channel difference %d, %zu pixels unlike the first\n",
                    target->getWidth(), target->getHeight(), worst, distinct);
        return worst <= 2 && distinct * 100 >= got.size() / 4 ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "render_check: %s\n", e.what());
        return 1;
    }
}
