package gizmoball.boardfile;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.Writer;
import java.nio.channels.Channels;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFileAttributeView;
import java.security.SecureRandom;
import java.util.HexFormat;

/**
 * Replaces a file all at once: the content goes to a temporary file in the target's own directory (so the
 * rename stays on one file system) and is then renamed over the target. If anything fails the target is left
 * exactly as it was and the temporary file is removed.
 *
 * <p>The result has the permissions the player expects: a file saved over keeps its permission bits, and a
 * new file gets what any program creating it would get under the user's umask. (Files.createTempFile would
 * make every saved file owner-only: it creates with mode 0600.)
 */
public final class AtomicFileWriter {
    private static final SecureRandom RANDOM = new SecureRandom();
    private static final int NAME_ATTEMPTS = 100;

    /** Writes the content; may fail part-way, which is what the temporary file guards against. */
    @FunctionalInterface
    public interface Content {
        void writeTo(Writer out) throws IOException;
    }

    private AtomicFileWriter() {
    }

    public static void write(Path target, Content content) throws IOException {
        Path absolute = target.toAbsolutePath();
        Path temporary = createTemporary(absolute);
        try {
            try (FileChannel channel = FileChannel.open(temporary, StandardOpenOption.WRITE);
                 Writer out = new BufferedWriter(Channels.newWriter(channel, StandardCharsets.UTF_8))) {
                content.writeTo(out);
                out.flush();
                // On disk before the rename, so a crash cannot leave the target renamed to an empty file.
                channel.force(true);
            }
            keepPermissionsOf(absolute, temporary);
            Files.move(temporary, absolute, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
        } catch (IOException | RuntimeException e) {
            try {
                Files.deleteIfExists(temporary);
            } catch (IOException cleanup) {
                e.addSuppressed(cleanup);
            }
            throw e;
        }
    }

    /**
     * A new, empty, hidden file beside {@code target}, created like any ordinary file (default mode, less the
     * umask) rather than owner-only.
     */
    private static Path createTemporary(Path target) throws IOException {
        Path directory = target.getParent();
        for (int attempt = 1; ; attempt++) {
            Path temporary = directory.resolve("." + target.getFileName() + "." + randomSuffix() + ".tmp");
            try {
                Files.newByteChannel(temporary, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE).close();
                return temporary;
            } catch (FileAlreadyExistsException taken) {
                if (attempt == NAME_ATTEMPTS) {
                    throw taken;
                }
            }
        }
    }

    private static String randomSuffix() {
        byte[] bytes = new byte[6];
        RANDOM.nextBytes(bytes);
        return HexFormat.of().formatHex(bytes);
    }

    /** A file saved over keeps its permission bits (where the file system has them). */
    private static void keepPermissionsOf(Path target, Path temporary) throws IOException {
        PosixFileAttributeView old = Files.getFileAttributeView(target, PosixFileAttributeView.class);
        if (old != null && Files.exists(target)) {
            Files.setPosixFilePermissions(temporary, old.readAttributes().permissions());
        }
    }
}
