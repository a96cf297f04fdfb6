import java.awt.image.BufferedImage;
import java.io.File;
import javax.imageio.ImageIO;
import javax.microedition.m3g.Graphics3D;
import javax.microedition.m3g.Loader;
import javax.microedition.m3g.Node;
import javax.microedition.m3g.Object3D;
import javax.microedition.m3g.RayIntersection;
import javax.microedition.m3g.World;
import org.m3gvk.TargetAdapter;
import org.m3gvk.TargetAdapters;

/**
 * A MIDlet-style game loop on m3g-vk's javax.microedition.m3g (docs/java.md):
 * load a scene, then each frame animate it, pick what is under the centre of
 * the screen and draw into the "screen" of an emulator, here a
 * {@link Screen} whose pixels a {@link TargetAdapter} hands to Graphics3D as
 * an emulator hands its lcdui Graphics. The last frame is written as a PNG.
 *
 *   java -cp m3g-vk.jar:. SampleGame scene.m3g out.png [frames]
 */
public final class SampleGame {
    /** An emulator's screen: ARGB pixels, a translation and a clip. */
    static final class Screen {
        final int width, height;
        final int[] pixels;
        int translateX, translateY;

        Screen(int width, int height) {
            this.width = width;
            this.height = height;
            pixels = new int[width * height];
        }
    }

    /** How Graphics3D reads and writes a Screen: about 30 lines for a real emulator's Graphics. */
    static final class ScreenAdapter implements TargetAdapter {
        @Override
        public int getWidth(Object target) {
            return ((Screen) target).width;
        }

        @Override
        public int getHeight(Object target) {
            return ((Screen) target).height;
        }

        @Override
        public int getTranslateX(Object target) {
            return ((Screen) target).translateX;
        }

        @Override
        public int getTranslateY(Object target) {
            return ((Screen) target).translateY;
        }

        @Override
        public void readPixels(Object target, int[] argb) {
            System.arraycopy(((Screen) target).pixels, 0, argb, 0, argb.length);
        }

        @Override
        public void writePixels(Object target, int[] argb) {
            System.arraycopy(argb, 0, ((Screen) target).pixels, 0, argb.length);
        }
    }

    public static void main(String[] args) throws Exception {
        if (args.length < 2) {
            System.err.println("usage: java SampleGame scene.m3g out.png [frames]");
            System.exit(2);
        }
        int frames = args.length > 2 ? Integer.parseInt(args[2]) : 11;
        TargetAdapters.register(Screen.class, new ScreenAdapter());
        World world = null;
        for (Object3D o : Loader.load(args[0]))
            if (o instanceof World) world = (World) o;
        if (world == null) throw new IllegalStateException("no World in " + args[0]);

        Screen screen = new Screen(320, 240);
        Graphics3D g3d = Graphics3D.getInstance();
        RayIntersection ray = new RayIntersection();
        int time = 0;
        for (int frame = 0; frame < frames; ++frame, time += 50) {
            world.animate(time);
            Node under = world.pick(-1, 0.5f, 0.5f, world.getActiveCamera(), ray) ? ray.getIntersected() : null;
            g3d.bindTarget(screen);
            try {
                g3d.render(world);
            } finally {
                g3d.releaseTarget();
            }
            if (frame % 5 == 0)
                System.out.printf("frame %d, t = %d ms: %s under the centre%n", frame, time,
                    under == null ? "nothing" : under.getClass().getSimpleName() + " (user ID " + under.getUserID() + ")");
        }
        BufferedImage png = new BufferedImage(screen.width, screen.height, BufferedImage.TYPE_INT_ARGB);
        png.setRGB(0, 0, screen.width, screen.height, screen.pixels, 0, screen.width);
        ImageIO.write(png, "png", new File(args[1]));
        System.out.println("wrote " + args[1] + " (t = " + (time - 50) + " ms)");
    }
}
