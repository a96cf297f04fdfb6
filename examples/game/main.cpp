// m3g_game: the ported-game example, headless. Plays the part of a
// handset's application manager: startApp(), then per frame the key events
// of a script, tick(time), paint(Graphics) and a PNG of the Graphics.
//   m3g_game [--frames N] [--fps F] [--size WxH] [-o PATTERN] [--keys SCRIPT]
// PATTERN: "{frame}" is the zero-padded frame number (default game_{frame}.png).
// SCRIPT: comma-separated ACTION@FRAME, ACTION one of UP DOWN LEFT RIGHT FIRE;
// the default script picks the robot, then each crate, then one crate again.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <m3g/m3g.h>
#include <m3g/vk/Vulkan.h>

#include "CliArgs.h"
#include "ImageIO.h"
#include "RenderOptions.h"
#include "RobotGame.h"

namespace {

// Frame numbers at 12 fps. The cursor starts in the middle of the view (the
// robot); crates sit at (0.2, 0.7), (0.8, 0.7) and (0.5, 0.3).
constexpr const char* kDefaultScript =
    "FIRE@2,LEFT@4,LEFT@5,LEFT@6,DOWN@7,DOWN@8,FIRE@9,"
    "RIGHT@11,RIGHT@12,RIGHT@13,RIGHT@14,RIGHT@15,RIGHT@16,FIRE@17,"
    "LEFT@19,LEFT@20,LEFT@21,UP@22,UP@23,UP@24,UP@25,FIRE@26,FIRE@28";

struct KeyEvent {
    int frame;
    int action;
};

std::vector<KeyEvent> parseScript(const std::string& text) {
    static const std::map<std::string, int> kActions = {{"UP", m3ggame::UP},
                                                        {"DOWN", m3ggame::DOWN},
                                                        {"LEFT", m3ggame::LEFT},
                                                        {"RIGHT", m3ggame::RIGHT},
                                                        {"FIRE", m3ggame::FIRE}};
    std::vector<KeyEvent> events;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        const auto at = item.find('@');
        const auto action = kActions.find(item.substr(0, at));
        const auto frame = at == std::string::npos ? std::nullopt : m3gcli::parseInt(item.substr(at + 1));
        if (action == kActions.end() || !frame || *frame < 0)
            throw std::invalid_argument("--keys: '" + item + "' is not ACTION@FRAME (UP DOWN LEFT RIGHT FIRE)");
        events.push_back({*frame, action->second});
    }
    return events;
}

}  // namespace

int main(int argc, char** argv) {
    int frames = 36, width = 320, height = 240;
    float fps = 12.0f;
    std::string pattern = "game_{frame}.png", script = kDefaultScript;
    std::vector<KeyEvent> events;
    try {
        for (int i = 1; i < argc; ++i) {
            const std::string a = argv[i];
            auto value = [&]() -> std::string {
                if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
                return argv[++i];
            };
            if (a == "--frames") {
                const auto n = m3gcli::parseInt(value());
                if (!n || *n <= 0) throw std::invalid_argument("--frames takes a positive integer");
                frames = *n;
            } else if (a == "--fps") {
                const auto f = m3gcli::parseFloat(value());
                if (!f || *f <= 0) throw std::invalid_argument("--fps takes a positive number");
                fps = *f;
            } else if (a == "--size") {
                if (!m3gcli::parseSize(value(), width, height))
                    throw std::invalid_argument("--size takes WxH, e.g. 320x240");
            } else if (a == "-o") {
                pattern = value();
            } else if (a == "--keys") {
                script = value();
            } else {
                throw std::invalid_argument("unknown argument '" + a + "'");
            }
        }
        events = parseScript(script);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "m3g_game: %s\nusage: m3g_game [--frames N] [--fps F] [--size WxH] [-o PATTERN] [--keys SCRIPT]\n",
                     e.what());
        return 2;
    }

    try {
        m3ggame::RobotGame game(width, height, [](const std::string& line) { std::printf("%s\n", line.c_str()); });
        game.startApp();
        m3g::Ref<m3g::Graphics> screen(new m3g::Graphics(width, height));  // the Canvas's Graphics
        for (int frame = 0; frame < frames; ++frame) {
            const int time = static_cast<int>(static_cast<double>(frame) * 1000.0 / fps + 0.5);
            game.tick(time);
            for (const KeyEvent& e : events)
                if (e.frame == frame) game.keyPressed(e.action);
            game.paint(*screen);
            const std::string path = m3gcli::frameFileName(pattern, frame, frames);
            const std::filesystem::path parent = std::filesystem::path(path).parent_path();
            if (!parent.empty()) std::filesystem::create_directories(parent);
            m3gcli::writePng(path, m3gcli::fromGraphics(*screen), false);
        }
        game.destroyApp(true);
        std::printf("wrote %d frames (%dx%d, %.1f fps); score %d\n", frames, width, height, fps, game.score());
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "m3g_game: %s\n", e.what());
        return 1;
    }
}
