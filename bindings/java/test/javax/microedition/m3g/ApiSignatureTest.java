package javax.microedition.m3g;

import static org.junit.Assert.assertTrue;

import java.io.IOException;
import java.lang.reflect.Constructor;
import java.lang.reflect.Field;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Paths;
import java.util.Set;
import java.util.TreeSet;
import org.junit.Test;

/**
 * The jar's public API, read by reflection, against the JSR-184 1.1 table
 * (bindings/java/test/jsr184-signatures.txt): every constructor, constant and
 * method of the 30 classes, and nothing public beyond them, so that Java code
 * written for JSR-184 compiles unchanged.
 */
public class ApiSignatureTest {
    private static String simple(Class<?> t) {
        if (t.isArray()) return simple(t.getComponentType()) + "[]";
        String name = t.getName();
        for (String pkg : new String[] {"java.lang.", "java.util.", "javax.microedition.m3g."})
            if (name.startsWith(pkg) && name.indexOf('.', pkg.length()) < 0) return name.substring(pkg.length());
        return name;
    }

    private static String params(Class<?>[] types) {
        StringBuilder b = new StringBuilder();
        for (Class<?> t : types) b.append(b.length() > 0 ? "," : "").append(simple(t));
        return b.toString();
    }

    static Set<String> expected() throws IOException {
        Set<String> out = new TreeSet<>();
        for (String line : Files.readAllLines(Paths.get(System.getProperty("m3g.api.table")), StandardCharsets.UTF_8))
            if (!line.isEmpty() && !line.startsWith("#")) out.add(line.trim());
        return out;
    }

    static Set<String> actual(Set<String> classNames) throws Exception {
        Set<String> out = new TreeSet<>();
        for (String name : classNames) {
            Class<?> c = Class.forName("javax.microedition.m3g." + name);
            for (Constructor<?> k : c.getDeclaredConstructors())
                if (Modifier.isPublic(k.getModifiers())) out.add(name + ": ctor (" + params(k.getParameterTypes()) + ")");
            for (Field f : c.getDeclaredFields())
                if (Modifier.isPublic(f.getModifiers())) out.add(name + ": field " + f.getName() + " = " + f.get(null));
            for (Method m : c.getDeclaredMethods())
                if (Modifier.isPublic(m.getModifiers()) && !m.isSynthetic() && !m.isBridge())
                    out.add(name + ": method " + simple(m.getReturnType()) + " " + m.getName() + "("
                        + params(m.getParameterTypes()) + ")" + (Modifier.isStatic(m.getModifiers()) ? " static" : ""));
        }
        return out;
    }

    @Test
    public void everyMemberOfTheSpecificationAndNothingElse() throws Exception {
        Set<String> expected = expected();
        Set<String> classes = new TreeSet<>();
        for (String line : expected) classes.add(line.substring(0, line.indexOf(':')));
        Set<String> actual = actual(classes);
        Set<String> missing = new TreeSet<>(expected);
        missing.removeAll(actual);
        Set<String> extra = new TreeSet<>(actual);
        extra.removeAll(expected);
        System.out.println("JSR-184 1.1 API: " + (expected.size() - missing.size()) + " of " + expected.size()
            + " members present in " + classes.size() + " classes; " + extra.size() + " public members beyond it");
        StringBuilder report = new StringBuilder();
        for (String m : missing) report.append("\n  missing: ").append(m);
        for (String e : extra) report.append("\n  extra:   ").append(e);
        assertTrue(report.toString(), missing.isEmpty() && extra.isEmpty());
    }
}
