// A program outside the m3g-vk tree that links only m3g::scene (no Vulkan):
// loads SCENE.m3g, animates it, saves its World with the writer, loads the
// bytes back and saves that again. Exit 0 when the reloaded file has a
// World, as many objects as the file, and the second save is as long as the
// first (the same objects and fields; orientations may move in their last
// bits through the file's angle-axis form), 1 otherwise
// (tests/package/run.sh).
#include <cstdio>
#include <exception>
#include <span>
#include <vector>

#include <m3g/m3g.h>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s SCENE.m3g\n", argv[0]);
        return 2;
    }
    try {
        const m3g::LoadResult first = m3g::Loader::loadDetailed(argv[1]);
        m3g::World* world = nullptr;
        for (const auto& o : first.objects)
            if (auto* w = dynamic_cast<m3g::World*>(o.get())) world = w;
        if (!world) {
            std::fprintf(stderr, "scene_check: no World in %s\n", argv[1]);
            return 1;
        }
        world->animate(500);
        m3g::Object3D* roots[] = {world};
        const std::vector<std::uint8_t> bytes = m3g::Saver::save(roots);
        const m3g::LoadResult again = m3g::Loader::loadDetailed(std::span<const std::uint8_t>(bytes), 0);
        m3g::World* reloaded = nullptr;
        for (const auto& o : again.objects)
            if (auto* w = dynamic_cast<m3g::World*>(o.get())) reloaded = w;
        std::vector<std::uint8_t> second;
        if (reloaded) {
            m3g::Object3D* roots2[] = {reloaded};
            second = m3g::Saver::save(roots2);
        }
        std::printf("scene_check: %zu objects loaded, %zu after save and reload, World %s, saves of %zu and %zu bytes\n",
                    first.objects.size(), again.objects.size(), reloaded ? "kept" : "lost", bytes.size(), second.size());
        return reloaded && again.objects.size() == first.objects.size() && second.size() == bytes.size() ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "scene_check: %s\n", e.what());
        return 1;
    }
}
