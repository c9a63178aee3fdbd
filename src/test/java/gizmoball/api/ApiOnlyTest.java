package gizmoball.api;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.io.InputStream;
import java.lang.reflect.Constructor;
import java.lang.reflect.Field;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.net.URISyntaxException;
import java.nio.file.FileSystem;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;

import gizmoball.Main;

/**
 * The game uses package {@code physics} only through the members that {@code docs/physics-api.txt} lists, so
 * that it builds unchanged against the MIT physics package. (That file is the repository's copy of the product's
 * {@code ../shared/physics-api.txt}; a test keeps the two equal where the original is there.) Reads the constant
 * pool of every compiled class of {@code src/main/java}, which holds all its symbolic references.
 * <p>
 * javac copies the value of a primitive or String constant into the class that uses it, leaving no reference
 * behind; the test of physics-lib's public surface below keeps such extras out of the game's reach.
 */
class ApiOnlyTest {
    private static final Path API_LIST = Path.of("docs", "physics-api.txt");
    private static final Path ORIGINAL_API_LIST = Path.of(System.getProperty("user.dir")).toAbsolutePath()
            .resolveSibling("shared").resolve("physics-api.txt");
    private static final String PHYSICS = "physics/";
    /** Members every class inherits: calling them on a physics type needs nothing beyond the type. */
    private static final Set<String> OBJECT_MEMBERS = Arrays.stream(Object.class.getMethods())
            .map(ApiOnlyTest::nameAndDescriptor).collect(Collectors.toSet());

    @Test
    void theGameReferencesOnlyTheListedMembersOfPackagePhysics() throws IOException, URISyntaxException {
        PhysicsApi api = PhysicsApi.read(API_LIST);
        assertThat(api.classes()).as("classes in %s", API_LIST).hasSize(9);

        List<String> violations = new ArrayList<>();
        Set<String> physicsClassesUsed = new TreeSet<>();
        List<String> classFiles = new ArrayList<>();
        forEachGameClassFile((name, refs) -> {
            classFiles.add(name);
            violations.addAll(violations(api, name, refs));
            refs.classes.stream().filter(c -> c.startsWith(PHYSICS)).forEach(physicsClassesUsed::add);
        });

        // Not vacuous: the game's classes were found, and they do use the physics package.
        assertThat(classFiles).contains("gizmoball/Main.class", "gizmoball/model/loop/CollisionDetector.class");
        assertThat(physicsClassesUsed).contains("physics/Geometry", "physics/GeometryImpl", "physics/Vect");
        assertThat(violations).as("references into package physics that the API does not list").isEmpty();
    }

    @Test
    void theRepositorysCopyOfTheApiListIsTheOriginal() throws IOException {
        assumeTrue(Files.isRegularFile(ORIGINAL_API_LIST), () -> "no original API list at " + ORIGINAL_API_LIST);
        assertThat(Files.readString(API_LIST)).isEqualTo(Files.readString(ORIGINAL_API_LIST));
    }

    /** The check can fail: physics-lib's GeometryImpl delegates to a helper class that is not in the API. */
    @Test
    void theCheckReportsAReferenceOutsideTheApi() throws IOException {
        PhysicsApi api = PhysicsApi.read(API_LIST);
        try (InputStream in = physics.GeometryImpl.class.getResourceAsStream("GeometryImpl.class")) {
            assertThat(in).as("physics/GeometryImpl.class on the test classpath").isNotNull();
            List<String> found = violations(api, "physics/GeometryImpl.class", ClassFileReferences.read(in));
            assertThat(found).isNotEmpty().allMatch(v -> v.startsWith("physics/GeometryImpl.class: "));
        }
    }

    /**
     * javac copies primitive and String constants into the classes that use them, so the constant pools cannot
     * show a use of one; physics-lib therefore makes public exactly the API, and the game cannot even compile
     * against an extra. Also the other way round: physics-lib provides every listed member.
     */
    @Test
    void physicsLibMakesPublicExactlyTheListedApi() throws IOException, URISyntaxException, ClassNotFoundException {
        PhysicsApi api = PhysicsApi.read(API_LIST);
        Set<String> publicClasses = new TreeSet<>();
        forEachClassFile(Path.of(physics.Vect.class.getProtectionDomain().getCodeSource().getLocation().toURI()),
                (name, refs) -> publicClasses.add(name.replaceFirst("\\.class$", "")));
        publicClasses.removeIf(name -> !isPublic(name));
        assertThat(publicClasses).as("public classes of physics-lib").isEqualTo(new TreeSet<>(api.classes()));

        Set<String> publicMembers = new TreeSet<>();
        for (String name : publicClasses) {
            Class<?> type = Class.forName(name.replace('/', '.'));
            for (Field field : type.getDeclaredFields()) {
                if (Modifier.isPublic(field.getModifiers())) {
                    publicMembers.add(name + "." + field.getName() + field.getType().descriptorString());
                }
            }
            for (Constructor<?> constructor : type.getDeclaredConstructors()) {
                if (Modifier.isPublic(constructor.getModifiers())) {
                    publicMembers.add(name + ".<init>" + parameters(constructor.getParameterTypes()) + "V");
                }
            }
            for (Method method : type.getDeclaredMethods()) {
                if (Modifier.isPublic(method.getModifiers())) {
                    publicMembers.add(name + "." + nameAndDescriptor(method));
                }
            }
        }
        assertThat(publicMembers).as("public members of physics-lib").isEqualTo(new TreeSet<>(api.members()));
    }

    @Test
    void theApiListIsReadInClassFileTerms() throws IOException {
        PhysicsApi api = PhysicsApi.read(API_LIST);
        assertThat(api.hasClass("physics/Geometry$VectPair")).isTrue();
        assertThat(api.hasMember("physics/Vect", "<init>", "(DD)V")).isTrue();
        assertThat(api.hasMember("physics/Vect", "ZERO", "Lphysics/Vect;")).isTrue();
        assertThat(api.hasMember("physics/Vect", "toPoint2D", "()Ljava/awt/geom/Point2D$Double;")).isTrue();
        assertThat(api.hasMember("physics/GeometryImpl", "<init>", "(DI)V")).isTrue();
        assertThat(api.hasMember("physics/Geometry", "timeUntilRotatingWallCollision",
                "(Lphysics/LineSegment;Lphysics/Vect;DLphysics/Circle;Lphysics/Vect;)D")).isTrue();
        assertThat(api.hasMember("physics/Vect", "plus", "(Lphysics/Vect;)Lphysics/Angle;")).isFalse();
        assertThat(api.hasMember("physics/GeometryImpl", "DEFAULT_SEARCH_SLICES", "I")).isFalse();
    }

    private static List<String> violations(PhysicsApi api, String classFile, ClassFileReferences refs) {
        List<String> found = new ArrayList<>();
        refs.classes.stream().filter(c -> c.startsWith(PHYSICS) && !api.hasClass(c)).distinct()
                .forEach(c -> found.add(classFile + ": class " + c));
        refs.members.stream()
                .filter(m -> m.owner().startsWith(PHYSICS) && !api.hasMember(m.owner(), m.name(), m.descriptor())
                        && !OBJECT_MEMBERS.contains(m.name() + m.descriptor()))
                .forEach(m -> found.add(classFile + ": " + m));
        return found;
    }

    interface ClassFileVisitor {
        void visit(String name, ClassFileReferences refs) throws IOException;
    }

    /**
     * Every class file of the game's main output: the directory or jar that the class loader took gizmoball.Main
     * from, which is src/main/java's output under every Gradle version. {@link PackageArrowsTest} reads them too.
     */
    static void forEachGameClassFile(ClassFileVisitor visitor) throws IOException, URISyntaxException {
        forEachClassFile(Path.of(Main.class.getProtectionDomain().getCodeSource().getLocation().toURI()), visitor);
    }

    /** Every class file in a class path entry, a directory or a jar. */
    static void forEachClassFile(Path location, ClassFileVisitor visitor) throws IOException {
        if (Files.isDirectory(location)) {
            visitClassFiles(location, visitor);
        } else {
            try (FileSystem jar = FileSystems.newFileSystem(location)) {
                visitClassFiles(jar.getPath("/"), visitor);
            }
        }
    }

    private static void visitClassFiles(Path root, ClassFileVisitor visitor) throws IOException {
        List<Path> files;
        try (Stream<Path> walk = Files.walk(root)) {
            files = walk.filter(p -> p.toString().endsWith(".class")).sorted().toList();
        }
        for (Path file : files) {
            try (InputStream in = Files.newInputStream(file)) {
                String name = root.relativize(file).toString().replace(root.getFileSystem().getSeparator(), "/");
                visitor.visit(name, ClassFileReferences.read(in));
            }
        }
    }

    private static boolean isPublic(String internalName) {
        try {
            return Modifier.isPublic(Class.forName(internalName.replace('/', '.')).getModifiers());
        } catch (ClassNotFoundException e) {
            throw new IllegalStateException(internalName + " is in physics-lib but cannot be loaded", e);
        }
    }

    private static String nameAndDescriptor(Method method) {
        return method.getName() + parameters(method.getParameterTypes()) + method.getReturnType().descriptorString();
    }

    private static String parameters(Class<?>[] types) {
        return Arrays.stream(types).map(Class::descriptorString).collect(Collectors.joining("", "(", ")"));
    }
}
