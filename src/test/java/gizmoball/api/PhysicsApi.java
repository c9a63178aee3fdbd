package gizmoball.api;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The public API of package {@code physics} as listed in {@code physics-api.txt} (javap's notation), turned into
 * class-file terms: internal class names and members as owner, name and JVM descriptor.
 */
final class PhysicsApi {
    private static final Pattern TYPE_HEADER =
            Pattern.compile("public (?:(?:final|abstract) )*(?:class|interface) ([\\w.$]+)\\b.*\\{");
    private static final Pattern MODIFIERS =
            Pattern.compile("^public ((?:static|final|abstract|synchronized|native) )*");
    private static final Map<String, String> PRIMITIVES = Map.of("void", "V", "boolean", "Z", "byte", "B", "char", "C",
            "short", "S", "int", "I", "long", "J", "float", "F", "double", "D");

    private final Set<String> classes = new HashSet<>();
    private final Set<String> members = new HashSet<>();

    private PhysicsApi() {
    }

    /** Reads the list; a line it cannot read is an error, so that a misread list cannot pass everything. */
    static PhysicsApi read(Path list) throws IOException {
        PhysicsApi api = new PhysicsApi();
        String owner = null;
        List<String> lines = Files.readAllLines(list);
        for (int i = 0; i < lines.size(); i++) {
            String line = lines.get(i).trim();
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            Matcher header = TYPE_HEADER.matcher(line);
            if (owner == null && header.matches()) {
                owner = internalName(header.group(1));
                api.classes.add(owner);
            } else if (owner != null && line.equals("}")) {
                owner = null;
            } else if (owner != null && line.startsWith("public ") && line.endsWith(";")) {
                api.members.add(member(owner, MODIFIERS.matcher(line).replaceFirst("").replaceFirst(";$", "")));
            } else {
                throw new IllegalArgumentException(list + " line " + (i + 1) + " is not a type header, member or '}': "
                        + line);
            }
        }
        if (owner != null) {
            throw new IllegalArgumentException(list + " ends inside " + owner);
        }
        return api;
    }

    boolean hasClass(String internalName) {
        return classes.contains(internalName);
    }

    /** A field or method (constructors are {@code <init>}) in class-file terms. */
    boolean hasMember(String owner, String name, String descriptor) {
        return members.contains(owner + "." + name + descriptor);
    }

    /** Internal names of the listed classes. */
    Set<String> classes() {
        return Set.copyOf(classes);
    }

    /** The listed members, each as owner.name followed by its descriptor. */
    Set<String> members() {
        return Set.copyOf(members);
    }

    /** "physics.Vect plus(physics.Vect)", "physics.Vect(double, double)" or "physics.Vect ZERO" in owner. */
    private static String member(String owner, String declaration) {
        int open = declaration.indexOf('(');
        if (open < 0) {
            String[] typeAndName = declaration.split(" ");
            return owner + "." + typeAndName[1] + descriptor(typeAndName[0]);
        }
        String head = declaration.substring(0, open);
        String params = declaration.substring(open + 1, declaration.lastIndexOf(')')).trim();
        StringBuilder descriptor = new StringBuilder("(");
        if (!params.isEmpty()) {
            for (String param : params.split(",")) {
                descriptor.append(descriptor(param.trim()));
            }
        }
        descriptor.append(')');
        int space = head.lastIndexOf(' ');
        if (space < 0) {
            // A constructor: javap writes the class's name where a method has return type and name.
            return owner + ".<init>" + descriptor + "V";
        }
        return owner + "." + head.substring(space + 1) + descriptor + descriptor(head.substring(0, space));
    }

    private static String descriptor(String javaType) {
        if (javaType.endsWith("[]")) {
            return "[" + descriptor(javaType.substring(0, javaType.length() - 2));
        }
        String primitive = PRIMITIVES.get(javaType);
        return primitive != null ? primitive : "L" + internalName(javaType) + ";";
    }

    private static String internalName(String binaryName) {
        return binaryName.replace('.', '/');
    }
}
