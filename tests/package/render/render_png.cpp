// The program of docs/library.md ("A program: load a file, render it,
// write a PNG"), kept here word for word so that CI builds it against the
// installed package and compares its PNG with `m3g render`'s
// (tests/package/run.sh).
#include <cstdio>
#include <m3g/m3g.h>

int main(int argc, char** argv) {
    if (argc != 3) return std::fprintf(stderr, "usage: %s in.m3g out.png\n", argv[0]), 2;
    try {
        m3g::World* world = nullptr;
        const auto objects = m3g::Loader::load(argv[1]);     // keeps the roots alive
        for (const auto& o : objects)
            if (auto* w = dynamic_cast<m3g::World*>(o.get())) world = w;
        if (!world) return std::fprintf(stderr, "no World in %s\n", argv[1]), 1;
        m3g::Ref<m3g::Image2D> image(new m3g::Image2D(m3g::Image2D::RGBA, 320, 240));
        world->animate(0);
        m3g::Graphics3D* g3d = m3g::Graphics3D::getInstance();
        g3d->bindTarget(image.get());
        g3d->render(world);
        g3d->releaseTarget();                                 // the pixels are in `image` now
        m3g::writePng(*image, argv[2]);
    } catch (const std::exception& e) {                       // m3g::Exception and VulkanError derive from it
        return std::fprintf(stderr, "%s\n", e.what()), 1;
    }
}
