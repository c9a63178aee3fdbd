package gizmoball.view.editor;

import java.awt.Toolkit;
import java.awt.datatransfer.DataFlavor;
import java.awt.datatransfer.StringSelection;
import java.awt.datatransfer.UnsupportedFlavorException;
import java.io.IOException;

/** The system clipboard, as text: what build mode copies is board-file lines, shared with every other program. */
final class Clipboard {
    private Clipboard() {
    }

    static void put(String text) {
        Toolkit.getDefaultToolkit().getSystemClipboard().setContents(new StringSelection(text), null);
    }

    /** The clipboard's text, or nothing (which the editor refuses to paste, saying why). */
    static String text() {
        try {
            return String.valueOf(Toolkit.getDefaultToolkit().getSystemClipboard().getData(DataFlavor.stringFlavor));
        } catch (UnsupportedFlavorException | IOException | IllegalStateException e) {
            return "";
        }
    }
}
