package gizmoball.view;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.StandardProtocolFamily;
import java.net.UnixDomainSocketAddress;
import java.nio.channels.SocketChannel;
import java.nio.file.Path;
import java.util.Optional;
import org.junit.platform.launcher.LauncherSession;
import org.junit.platform.launcher.LauncherSessionListener;

/**
 * Decides, before any test touches AWT, whether the X display named by {@code DISPLAY} can really be opened.
 * A stale {@code DISPLAY} (the server is gone) makes AWT throw on first use in every test that paints, even
 * into an image; so when nothing answers there, this turns AWT headless: painting tests still run, and the
 * GUI tests skip with {@link #reason()} instead of erroring. Registered through META-INF/services.
 */
public final class DisplayCheck implements LauncherSessionListener {
    private static final int X_TCP_BASE_PORT = 6000;
    private static final int CONNECT_TIMEOUT_MILLIS = 1000;
    private static volatile String reason;

    @Override
    public void launcherSessionOpened(LauncherSession session) {
        String display = System.getenv("DISPLAY");
        if (display == null || display.isBlank() || Boolean.getBoolean("java.awt.headless")) {
            return;
        }
        unreachable(display).ifPresent(why -> {
            reason = "DISPLAY=" + display + " is set but " + why;
            System.setProperty("java.awt.headless", "true");
        });
    }

    /** Why the GUI tests cannot run here although DISPLAY is set; empty if they can (or DISPLAY is unset). */
    static Optional<String> reason() {
        return Optional.ofNullable(reason);
    }

    /** Why no X server answers at {@code display} ({@code [host]:number[.screen]}); empty if one does. */
    static Optional<String> unreachable(String display) {
        int colon = display.lastIndexOf(':');
        if (colon < 0) {
            return Optional.of("is not of the form [host]:number");
        }
        String host = display.substring(0, colon);
        String number = display.substring(colon + 1).replaceFirst("\\..*", "");
        if (!number.matches("\\d+")) {
            return Optional.of("has no display number");
        }
        try {
            if (host.isEmpty() || host.equals("unix")) {
                Path socket = Path.of("/tmp/.X11-unix/X" + number);
                try (SocketChannel channel = SocketChannel.open(StandardProtocolFamily.UNIX)) {
                    channel.connect(UnixDomainSocketAddress.of(socket));
                }
            } else {
                try (Socket tcp = new Socket()) {
                    tcp.connect(new InetSocketAddress(host, X_TCP_BASE_PORT + Integer.parseInt(number)),
                            CONNECT_TIMEOUT_MILLIS);
                }
            }
            return Optional.empty();
        } catch (IOException | RuntimeException e) {
            return Optional.of("no X server answers there (" + e.getMessage() + ")");
        }
    }
}
