// The two J2ME classes a M3G game is built on, reduced to what the ported
// example needs: MIDlet's life cycle (startApp / pauseApp / destroyApp) and
// lcdui Canvas's paint(Graphics) and keyPressed with game actions. A port
// keeps its Java class layout by deriving from these; the host (a window, or
// the headless frame dump of main.cpp) plays the part of the handset's
// application manager and event thread. Not part of the library.
#pragma once

#include <m3g/Graphics.h>

namespace m3ggame {

/// javax.microedition.lcdui.Canvas game actions (values of MIDP 2.0).
enum GameAction : int { UP = 1, LEFT = 2, RIGHT = 5, DOWN = 6, FIRE = 8 };

class GameCanvas {
public:
    virtual ~GameCanvas() = default;

    /// MIDlet.startApp(): build the World, start the clock.
    virtual void startApp() = 0;
    /// MIDlet.pauseApp(): the host stops calling tick/paint until startApp.
    virtual void pauseApp() {}
    /// MIDlet.destroyApp(unconditional).
    virtual void destroyApp(bool /*unconditional*/) {}

    /// The game thread's step: advance the game to `timeMs` (the MIDlet's
    /// System.currentTimeMillis() - start, fixed steps when headless).
    virtual void tick(int timeMs) = 0;
    /// Canvas.paint(Graphics): draw the current frame into `g`.
    virtual void paint(m3g::Graphics& g) = 0;
    /// Canvas.keyPressed(keyCode) after getGameAction(keyCode).
    virtual void keyPressed(int gameAction) = 0;
};

}  // namespace m3ggame
