package javax.microedition.m3g;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;
import static org.junit.Assume.assumeTrue;

import java.awt.image.BufferedImage;
import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import javax.imageio.ImageIO;
import org.junit.Test;
import org.m3gvk.testing.Json;
import org.m3gvk.testing.SceneSetup;

/**
 * The shared corpus through the Java API, against Nokia's renders (scenes
 * set up as docs/scene-setup.md describes): each file loaded with Loader.load,
 * animated to each reference time and rendered into a 320x240 BufferedImage,
 * compared as the C++ agreement test compares (tests/vk/test_CorpusAgreement.cpp:
 * at most 1% of pixels off by more than 8 in a channel, PSNR at least 35 dB,
 * at least 60 of the 62 images). Skips where the corpus is absent.
 */
public class CorpusAgreementTest {
    private static final double AGREE_SHARE = 0.01, AGREE_PSNR = 35.0;
    private static final int AGREE_FLOOR = 60;

    private static File corpus() {
        File dir = new File(System.getProperty("m3g.corpus", "../shared/corpus"));
        assumeTrue("no shared corpus at " + dir + " (skipped)", new File(dir, "manifest.json").isFile());
        return dir;
    }

    /** Share of pixels whose largest RGB difference exceeds 8, and PSNR over RGB. */
    static double[] compare(BufferedImage a, BufferedImage b) {
        assertEquals(a.getWidth(), b.getWidth());
        assertEquals(a.getHeight(), b.getHeight());
        long differing = 0, total = (long) a.getWidth() * a.getHeight();
        double squared = 0;
        for (int y = 0; y < a.getHeight(); ++y)
            for (int x = 0; x < a.getWidth(); ++x) {
                int p = a.getRGB(x, y), q = b.getRGB(x, y), largest = 0;
                for (int shift = 0; shift <= 16; shift += 8) {
                    int d = Math.abs(((p >> shift) & 255) - ((q >> shift) & 255));
                    largest = Math.max(largest, d);
                    squared += (double) d * d;
                }
                if (largest > 8) ++differing;
            }
        double mse = squared / (3.0 * total);
        return new double[] {(double) differing / total, mse == 0 ? Double.POSITIVE_INFINITY : 10 * Math.log10(255.0 * 255.0 / mse)};
    }

    @Test
    @SuppressWarnings("unchecked")
    public void corpusAgreesWithNokiasRenders() throws Exception {
        File corpus = corpus();
        List<Object> manifest = (List<Object>) Json.parse(
            new String(Files.readAllBytes(new File(corpus, "manifest.json").toPath()), StandardCharsets.UTF_8));
        int agree = 0, total = 0;
        List<String> errors = new ArrayList<>();
        Graphics3D g = Graphics3D.getInstance();
        for (Object e : manifest) {
            Map<String, Object> entry = (Map<String, Object>) e;
            String file = (String) entry.get("file");
            int w = entry.get("width") == null ? 320 : ((Double) entry.get("width")).intValue();
            int h = entry.get("height") == null ? 240 : ((Double) entry.get("height")).intValue();
            for (Object i : (List<Object>) entry.get("images")) {
                Map<String, Object> image = (Map<String, Object>) i;
                int time = ((Double) image.get("time")).intValue();
                ++total;
                try {
                    Object3D[] roots = Loader.load(new File(new File(corpus, "models"), file).getPath());
                    World world = SceneSetup.prepare(roots, w, h);
                    world.animate(time);
                    BufferedImage actual = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
                    g.bindTarget(actual, true, 0);
                    try {
                        g.render(world);
                    } finally {
                        g.releaseTarget();
                    }
                    BufferedImage expected = ImageIO.read(new File(new File(corpus, "nokia"), (String) image.get("png")));
                    double[] c = compare(actual, expected);
                    boolean ok = c[0] <= AGREE_SHARE && c[1] >= AGREE_PSNR;
                    if (ok) ++agree;
                    System.out.printf("%-78s %6d %8.3f%% %7.2f%s%n", tail(file), time, 100 * c[0], c[1], ok ? "" : "  *");
                } catch (Exception | Error x) {
                    errors.add(file + " t=" + time + ": " + x);
                    System.out.printf("%-78s %6d  ERROR: %s%n", tail(file), time, x);
                }
            }
        }
        System.out.printf("agreement through Java: %d of %d images; %d errors%n", agree, total, errors.size());
        assertTrue("errors: " + errors, errors.isEmpty());
        assertTrue(agree + " of " + total + " images agree, fewer than " + AGREE_FLOOR, agree >= AGREE_FLOOR);
    }

    private static String tail(String s) {
        return s.length() > 78 ? "..." + s.substring(s.length() - 75) : s;
    }

    /** World.pick through Java: the teapot (user ID 111) at the centre of its view, as `m3g pick` finds it. */
    @Test
    public void pickThroughWorld() throws Exception {
        File teapot = new File(corpus(), "models/jacques-gasselin__m3x/tools/test/data/teapot.m3g");
        assumeTrue(teapot.isFile());
        Object3D[] roots = Loader.load(teapot.getPath());
        World world = SceneSetup.prepare(roots, 320, 240);
        world.animate(0);
        RayIntersection ri = new RayIntersection();
        assertTrue("a hit at the centre", world.pick(-1, 0.5f, 0.5f, world.getActiveCamera(), ri));
        Node hit = ri.getIntersected();
        assertNotNull(hit);
        assertEquals(111, hit.getUserID());
        assertSame("the same peer as find() gives", hit, world.find(111));
        assertTrue(ri.getDistance() > 0f);
    }
}
