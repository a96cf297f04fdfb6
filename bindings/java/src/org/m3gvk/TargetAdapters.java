package org.m3gvk;

import java.awt.image.BufferedImage;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * The registry of {@link TargetAdapter}s by target class. Graphics3D looks a
 * target up by its class, then by its superclasses and interfaces.
 */
public final class TargetAdapters {
    private static final Map<Class<?>, TargetAdapter> ADAPTERS = new ConcurrentHashMap<>();

    static {
        register(BufferedImage.class, new BufferedImageAdapter());
    }

    private TargetAdapters() {}

    /** Makes Graphics3D.bindTarget accept objects of {@code type} (and its subclasses). */
    public static void register(Class<?> type, TargetAdapter adapter) {
        if (type == null || adapter == null) throw new NullPointerException("TargetAdapters.register: null argument");
        ADAPTERS.put(type, adapter);
    }

    /** Removes the adapter of {@code type}; returns it, or null. */
    public static TargetAdapter unregister(Class<?> type) {
        return ADAPTERS.remove(type);
    }

    /** The adapter for {@code target}'s class or a supertype of it, or null. */
    public static TargetAdapter find(Object target) {
        for (Class<?> c = target.getClass(); c != null; c = c.getSuperclass()) {
            TargetAdapter a = ADAPTERS.get(c);
            if (a != null) return a;
            for (Class<?> i : c.getInterfaces()) {
                a = ADAPTERS.get(i);
                if (a != null) return a;
            }
        }
        return null;
    }
}
