import java.awt.image.BufferedImage;
import javax.microedition.m3g.Background;
import javax.microedition.m3g.Graphics3D;
import javax.microedition.m3g.Image2D;
import javax.microedition.m3g.Loader;
import javax.microedition.m3g.Object3D;
import javax.microedition.m3g.World;

/**
 * What the JNI layer costs (docs/java.md, "Performance"): a simple setter,
 * and a whole frame of a file (animate + render(World) at 320x240) into an
 * Image2D and into a BufferedImage, to set beside `m3g bench render FILE
 * --size 320x240` of the C++ tool. A benchmark, run by hand:
 *
 *   java -Dm3g.jni.library=build/bindings/java/libm3g_jni.so \
 *        -cp build/bindings/java/m3g-vk.jar:build/bindings/java/m3g-vk-bench.jar JniBench FILE.m3g [frames]
 */
public final class JniBench {
    private static double nsPer(long start, long count) {
        return (System.nanoTime() - start) / (double) count;
    }

    public static void main(String[] args) throws Exception {
        if (args.length < 1) {
            System.err.println("usage: JniBench FILE.m3g [frames]");
            System.exit(2);
        }
        int frames = args.length > 1 ? Integer.parseInt(args[1]) : 300;

        Background b = new Background();
        final int calls = 5_000_000;
        for (int round = 0; round < 3; ++round) {
            long t0 = System.nanoTime();
            for (int i = 0; i < calls; ++i) b.setColor(i);
            System.out.printf("Background.setColor: %.1f ns a call%n", nsPer(t0, calls));
        }

        World world = null;
        for (Object3D o : Loader.load(args[0]))
            if (o instanceof World) world = (World) o;
        if (world == null) throw new IllegalStateException("no World in " + args[0]);
        Graphics3D g = Graphics3D.getInstance();
        Object[] targets = {new Image2D(Image2D.RGBA, 320, 240), new BufferedImage(320, 240, BufferedImage.TYPE_INT_ARGB)};
        // As `m3g bench render FILE --size 320x240` measures: the same frame
        // again (animated once), then with animate() each frame.
        world.animate(0);
        for (boolean animated : new boolean[] {false, true})
            for (Object target : targets) {
                for (int round = 0; round < 3; ++round) {
                    long t0 = System.nanoTime();
                    for (int f = 0; f < frames; ++f) {
                        if (animated) world.animate(f * 33);
                        g.bindTarget(target);
                        g.render(world);
                        g.releaseTarget();
                    }
                    System.out.printf("%s: %.3f ms a frame (%srender(World) at 320x240, %d frames)%n",
                        target.getClass().getSimpleName(), nsPer(t0, frames) / 1e6, animated ? "animate + " : "",
                        frames);
                }
            }
    }
}
