package gizmoball.view.editor;

import java.awt.Color;

/** The editor's colours in one place, so palette icons, previews and highlights agree. */
final class EditorColors {
    static final Color BALL = new Color(0xD8, 0xD8, 0xE0);
    static final Color ICON_BACKGROUND = new Color(0x2B, 0x2F, 0x3A);
    static final Color ICON_INK = new Color(0xEE, 0xEE, 0xF2);

    static final Color FITS = new Color(0x35, 0xD0, 0x5A);
    static final Color REFUSED = new Color(0xF0, 0x3E, 0x3E);
    static final Color TARGET = new Color(255, 255, 255, 150);
    static final Color SELECTION = new Color(0xFF, 0xE0, 0x3A);
    static final Color CONNECTION = new Color(0x44, 0xD6, 0xF2);
    static final Color INCOMING = new Color(0xFF, 0x8C, 0x42);
    static final Color KEY_LABEL = new Color(0xFF, 0xFF, 0xFF);

    private EditorColors() {
    }

    static Color translucent(Color c, int alpha) {
        return new Color(c.getRed(), c.getGreen(), c.getBlue(), alpha);
    }
}
