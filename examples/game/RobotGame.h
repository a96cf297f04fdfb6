// The ported game: a Canvas that renders the World with Graphics3D, draws an
// immediate-mode HUD (a cursor and one square per collected crate) and
// picks through the camera where the cursor is. LEFT/RIGHT/UP/DOWN move the
// cursor, FIRE picks: the robot jumps, a crate is collected. docs/porting.md
// sets this code beside the Java it stands for.
#pragma once

#include <functional>
#include <string>

#include <m3g/m3g.h>

#include "GameCanvas.h"
#include "RobotWorld.h"

namespace m3ggame {

class RobotGame : public GameCanvas {
public:
    /// `log` receives one line per game event (picks, jumps, score).
    RobotGame(int width, int height, std::function<void(const std::string&)> log);

    void startApp() override;
    void tick(int timeMs) override;
    void paint(m3g::Graphics& g) override;
    void keyPressed(int gameAction) override;

    int score() const noexcept { return score_; }
    /// Cursor in viewport coordinates: (0, 0) top left, (1, 1) bottom right.
    float cursorX() const noexcept { return cursorX_; }
    float cursorY() const noexcept { return cursorY_; }

private:
    void fire();
    void drawHud(m3g::Graphics3D& g3d);

    int width_, height_;
    std::function<void(const std::string&)> log_;
    RobotWorld scene_;
    int time_ = 0;
    float cursorX_ = 0.5f, cursorY_ = 0.5f;
    int score_ = 0;
    bool collected_[3] = {false, false, false};

    // Immediate-mode HUD: one unit quad, white and yellow, drawn unlit over
    // the scene through a parallel camera.
    m3g::Ref<m3g::Camera> hudCamera_;
    m3g::Ref<m3g::VertexBuffer> white_, yellow_;
    m3g::Ref<m3g::IndexBuffer> quad_;
    m3g::Ref<m3g::Appearance> hudLook_;
};

}  // namespace m3ggame
