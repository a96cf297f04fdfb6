package javax.microedition.m3g;

import static org.junit.Assert.assertEquals;

import org.junit.Test;

/** JSR-184 1.1 AnimationController: defaults, the time mapping, the exceptions. */
public class AnimationControllerTest {
    @Test
    public void defaults() {
        AnimationController c = new AnimationController();
        assertEquals(0, c.getActiveIntervalStart());
        assertEquals(0, c.getActiveIntervalEnd());
        assertEquals(1.0f, c.getSpeed(), 0);
        assertEquals(1.0f, c.getWeight(), 0);
        assertEquals(0, c.getRefWorldTime());
        assertEquals(250f, c.getPosition(250), 0);
    }

    @Test
    public void settersRoundTrip() {
        AnimationController c = new AnimationController();
        c.setActiveInterval(-10, 20);
        assertEquals(-10, c.getActiveIntervalStart());
        assertEquals(20, c.getActiveIntervalEnd());
        c.setActiveInterval(5, 5);
        c.setWeight(0);
        assertEquals(0f, c.getWeight(), 0);
        c.setWeight(2.5f);
        assertEquals(2.5f, c.getWeight(), 0);
    }

    @Test
    public void positionAndSpeed() {
        AnimationController c = new AnimationController();
        c.setPosition(10, 100);
        assertEquals(100, c.getRefWorldTime());
        assertEquals(10f, c.getPosition(100), 1e-4f);
        assertEquals(110f, c.getPosition(200), 1e-4f);
        c.setSpeed(2, 200);  // continuous at 200
        assertEquals(2f, c.getSpeed(), 0);
        assertEquals(200, c.getRefWorldTime());
        assertEquals(110f, c.getPosition(200), 1e-4f);
        assertEquals(310f, c.getPosition(300), 1e-4f);
        c.setSpeed(-1, 300);
        assertEquals(210f, c.getPosition(400), 1e-4f);
    }

    @Test(expected = IllegalArgumentException.class)
    public void intervalStartAfterEnd() {
        new AnimationController().setActiveInterval(5, 4);
    }

    @Test(expected = IllegalArgumentException.class)
    public void negativeWeight() {
        new AnimationController().setWeight(-0.01f);
    }
}
