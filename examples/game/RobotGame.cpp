#include "RobotGame.h"

#include <algorithm>
#include <cstdio>

namespace m3ggame {

using namespace m3g;

RobotGame::RobotGame(int width, int height, std::function<void(const std::string&)> log)
    : width_(width), height_(height), log_(std::move(log)) {}

void RobotGame::startApp() {
    const float aspect = static_cast<float>(width_) / static_cast<float>(height_);
    scene_ = buildRobotWorld(aspect);

    // The HUD camera: 2 units high (y -1..1), aspect * 2 wide, looking down -Z.
    hudCamera_ = new Camera();
    hudCamera_->setParallel(2.0f, aspect, 0.1f, 10.0f);
    Ref<VertexArray> corners(new VertexArray(4, 3, 1));
    const std::int8_t xyz[12] = {-1, -1, 0, 1, -1, 0, -1, 1, 0, 1, 1, 0};
    corners->set(0, 4, std::span<const std::int8_t>(xyz));
    const float noBias[3] = {0, 0, 0};
    white_ = new VertexBuffer();
    white_->setPositions(corners.get(), 1.0f, noBias);
    white_->setDefaultColor(static_cast<int>(0xFFFFFFFFu));
    yellow_ = new VertexBuffer();
    yellow_->setPositions(corners.get(), 1.0f, noBias);
    yellow_->setDefaultColor(static_cast<int>(0xFFFFD020u));
    const int lengths[1] = {4};
    quad_ = new TriangleStripArray(0, lengths);
    hudLook_ = new Appearance();
    Ref<CompositingMode> overlay(new CompositingMode());
    overlay->setDepthTestEnable(false);
    overlay->setDepthWriteEnable(false);
    hudLook_->setCompositingMode(overlay.get());
    Ref<PolygonMode> noCull(new PolygonMode());
    noCull->setCulling(PolygonMode::CULL_NONE);
    hudLook_->setPolygonMode(noCull.get());
}

void RobotGame::tick(int timeMs) {
    time_ = timeMs;
    scene_.world->animate(time_);
}

void RobotGame::paint(Graphics& g) {
    Graphics3D* g3d = Graphics3D::getInstance();
    g3d->bindTarget(&g);
    try {
        g3d->render(scene_.world.get());
        drawHud(*g3d);
    } catch (...) {
        g3d->releaseTarget();  // Java's finally
        throw;
    }
    g3d->releaseTarget();
}

void RobotGame::drawHud(Graphics3D& g3d) {
    const float aspect = static_cast<float>(width_) / static_cast<float>(height_);
    g3d.setCamera(hudCamera_.get(), nullptr);
    g3d.resetLights();
    auto box = [&](VertexBuffer* color, float x, float y, float halfW, float halfH) {
        Transform t;
        t.postTranslate(x, y, -1.0f);
        t.postScale(halfW, halfH, 1.0f);
        g3d.render(color, quad_.get(), hudLook_.get(), &t);
    };
    // The cursor: a cross at the viewport point (cursorX, cursorY).
    const float x = (2.0f * cursorX_ - 1.0f) * aspect, y = 1.0f - 2.0f * cursorY_;
    box(white_.get(), x, y, 0.08f, 0.012f);
    box(white_.get(), x, y, 0.012f, 0.08f);
    // One square per collected crate, top left.
    for (int i = 0; i < score_; ++i) box(yellow_.get(), -aspect + 0.12f + 0.16f * static_cast<float>(i), 0.88f, 0.06f, 0.06f);
}

void RobotGame::keyPressed(int gameAction) {
    constexpr float kStep = 0.1f;
    switch (gameAction) {
        case LEFT: cursorX_ = std::max(0.0f, cursorX_ - kStep); break;
        case RIGHT: cursorX_ = std::min(1.0f, cursorX_ + kStep); break;
        case UP: cursorY_ = std::max(0.0f, cursorY_ - kStep); break;
        case DOWN: cursorY_ = std::min(1.0f, cursorY_ + kStep); break;
        case FIRE: fire(); break;
        default: break;
    }
}

void RobotGame::fire() {
    // Group.pick(scope, x, y, camera, ri): the ray through the cursor.
    RayIntersection ri;
    char line[160];
    if (!scene_.world->pick(-1, cursorX_, cursorY_, scene_.camera.get(), &ri)) {
        std::snprintf(line, sizeof line, "t=%d ms: cursor (%.1f, %.1f): nothing there", time_, cursorX_, cursorY_);
        log_(line);
        return;
    }
    Ref<Node> hit = ri.getIntersected();
    const int id = hit->getUserID();
    if (id == kRobotID) {
        // Restart the one-shot jump: active for its 600 ms from now.
        scene_.jump->setActiveInterval(time_, time_ + 600);
        scene_.jump->setPosition(0.0f, time_);
        std::snprintf(line, sizeof line, "t=%d ms: picked the robot at distance %.2f: jump", time_, ri.getDistance());
    } else if (id >= kFirstCrateID && id < kFirstCrateID + 3) {
        const int i = id - kFirstCrateID;
        if (collected_[i]) {
            std::snprintf(line, sizeof line, "t=%d ms: crate %d was already collected", time_, id);
        } else {
            collected_[i] = true;
            ++score_;
            scene_.crateMaterials[i]->setColor(Material::EMISSIVE, 0x605000);
            std::snprintf(line, sizeof line, "t=%d ms: picked crate %d at distance %.2f: score %d", time_, id,
                          ri.getDistance(), score_);
        }
    } else {
        std::snprintf(line, sizeof line, "t=%d ms: picked %s #%d (not a target)", time_, hit->getClassName(), id);
    }
    log_(line);
}

}  // namespace m3ggame
