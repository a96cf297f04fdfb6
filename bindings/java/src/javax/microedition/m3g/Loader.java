package javax.microedition.m3g;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.net.URI;
import java.net.URISyntaxException;
import java.net.URL;

/**
 * JSR-184 1.1 Loader over m3g::Loader. A name resolves as a MIDlet's does
 * (docs/java.md, "Loading"): a URI with a scheme (file:, http:, jar: ...)
 * through java.net.URL; otherwise a resource of the context class loader
 * (a leading '/' is the root of the class path, as MIDP's getResourceAsStream
 * has it), else a file. Files read where they lie, so their external
 * references resolve against their folder; other sources are read into
 * memory first, where only absolute external references resolve.
 */
public class Loader {
    static {
        Native.ensureLoaded();
    }

    private Loader() {}

    public static Object3D[] load(String name) throws IOException {
        if (name == null) throw new NullPointerException("Loader.load: the name is null");
        File file = fileOf(name);
        if (file != null) return loadFile(file.getPath());
        URL url = urlOf(name);
        if (url == null) throw new IOException("Loader.load: \"" + name + "\" is not a resource, a file or a URL");
        File local = fileOf(url);
        if (local != null) return loadFile(local.getPath());
        try (InputStream in = url.openStream()) {
            return loadBytes(readAll(in), 0);
        }
    }

    public static Object3D[] load(byte[] data, int offset) throws IOException {
        if (data == null) throw new NullPointerException("Loader.load: the data is null");
        return loadBytes(data, offset);
    }

    private static boolean hasScheme(String name) {
        int colon = name.indexOf(':');
        return colon > 1 && name.substring(0, colon).matches("[A-Za-z][A-Za-z0-9+.-]*");
    }

    /** A file: URI or an existing plain path without a resource of that name; else null. */
    private static File fileOf(String name) {
        if (hasScheme(name)) {
            try {
                URI uri = new URI(name);
                return "file".equals(uri.getScheme()) ? new File(uri) : null;
            } catch (URISyntaxException | IllegalArgumentException e) {
                return null;
            }
        }
        if (resource(name) != null) return null;
        File f = new File(name);
        return f.isFile() ? f : null;
    }

    private static URL urlOf(String name) throws IOException {
        if (hasScheme(name)) return new URL(name);
        return resource(name);
    }

    private static URL resource(String name) {
        String path = name.startsWith("/") ? name.substring(1) : name;
        ClassLoader loader = Thread.currentThread().getContextClassLoader();
        if (loader == null) loader = Loader.class.getClassLoader();
        return loader == null ? null : loader.getResource(path);
    }

    private static File fileOf(URL url) {
        if (!"file".equals(url.getProtocol())) return null;
        try {
            return new File(url.toURI());
        } catch (URISyntaxException | IllegalArgumentException e) {
            return null;
        }
    }

    private static byte[] readAll(InputStream in) throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        byte[] buffer = new byte[1 << 16];
        for (int n; (n = in.read(buffer)) > 0;) out.write(buffer, 0, n);
        return out.toByteArray();
    }

    private static native Object3D[] loadFile(String path) throws IOException;

    private static native Object3D[] loadBytes(byte[] data, int offset) throws IOException;
}
