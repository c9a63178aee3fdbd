package gizmoball.bench;

import java.io.File;
import java.lang.reflect.Constructor;
import java.lang.reflect.Method;
import java.lang.reflect.RecordComponent;
import java.net.MalformedURLException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.EnumMap;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Optional;

/**
 * Runs a static method of the benchmark with a copy of the game's classes of its own, loaded afresh from the class
 * path, as a JVM that plays one board has them. The just-in-time compiler keeps its profile of a method per class, so
 * a board measured after others runs code compiled for what the others asked of it: 200 balls in play cost 180-195 us
 * a tick measured after the other boards of the steady state, and 222-236 us in two runs of eight that had the aim
 * preview's boards before them, the same code. The JDK's classes stay shared.
 *
 * <p>Arguments and results cross between the two copies as values: records, enums, maps and optionals are made again
 * of the other copy's classes; strings, paths, boxed primitives and arrays of primitives are the JDK's.
 */
final class Isolated {
    private Isolated() {
    }

    /**
     * {@code type.method(args)} in a fresh copy of the classes; its result made of this copy's classes. The copies of
     * earlier calls are collected first, so that the collector does not unload their classes while this one is timed.
     */
    static Object call(Class<?> type, String method, Object... args) {
        System.gc();
        URL[] path = Arrays.stream(System.getProperty("java.class.path").split(File.pathSeparator))
                .map(Isolated::url).toArray(URL[]::new);
        try (URLClassLoader own = new URLClassLoader(path, ClassLoader.getPlatformClassLoader())) {
            Class<?> theirs = own.loadClass(type.getName());
            Method target = Arrays.stream(theirs.getDeclaredMethods())
                    .filter(m -> m.getName().equals(method) && m.getParameterCount() == args.length).findFirst()
                    .orElseThrow(() -> new IllegalArgumentException("no method " + method + " in " + type));
            target.setAccessible(true);
            Object[] moved = new Object[args.length];
            for (int i = 0; i < args.length; i++) {
                moved[i] = transplant(args[i], own);
            }
            return transplant(target.invoke(null, moved), Isolated.class.getClassLoader());
        } catch (ReflectiveOperationException | java.io.IOException e) {
            throw new IllegalStateException("isolated call of " + type.getSimpleName() + "." + method + " failed", e);
        }
    }

    private static URL url(String entry) {
        try {
            return Path.of(entry).toUri().toURL();
        } catch (MalformedURLException e) {
            throw new IllegalArgumentException("class path entry " + entry, e);
        }
    }

    /** The value made of the classes {@code loader} loads (the JDK's own kept as they are). */
    @SuppressWarnings({"unchecked", "rawtypes"})
    private static Object transplant(Object value, ClassLoader loader) throws ReflectiveOperationException {
        boolean primitives = value != null && value.getClass().isArray()
                && value.getClass().getComponentType().isPrimitive();
        if (value == null || value instanceof String || value instanceof Number || value instanceof Boolean
                || value instanceof Path || primitives) {
            return value;   // the JDK's own; arrays of primitives are handed over, not shared after
        }
        if (value instanceof Optional<?> optional) {
            return optional.isPresent() ? Optional.of(transplant(optional.get(), loader)) : Optional.empty();
        }
        if (value instanceof Enum<?> constant) {
            return Enum.valueOf((Class) Class.forName(constant.getDeclaringClass().getName(), true, loader),
                    constant.name());
        }
        if (value instanceof Map<?, ?> map) {
            Map copy = new LinkedHashMap<>();
            for (Map.Entry<?, ?> entry : map.entrySet()) {
                copy.put(transplant(entry.getKey(), loader), transplant(entry.getValue(), loader));
            }
            return map instanceof EnumMap<?, ?> && !copy.isEmpty() ? new EnumMap(copy) : copy;
        }
        if (value instanceof Record) {
            Class<?> type = Class.forName(value.getClass().getName(), true, loader);
            RecordComponent[] components = value.getClass().getRecordComponents();
            Object[] values = new Object[components.length];
            Class<?>[] types = new Class<?>[components.length];
            RecordComponent[] theirs = type.getRecordComponents();
            for (int i = 0; i < components.length; i++) {
                Method accessor = components[i].getAccessor();
                accessor.setAccessible(true);
                values[i] = transplant(accessor.invoke(value), loader);
                types[i] = theirs[i].getType();
            }
            Constructor<?> canonical = type.getDeclaredConstructor(types);
            canonical.setAccessible(true);
            return canonical.newInstance(values);
        }
        throw new IllegalArgumentException("cannot hand over a " + value.getClass().getName());
    }
}
