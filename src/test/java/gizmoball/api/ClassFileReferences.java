package gizmoball.api;

import java.io.DataInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * What one class file refers to, read from its constant pool (JVMS 4.4): every class it names, every field and
 * method it uses (owner, name, descriptor), and every class that appears inside a descriptor or signature.
 * All symbolic references of a class file live in its constant pool, so nothing else needs reading.
 */
final class ClassFileReferences {
    private static final int MAGIC = 0xCAFEBABE;
    private static final Pattern CLASS_IN_DESCRIPTOR = Pattern.compile("L([\\w$/]+)[;<]");

    /** A field or method reference: {@code Fieldref}, {@code Methodref} or {@code InterfaceMethodref}. */
    record MemberRef(String owner, String name, String descriptor) {
        @Override
        public String toString() {
            return owner + "." + name + descriptor;
        }
    }

    final List<String> classes = new ArrayList<>();
    final List<MemberRef> members = new ArrayList<>();

    private ClassFileReferences() {
    }

    static ClassFileReferences read(InputStream classFile) throws IOException {
        DataInputStream in = new DataInputStream(classFile);
        if (in.readInt() != MAGIC) {
            throw new IOException("not a class file");
        }
        in.readUnsignedShort();
        in.readUnsignedShort();
        int count = in.readUnsignedShort();
        String[] utf8 = new String[count];
        int[] classNameIndex = new int[count];
        int[][] memberIndices = new int[count][];
        int[][] nameAndType = new int[count][];
        for (int i = 1; i < count; i++) {
            int tag = in.readUnsignedByte();
            switch (tag) {
                case 1 -> utf8[i] = in.readUTF();
                case 7 -> classNameIndex[i] = in.readUnsignedShort();
                case 9, 10, 11 -> memberIndices[i] = new int[] {in.readUnsignedShort(), in.readUnsignedShort()};
                case 12 -> nameAndType[i] = new int[] {in.readUnsignedShort(), in.readUnsignedShort()};
                case 3, 4 -> in.readInt();
                case 5, 6 -> {
                    in.readLong();
                    i++; // eight-byte constants take two entries
                }
                case 8, 16, 19, 20 -> in.readUnsignedShort();
                case 15 -> {
                    in.readUnsignedByte();
                    in.readUnsignedShort();
                }
                case 17, 18 -> in.readInt();
                default -> throw new IOException("unknown constant pool tag " + tag + " at entry " + i);
            }
        }
        ClassFileReferences refs = new ClassFileReferences();
        for (int i = 1; i < count; i++) {
            if (classNameIndex[i] != 0) {
                refs.addClass(utf8[classNameIndex[i]]);
            }
            if (memberIndices[i] != null) {
                int[] nat = nameAndType[memberIndices[i][1]];
                refs.members.add(new MemberRef(utf8[classNameIndex[memberIndices[i][0]]], utf8[nat[0]], utf8[nat[1]]));
            }
            if (utf8[i] != null) {
                Matcher inDescriptor = CLASS_IN_DESCRIPTOR.matcher(utf8[i]);
                while (inDescriptor.find()) {
                    refs.classes.add(inDescriptor.group(1));
                }
            }
        }
        return refs;
    }

    /** A Class entry names a class by its internal name, or an array type by its descriptor. */
    private void addClass(String name) {
        if (name.startsWith("[")) {
            Matcher element = CLASS_IN_DESCRIPTOR.matcher(name);
            if (element.find()) {
                classes.add(element.group(1));
            }
        } else {
            classes.add(name);
        }
    }
}
